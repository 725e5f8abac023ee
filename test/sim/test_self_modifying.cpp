// Code written by the program runs as written after a fence.i: the
// pre-decoded entries (and fused pairs, and block costs in the timed loop)
// are dropped, while debugger breakpoints stay.
#include <catch2/catch.hpp>

#include "cycle_model.hpp"
#include "sim_harness.hpp"

using namespace rv;
using fwsim::StopCause;

namespace {
// Calls f (entry 5) twice; between the calls it stores x6 over f's first
// instruction and runs fence.i. f sets x5 and returns.
std::vector<uint32_t> patching_program() {
  return {jal(1, 20),      // 0: call f: decodes the original
          sw(6, 7, 20),    // 1: overwrite f's first word
          fence_i(),       // 2
          jal(1, 8),       // 3: call f again
          ebreak(),        // 4
          addi(5, 0, 1),   // 5: f (original: x5 = 1)
          addi(8, 8, 1),   // 6: counts f's runs (fuses with 5 as addi+addi)
          jalr(0, 1, 0)};  // 7
}
void set_patch(Sim& s) {
  s.x(6) = addi(5, 0, 7);  // the patch: x5 = 7
  s.x(7) = fwsim::kRamBase;
}
}  // namespace

TEST_CASE("fence.i makes stored code run as written", "[smc]") {
  Sim s(patching_program());
  set_patch(s);
  CHECK(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(5) == 7);
  CHECK(s.x(8) == 2);
  CHECK(s.m.hart().instret == 10);
}

TEST_CASE("fence.i makes stored code run as written in the timed loop", "[smc]") {
  Sim s(patching_program());
  set_patch(s);
  fwsim::CycleModel model(fwsim::default_cycle_model());
  s.m.set_cycle_model(&model);
  CHECK(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(5) == 7);
  CHECK(s.x(8) == 2);
  CHECK(s.m.hart().instret == 10);
  CHECK(s.m.hart().cycles >= 10);
}

TEST_CASE("fence.i keeps debugger breakpoints", "[smc]") {
  Sim s(patching_program());
  set_patch(s);
  REQUIRE(s.m.set_breakpoint(fwsim::kRamBase + 6 * 4));
  fwsim::StopInfo stop = s.run();
  REQUIRE(stop.cause == StopCause::Breakpoint);  // first call of f
  CHECK(s.x(5) == 1);
  s.m.clear_breakpoint(stop.pc);
  // Step over: run one instruction, then set the breakpoint again.
  CHECK(s.m.run(s.m.hart().instret + 1).cause == StopCause::InstructionLimit);
  REQUIRE(s.m.set_breakpoint(fwsim::kRamBase + 6 * 4));
  stop = s.run();
  REQUIRE(stop.cause == StopCause::Breakpoint);  // second call, after the fence.i
  CHECK(stop.pc == fwsim::kRamBase + 6 * 4);
  CHECK(s.x(5) == 7);
}
