// Timed generated code (block_jit.hpp with BlockJit::Timing) against the
// block-costed interpreter: with a cycle model and a profiler, runs with and
// without it must leave the same registers, memory, counts and stops (as
// plain runs) and the same cycles, instruction mix, branch, misprediction
// and load-use statistics and the same profile, for every instruction
// limit, across model and profiler changes between runs, and when an entry
// before a translated block is decoded later.
#include <catch2/catch.hpp>

#include <memory>
#include <random>
#include <sstream>

#include "jit_programs.hpp"
#include "profile_writers.hpp"

using namespace rv;
using namespace jit_programs;
using fwsim::StopCause;
using fwsim::StopInfo;

namespace {

// Static predictors (the branch cycles are block costs) and dynamic ones
// (the predictor is called), with taken and not-taken cycles and stalls that
// differ, so a miscounted branch or stall shows.
fwsim::CycleModelConfig model_config(unsigned which) {
  fwsim::CycleModelConfig c = fwsim::default_cycle_model();
  if (which % 5 == 3) {
    c.predictor = fwsim::PredictorKind::Gshare;
    c.predictor_bits = 4;
    c.mispredict_penalty = 5;
  } else if (which % 5 == 4) {
    c.predictor = fwsim::PredictorKind::Bimodal;
    c.predictor_bits = 3;
    c.branch_taken = 3;
  } else if (which % 5 == 1) {
    c.predictor = fwsim::PredictorKind::StaticNotTaken;
    c.branch_taken = 5;
    c.branch_not_taken = 2;
    c.mispredict_penalty = 7;
    c.load_use_stall = 3;
  } else if (which % 5 == 2) {
    c.branch_taken = 1;
    c.branch_not_taken = 4;
    c.mispredict_penalty = 9;
    c.load_use_stall = 2;
    c.latency[static_cast<size_t>(fwsim::InsnClass::Jump)] = 6;
  }
  return c;
}

// A random program run with a cycle model and (optionally) a profiler.
struct TimedSim {
  Sim sim;
  fwsim::SymbolTable symbols;
  fwsim::CycleModel model;
  std::unique_ptr<fwsim::Profiler> profiler;

  TimedSim(const Program& p, bool jit, uint8_t frm, const fwsim::CycleModelConfig& cfg, bool profile)
      : sim(p.code), model(cfg) {
    load(sim, p, jit, frm);
    symbols.add({"start", fwsim::kRamBase, 4});
    symbols.add({"sub", fwsim::kRamBase + 4, 0});
    symbols.add({"loop", fwsim::kRamBase + 4 * p.loop, 0});
    symbols.finalize();
    sim.m.set_cycle_model(&model);
    if (profile) {
      profiler = std::make_unique<fwsim::Profiler>(symbols, fwsim::kRamBase);
      sim.m.set_profiler(profiler.get());
    }
  }
  // Callgrind and folded output of the profile so far.
  std::string profile() {
    if (!profiler) return {};
    profiler->finish(fwsim::Cost{sim.m.hart().instret, sim.m.hart().cycles});
    std::ostringstream out;
    fwsim::write_callgrind(*profiler, out, "test", "test.elf");
    fwsim::write_folded(*profiler, out);
    return out.str();
  }
};

void require_same_timing(TimedSim& a, TimedSim& b, const StopInfo& sa, const StopInfo& sb) {
  require_same(a.sim, b.sim, sa, sb);
  for (unsigned op = 0; op < static_cast<unsigned>(fwsim::Op::Count); ++op) {
    INFO("op " << op);
    REQUIRE(a.model.op_count(static_cast<fwsim::Op>(op)) == b.model.op_count(static_cast<fwsim::Op>(op)));
  }
  REQUIRE(a.model.branches() == b.model.branches());
  REQUIRE(a.model.mispredicts() == b.model.mispredicts());
  REQUIRE(a.model.load_use_stalls() == b.model.load_use_stalls());
}

}  // namespace

TEST_CASE("timed generated code matches the interpreter on random loops", "[jit][cycle]") {
  uint64_t blocks = 0;
  for (uint32_t seed = 1; seed <= 300; ++seed) {
    INFO("seed " << seed);
    const Program p = random_program(seed);
    const fwsim::CycleModelConfig cfg = model_config(seed);
    for (uint8_t frm : {uint8_t{0}, uint8_t{1}}) {
      const bool profile = frm == 0 || seed % 2;
      TimedSim with(p, true, frm, cfg, profile), without(p, false, frm, cfg, profile);
      const StopInfo a = with.sim.run(), b = without.sim.run();
      require_same_timing(with, without, a, b);
      REQUIRE(with.profile() == without.profile());
      CHECK(without.sim.m.jit_blocks() == 0);
      blocks += with.sim.m.jit_blocks();
    }
  }
  CHECK(blocks > 1000);  // the loops did run as generated code
}

