// What the scene-reader fuzz targets share: an arena allocated once, the
// general model's builder over it, the rule that a refusal says what it
// refuses, and the entry point that runs a target in double and in the
// board's float.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "core/base/byte_io.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/model/scene_builder.hpp"

namespace fuzzing {

// An arena over `bytes` allocated once per policy: an arena needs no
// clearing between inputs.
template <class M>
minrt::Arena arena_once(std::size_t bytes = std::size_t{1} << 22) {
  static std::vector<unsigned char> storage(bytes);
  return minrt::Arena(storage.data(), storage.size());
}

// One input for a reader of the general model (CS418, miniRT).
template <class M>
struct GeneralInput {
  minrt::Arena arena = arena_once<M>();
  minrt::model::SceneBuilder<typename M::real> builder{arena};
  minrt::MemorySource mem;
};

// A texture resolver that gives every name the first texture.
inline int32_t any_texture(void*, const char*, minrt::Diagnostic&) { return 0; }

// A reader never refuses silently: it says what, and where when `located`.
inline void require_message(const minrt::Diagnostic& d, bool located) {
  if (d.length <= 0 || (located && !d.has_pos)) std::abort();
}

}  // namespace fuzzing

// The libFuzzer entry point: `read_one` on each input in double and in the
// board's portable float.
#define MINRT_FUZZ_BOTH_POLICIES(read_one)                                  \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { \
    read_one<minrt::LibmDouble>(data, size);                                \
    read_one<minrt::PortableFloat>(data, size);                             \
    return 0;                                                               \
  }
