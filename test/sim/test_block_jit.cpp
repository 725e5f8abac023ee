// Generated code (block_jit.hpp) against the interpreter: the same programs
// run with and without it must leave the same registers, memory, flags,
// instruction counts and stop reasons, for every instruction limit, and
// with decoded code changing under it (fence.i, breakpoints).
#include <catch2/catch.hpp>

#include <random>

#include "jit_programs.hpp"

using namespace rv;
using namespace jit_programs;
using fwsim::StopCause;
using fwsim::StopInfo;

TEST_CASE("generated code matches the interpreter on random loops", "[jit]") {
  uint64_t blocks = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    INFO("seed " << seed);
    const Program p = random_program(seed);
    for (uint8_t frm : {uint8_t{0}, uint8_t{1}}) {
      Sim with(p.code), without(p.code);
      load(with, p, true, frm);
      load(without, p, false, frm);
      const StopInfo a = with.run(), b = without.run();
      require_same(with, without, a, b);
      CHECK(without.m.jit_blocks() == 0);
      blocks += with.m.jit_blocks();
    }
  }
  CHECK(blocks > 1000);  // the loops did run as generated code
}

TEST_CASE("generated code stops at the same instruction limit", "[jit]") {
  for (uint32_t seed = 1000; seed < 1040; ++seed) {
    INFO("seed " << seed);
    const Program p = random_program(seed);
    const uint64_t total = instructions_to_end(p);
    std::mt19937 rng(seed);
    for (int k = 0; k < 8; ++k) {
      const uint64_t limit = 1 + rng() % total;
      INFO("limit " << limit);
      Sim with(p.code), without(p.code);
      load(with, p, true, 0);
      load(without, p, false, 0);
      StopInfo a = with.run(limit), b = without.run(limit);
      require_same(with, without, a, b);
      // Resuming after the limit continues identically.
      a = with.run();
      b = without.run();
      require_same(with, without, a, b);
    }
  }
}

TEST_CASE("generated code leaves loads outside RAM to the interpreter", "[jit]") {
  // A hot loop whose load address walks from RAM's last word past its end:
  // the same fault, at the same instruction and count.
  const std::vector<uint32_t> code = {lw(5, 6, 0),       // 0
                                      addi(6, 6, 4),     // 1
                                      addi(7, 7, 1),     // 2
                                      jal(0, -12)};      // 3
  for (bool jit : {true, false}) {
    Sim s(code);
    s.m.set_jit(jit);
    s.x(6) = fwsim::kRamBase + (1u << 20) - 400;
    const StopInfo stop = s.run();
    CHECK(stop.cause == StopCause::LoadFault);
    CHECK(stop.pc == fwsim::kRamBase);
    CHECK(stop.addr == fwsim::kRamBase + (1u << 20));
    CHECK(s.x(7) == 100);
    CHECK(s.m.hart().instret == 400);
    if (jit) CHECK(s.m.jit_blocks() > 0);
  }
}

TEST_CASE("generated code sees fence.i and leaves stored code alone without it", "[jit][smc]") {
  // The loop body's first word is overwritten after 30 iterations (by then
  // translated); without fence.i the old instruction keeps running, after
  // it the new one does.
  const uint32_t patch = addi(5, 5, 100);
  for (bool fence : {false, true}) {
    std::vector<uint32_t> code = {addi(5, 5, 1),                // 0: loop
                                  addi(8, 8, -1),               // 1
                                  bne(8, 9, 12),                // 2: at x8 == 30, patch
                                  sw(6, 7, 0),                  // 3
                                  fence ? fence_i() : 0x0ff0000fu,  // 4
                                  bne(8, 0, -20)};              // 5
    uint32_t x5[2] = {}, n[2] = {};
    for (bool jit : {true, false}) {
      Sim s(code);
      s.m.set_jit(jit);
      s.x(6) = patch;
      s.x(7) = fwsim::kRamBase;
      s.x(8) = 60;
      s.x(9) = 30;
      CHECK(s.run().cause == StopCause::Ebreak);
      x5[jit] = s.x(5);
      n[jit] = static_cast<uint32_t>(s.m.hart().instret);
      if (jit) CHECK(s.m.jit_blocks() > 0);
    }
    CHECK(x5[0] == x5[1]);
    CHECK(n[0] == n[1]);
    CHECK(x5[1] == (fence ? 30u + 30u * 100u : 60u));
  }
}

TEST_CASE("a breakpoint set in translated code stops there", "[jit]") {
  const std::vector<uint32_t> code = {addi(5, 5, 1), addi(6, 6, 2), add(7, 5, 6), bne(5, 9, -12)};
  StopInfo stops[2][2];
  uint64_t counts[2][2] = {};
  for (bool jit : {true, false}) {
    Sim s(code);
    s.m.set_jit(jit);
    s.x(9) = 1000;
    // Run hot first, then break on the add inside the loop.
    CHECK(s.run(500).cause == StopCause::InstructionLimit);
    REQUIRE(s.m.set_breakpoint(fwsim::kRamBase + 8));
    stops[jit][0] = s.run();
    counts[jit][0] = s.m.hart().instret;
    s.m.clear_breakpoint(fwsim::kRamBase + 8);
    stops[jit][1] = s.run();
    counts[jit][1] = s.m.hart().instret;
    CHECK(s.x(5) == 1000);
    if (jit) CHECK(s.m.jit_blocks() > 0);
  }
  for (int k = 0; k < 2; ++k) {
    CHECK(stops[0][k].cause == stops[1][k].cause);
    CHECK(stops[0][k].pc == stops[1][k].pc);
    CHECK(counts[0][k] == counts[1][k]);
  }
  CHECK(stops[1][0].cause == StopCause::Breakpoint);
  CHECK(stops[1][0].pc == fwsim::kRamBase + 8);
  CHECK(stops[1][1].cause == StopCause::Ebreak);
}
