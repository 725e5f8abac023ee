// Fused pairs (isa_table.hpp FWSIM_FUSED): a pair runs as both of its
// instructions, faults in the second stop at the second, a jump into the
// second runs it alone, and a breakpoint on the second undoes the fusion.
#include <catch2/catch.hpp>

#include "sim_harness.hpp"

using namespace fwsim;

TEST_CASE("fused pairs run as two instructions", "[fused]") {
  // lw, lw (second uses the first's result); addi, beq taken and not taken.
  Sim s({rv::lw(5, 10, 0), rv::lw(6, 5, 4), rv::addi(7, 6, 1), rv::beq(7, 0, 8), rv::addi(8, 0, 3),
         rv::addi(9, 0, 4)});
  const uint32_t data = kRamBase + 0x1000;
  s.x(10) = data;
  const uint32_t words[2] = {data + 8, 0};
  std::memcpy(s.m.bus().ram() + 0x1000, words, 8);
  const uint32_t target = 41;
  std::memcpy(s.m.bus().ram() + 0x100c, &target, 4);
  CHECK(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(5) == data + 8);
  CHECK(s.x(6) == 41);
  CHECK(s.x(7) == 42);
  CHECK(s.x(8) == 3);
  CHECK(s.x(9) == 4);
  CHECK(s.m.hart().instret == 6);
}

TEST_CASE("a fault in the second of a pair stops at the second", "[fused]") {
  Sim s({rv::lw(5, 10, 0), rv::lw(6, 11, 0)});
  s.x(10) = kRamBase + 0x1000;
  s.x(11) = 0x4;  // no memory there
  const StopInfo stop = s.run();
  CHECK(stop.cause == StopCause::LoadFault);
  CHECK(stop.pc == kRamBase + 4);
  CHECK(s.m.hart().instret == 1);
}

TEST_CASE("a breakpoint on the second instruction of a pair stops there", "[fused]") {
  Sim s({rv::addi(5, 0, 1), rv::addi(6, 0, 2), rv::addi(7, 0, 3)});
  // First run decodes and fuses; the breakpoint then splits the pair.
  REQUIRE(s.run().cause == StopCause::Ebreak);
  s.x(5) = s.x(6) = s.x(7) = 0;
  s.m.hart().pc = kRamBase;
  REQUIRE(s.m.set_breakpoint(kRamBase + 4));
  const StopInfo stop = s.run();
  CHECK(stop.cause == StopCause::Breakpoint);
  CHECK(stop.pc == kRamBase + 4);
  CHECK(s.x(5) == 1);
  CHECK(s.x(6) == 0);
}
