// Cycle model: config parsing, class latencies, load-use stalls, branch
// predictors and caches, checked on small programs with known timing.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "cycle_model.hpp"
#include "sim_harness.hpp"

using namespace rv;
using fwsim::CycleModel;
using fwsim::parse_cycle_model;

namespace {
// All latencies 1, no stalls, no penalties: a neutral base to vary.
const char* kUnit =
    "alu=1\nmul=1\ndiv=1\nload=1\nstore=1\njump=1\ncsr=1\nsystem=1\nfp_add=1\nfp_mul=1\nfp_div=1\n"
    "fp_sqrt=1\nfp_convert=1\nfp_compare=1\nfp_move=1\nfp_fused=1\nfp_load=1\nfp_store=1\n"
    "branch_taken=1\nbranch_not_taken=1\nmispredict_penalty=0\nload_use_stall=0\n";

uint64_t cycles_of(Sim& s, const std::string& cfg) {
  CycleModel model(parse_cycle_model(std::string(kUnit) + cfg, "test"));
  s.m.set_cycle_model(&model);
  REQUIRE(s.run().cause == fwsim::StopCause::Ebreak);
  return s.m.hart().cycles;
}
}  // namespace

TEST_CASE("the default model parses and keys override it", "[cycle]") {
  auto d = fwsim::default_cycle_model();
  CHECK(d.clock_hz == 100000000u);
  CHECK(d.latency[static_cast<size_t>(fwsim::InsnClass::Div)] == 34u);
  auto c = parse_cycle_model("div = 7 # comment\n\npredictor = gshare\npredictor_bits=12\n", "x");
  CHECK(c.latency[static_cast<size_t>(fwsim::InsnClass::Div)] == 7u);
  CHECK(c.latency[static_cast<size_t>(fwsim::InsnClass::Mul)] == 3u);
  CHECK(c.predictor == fwsim::PredictorKind::Gshare);
  CHECK(c.predictor_bits == 12u);
}

