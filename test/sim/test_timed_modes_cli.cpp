// The timed interpreter has two forms: pre-computed costs per instruction
// (block_costs.hpp) and per-instruction model calls (used with --trace and
// caches). Both must count the same cycles, instruction mix, stalls and
// profile.
#include <catch2/catch.hpp>

#include <regex>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
// The --stats lines the model fills in.
std::string model_lines(const std::string& err) {
  std::string out;
  std::regex keep("^(instructions|cycles|instruction mix|branches): .*$");
  size_t pos = 0;
  while (pos < err.size()) {
    const size_t end = err.find('\n', pos);
    const std::string line = err.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
    if (std::regex_match(line, keep)) out += line + "\n";
    if (end == std::string::npos) break;
    pos = end + 1;
  }
  return out;
}
}  // namespace

TEST_CASE("block-costed and per-instruction timing count the same", "[cli][cycle]") {
  const std::string fast_cg = temp_path("fast.cg"), hooks_cg = temp_path("hooks.cg");
  // A model without caches runs block-costed; --trace forces the hooks.
  const Result fast = sim("--stats --cycle-model default --folded-out " + fast_cg + " " + kElf);
  const Result hooks = sim("--stats --trace --cycle-model default --folded-out " + hooks_cg + " " + kElf);
  REQUIRE(fast.status == hooks.status);
  CHECK(fast.out == hooks.out);
  const std::string lines = model_lines(fast.err);
  CHECK(lines.find("load-use stalls: ") != std::string::npos);
  CHECK(stat_value(fast.err, "cycles") > stat_value(fast.err, "instructions"));
  CHECK(lines == model_lines(hooks.err));
  CHECK(slurp(fast_cg) == slurp(hooks_cg));
  CHECK(!slurp(fast_cg).empty());
  std::remove(fast_cg.c_str());
  std::remove(hooks_cg.c_str());
}

TEST_CASE("block-costed branch cycles agree with the predictor's for every kind", "[cli][cycle]") {
  // Static predictors take the branch cycles from the cost slots (a taken
  // difference beyond int8 falls back to the model call), the others call
  // the predictor: each must match the hooked loop, which always calls it.
  const char* const models[] = {
      "predictor = static_not_taken\nbranch_taken = 5\nbranch_not_taken = 2\nmispredict_penalty = 7\n",
      "predictor = backward_taken\nbranch_taken = 1\nbranch_not_taken = 4\nmispredict_penalty = 9\n",
      "predictor = backward_taken\nbranch_taken = 300\nmispredict_penalty = 1\n",
      "predictor = gshare\nmispredict_penalty = 3\n",
  };
  for (const char* model : models) {
    INFO(model);
    const std::string cfg = temp_path("branches.cfg");
    const std::string fast_cg = temp_path("fast.cg"), hooks_cg = temp_path("hooks.cg");
    spit(cfg, model);
    const Result fast = sim("--stats --cycle-model " + cfg + " --folded-out " + fast_cg + " " + kElf);
    const Result hooks = sim("--stats --trace --cycle-model " + cfg + " --folded-out " + hooks_cg + " " + kElf);
    REQUIRE(fast.status == hooks.status);
    const std::string lines = model_lines(fast.err);
    CHECK(lines.find("mispredicted: ") != std::string::npos);
    CHECK(lines == model_lines(hooks.err));
    CHECK(slurp(fast_cg) == slurp(hooks_cg));
    std::remove(cfg.c_str());
    std::remove(fast_cg.c_str());
    std::remove(hooks_cg.c_str());
  }
}
