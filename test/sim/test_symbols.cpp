// Demangled names for every report the simulator writes.
#include <catch2/catch.hpp>

#include "symbols.hpp"

TEST_CASE("C++ symbols are demangled, other names kept", "[symbols]") {
  using fwsim::demangle;
  CHECK(demangle("_ZN5minrt6TracerINS_19PortableFloatHwSqrtEE9in_shadowEv") ==
        "minrt::Tracer<minrt::PortableFloatHwSqrt>::in_shadow()");
  CHECK(demangle("_ZN5minrt6TracerINS_19PortableFloatHwSqrtEE23judge_intersection_fastILb1EEEbRKNS_11TracerStateIS1_E6DirVecE") ==
        "bool minrt::Tracer<minrt::PortableFloatHwSqrt>::judge_intersection_fast<true>("
        "minrt::TracerState<minrt::PortableFloatHwSqrt>::DirVec const&)");
  CHECK(demangle("main") == "main");
  CHECK(demangle("_start") == "_start");
  CHECK(demangle("_Z") == "_Z");            // not a valid mangled name: unchanged
  CHECK(demangle("_Zzz_not") == "_Zzz_not");
}

TEST_CASE("symbol table finds the demangled name by address", "[symbols]") {
  fwsim::SymbolTable t;
  t.add({fwsim::demangle("_ZN5minrt4haltEi"), 0x80000100, 0x20});
  t.add({"main", 0x80000000, 0});
  t.finalize();
  CHECK(t.describe(0x80000104) == "minrt::halt(int)+0x4");
  CHECK(t.describe(0x80000010) == "main+0x10");
}