TEST_CASE("bad model files are rejected with file and line", "[cycle]") {
  auto msg = [](const std::string& text) {
    try {
      parse_cycle_model(text, "m.cfg");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(msg("alu = 1\nbogus = 3\n") == "m.cfg:2: unknown key 'bogus'");
  CHECK(msg("alu 1\n") == "m.cfg:1: expected `key = value`");
  CHECK(msg("mul = -1\n") == "m.cfg:1: '-1' is not a non-negative integer");
  CHECK(msg("predictor = perceptron\n").find("unknown predictor") != std::string::npos);
  CHECK(msg("dcache_size = 1000\ndcache_line = 24\n").find("dcache_line") != std::string::npos);
  CHECK(msg("clock_hz = 0\n").find("clock_hz") != std::string::npos);
}

TEST_CASE("class latencies add up", "[cycle]") {
  Sim s({addi(1, 0, 6), addi(2, 0, 3), mul(3, 1, 2), div(4, 1, 2), add(5, 3, 4)});
  // 3 ALU + mul 5 + div 20; the final ebreak traps and does not retire
  CHECK(cycles_of(s, "mul=5\ndiv=20\n") == 3 + 5 + 20);
}

TEST_CASE("load-use stall only when the next instruction reads the loaded register", "[cycle]") {
  Sim dep({lw(1, 5, 0), addi(2, 1, 1)});
  dep.x(5) = fwsim::kRamBase;
  Sim indep({lw(1, 5, 0), addi(2, 3, 1)});
  indep.x(5) = fwsim::kRamBase;
  Sim fdep({flw(1, 5, 0), fadd(2, 1, 1)});
  fdep.x(5) = fwsim::kRamBase;
  CHECK(cycles_of(dep, "load_use_stall=4\n") == 2 + 4);
  CHECK(cycles_of(indep, "load_use_stall=4\n") == 2);
  CHECK(cycles_of(fdep, "load_use_stall=4\n") == 2 + 4);
}

TEST_CASE("branch predictors: static, backward-taken, bimodal, gshare", "[cycle]") {
  // A 100-iteration loop: backward branch taken 99 times, not taken once.
  auto loop = [] {
    auto s = std::make_unique<Sim>(std::vector<uint32_t>{addi(1, 0, 100), addi(1, 1, -1), bne(1, 0, -4)});
    return s;
  };
  const std::string pen = "mispredict_penalty=10\n";
  auto s1 = loop();
  const uint64_t base = 1 + 100 + 100;  // addi, 100 addi, 100 branches
  CHECK(cycles_of(*s1, pen + "predictor=static_not_taken\n") == base + 99 * 10);
  auto s2 = loop();
  CHECK(cycles_of(*s2, pen + "predictor=backward_taken\n") == base + 1 * 10);
  auto s3 = loop();
  // Counters start weakly not-taken: first iteration mispredicts, then the exit.
  CHECK(cycles_of(*s3, pen + "predictor=bimodal\n") == base + 2 * 10);
  auto s4 = loop();
  const uint64_t g = cycles_of(*s4, pen + "predictor=gshare\npredictor_bits=4\n");
  CHECK(g > base);
  CHECK(g < base + 99 * 10);
}

TEST_CASE("branch and misprediction counts, the last branch falling through to a trap", "[cycle]") {
  // The loop's final, not-taken branch is the last instruction to retire
  // (the ebreak after it traps): it must not count as taken.
  struct Case {
    const char* predictor;
    uint64_t mispredicts;
  };
  for (const Case c : {Case{"static_not_taken", 99}, Case{"backward_taken", 1}, Case{"bimodal", 2}}) {
    INFO(c.predictor);
    Sim s({addi(1, 0, 100), addi(1, 1, -1), bne(1, 0, -4)});
    CycleModel model(parse_cycle_model(std::string(kUnit) + "predictor=" + c.predictor + "\n", "test"));
    s.m.set_cycle_model(&model);
    REQUIRE(s.run().cause == fwsim::StopCause::Ebreak);
    CHECK(model.branches() == 100u);
    CHECK(model.mispredicts() == c.mispredicts);
  }
}

TEST_CASE("data cache misses cost the miss penalty, LRU keeps the working set", "[cycle]") {
  // Two loads to the same line: 1 miss. Then 3 lines in a 2-way, 1-set cache:
  // a, b, a, c, b -> misses a, b, c, b (b was evicted by c as LRU).
  Sim same({lw(1, 5, 0), lw(2, 5, 4)});
  same.x(5) = fwsim::kRamBase + 0x1000;
  CHECK(cycles_of(same, "dcache_size=64\ndcache_ways=2\ndcache_line=32\ndcache_miss_penalty=50\n") == 2 + 50);
  Sim lru({lw(1, 5, 0), lw(1, 5, 32), lw(1, 5, 0), lw(1, 5, 64), lw(1, 5, 32)});
  lru.x(5) = fwsim::kRamBase + 0x1000;
  CHECK(cycles_of(lru, "dcache_size=64\ndcache_ways=2\ndcache_line=32\ndcache_miss_penalty=50\n") == 5 + 4 * 50);
}

TEST_CASE("instruction cache counts a miss per new line", "[cycle]") {
  // 8 retired instructions in 32 bytes: lines of 16 bytes -> 2 misses.
  Sim s({addi(1, 0, 1), addi(1, 0, 1), addi(1, 0, 1), addi(1, 0, 1), addi(1, 0, 1), addi(1, 0, 1),
         addi(1, 0, 1), addi(1, 0, 1)});
  CHECK(cycles_of(s, "icache_size=256\nicache_ways=1\nicache_line=16\nicache_miss_penalty=7\n") == 8 + 2 * 7);
}

TEST_CASE("cycle and time CSRs read the model's cycle count", "[cycle][counters]") {
  Sim s({mul(1, 1, 1), csrrs(10, kCycle, 0), csrrs(11, 0xc01, 0)});
  const uint64_t c = cycles_of(s, "mul=100\nclock_hz=10000000\n");
  CHECK(s.x(10) == 100u);  // counts what retired before the read
  CHECK(s.x(11) == 101u);  // time at 10 MHz timebase = cycles at a 10 MHz clock
  CHECK(c == 102u);
}