TEST_CASE("timed generated code stops at the same instruction limit", "[jit][cycle]") {
  for (uint32_t seed = 2000; seed < 2040; ++seed) {
    INFO("seed " << seed);
    const Program p = random_program(seed);
    const fwsim::CycleModelConfig cfg = model_config(seed);
    const uint64_t total = instructions_to_end(p);
    std::mt19937 rng(seed);
    for (int k = 0; k < 8; ++k) {
      const uint64_t limit = 1 + rng() % total;
      INFO("limit " << limit);
      TimedSim with(p, true, 0, cfg, true), without(p, false, 0, cfg, true);
      StopInfo a = with.sim.run(limit), b = without.sim.run(limit);
      require_same_timing(with, without, a, b);
      // Resuming after the limit continues identically.
      a = with.sim.run();
      b = without.sim.run();
      require_same_timing(with, without, a, b);
      REQUIRE(with.profile() == without.profile());
    }
  }
}

TEST_CASE("timed generated code follows model and profiler changes between runs", "[jit][cycle]") {
  uint64_t blocks = 0;
  for (uint32_t seed = 3000; seed < 3030; ++seed) {
    INFO("seed " << seed);
    const Program p = random_program(seed);
    TimedSim with(p, true, 0, model_config(seed), true), without(p, false, 0, model_config(seed), true);
    fwsim::CycleModel other_with(model_config(seed + 1)), other_without(model_config(seed + 1));
    StopInfo a = with.sim.run(300), b = without.sim.run(300);
    require_same_timing(with, without, a, b);
    // Another model for a while (its own statistics), then no profiler.
    with.sim.m.set_cycle_model(&other_with);
    without.sim.m.set_cycle_model(&other_without);
    a = with.sim.run(900);
    b = without.sim.run(900);
    require_same(with.sim, without.sim, a, b);
    REQUIRE(other_with.branches() == other_without.branches());
    REQUIRE(other_with.mispredicts() == other_without.mispredicts());
    REQUIRE(other_with.load_use_stalls() == other_without.load_use_stalls());
    REQUIRE(with.profile() == without.profile());
    with.sim.m.set_cycle_model(&with.model);
    without.sim.m.set_cycle_model(&without.model);
    with.sim.m.set_profiler(nullptr);
    without.sim.m.set_profiler(nullptr);
    a = with.sim.run();
    b = without.sim.run();
    require_same_timing(with, without, a, b);
    blocks += with.sim.m.jit_blocks();
  }
  CHECK(blocks > 100);
}

TEST_CASE("a translated block's cost follows the entry before it being decoded later", "[jit][cycle]") {
  // Entry 2 is hot as a branch target while entry 1 (a load whose result it
  // uses) has never run; then 1 runs and falls into 2 (a load-use stall),
  // then 2 is reached by the branch again (no stall when entered by a jump).
  const std::vector<uint32_t> code = {beq(8, 0, 8),     // 0
                                      lw(5, 2, 0),      // 1
                                      add(6, 5, 6),     // 2
                                      addi(9, 9, -1),   // 3
                                      bne(9, 0, -16),   // 4
                                      addi(9, 0, 40),   // 5
                                      i_type(1, 8, 4, 8, 0x13),  // 6: xori x8, x8, 1
                                      addi(10, 10, -1), // 7
                                      bne(10, 0, -32)}; // 8
  uint64_t cycles[2] = {}, stalls[2] = {};
  for (bool jit : {true, false}) {
    Sim s(code);
    fwsim::CycleModel model(fwsim::default_cycle_model());
    s.m.set_cycle_model(&model);
    s.m.set_jit(jit);
    s.x(2) = fwsim::kRamBase + kDataOffset;
    s.x(9) = 40;
    s.x(10) = 3;
    CHECK(s.run().cause == StopCause::Ebreak);
    cycles[jit] = s.m.hart().cycles;
    stalls[jit] = model.load_use_stalls();
    if (jit) CHECK(s.m.jit_blocks() > 0);
  }
  CHECK(stalls[1] == 40);
  CHECK(stalls[0] == stalls[1]);
  CHECK(cycles[0] == cycles[1]);
}

TEST_CASE("timed runs with caches stay interpreted", "[jit][cycle]") {
  const Program p = random_program(7);
  fwsim::CycleModelConfig dcache = fwsim::default_cycle_model(), icache = dcache;
  dcache.dcache.size = 1024;
  icache.icache.size = 1024;
  for (const fwsim::CycleModelConfig& cfg : {dcache, icache}) {
    TimedSim with(p, true, 0, cfg, true), without(p, false, 0, cfg, true);
    const StopInfo a = with.sim.run(), b = without.sim.run();
    require_same_timing(with, without, a, b);
    REQUIRE(with.profile() == without.profile());
    CHECK(with.sim.m.jit_blocks() == 0);
  }
}
