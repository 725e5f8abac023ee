// --trace: every retired instruction with the registers and memory it wrote.
#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

TEST_CASE("trace shows register writes, FP values and stores", "[cli][trace]") {
  Result r = sim("--stats --trace " + kElf + " -- exit 3");
  REQUIRE(r.status == 3);
  // crt0's first instruction: li t0, 0x6000 (mstatus.FS), then csrs without rd.
  CHECK(r.err.rfind("80000000: 000062b7  lui t0, 0x6                      t0=0x00006000\n"
                    "80000004: 3002a073  csrrs zero, 0x300, t0\n", 0) == 0);
  // The finisher store that ends the run: (3 << 16) | 0x3333 to 0x100000.
  CHECK(std::regex_search(r.err, std::regex("sw [a-z0-9]+, 0\\([a-z0-9]+\\) +mem32\\[0x00100000\\]=0x00033333\n")));
  // One line per retired instruction, every one with pc, word and text.
  std::istringstream lines(r.err);
  uint64_t traced = 0;
  for (std::string line; std::getline(lines, line);) {
    if (std::regex_match(line, std::regex("[0-9a-f]{8}: [0-9a-f]{8}  .*"))) ++traced;
  }
  CHECK(traced == stat_value(r.err, "instructions"));

  Result w = sim("--trace " + kElf);  // the workload: float loads and arithmetic
  REQUIRE(w.status == 0);
  // b[0] = 0 * 0.37f - 2 and the float constant 1.0f load as in the source.
  CHECK(std::regex_search(w.err, std::regex("flw (f[a-z0-9]+), -?[0-9]+\\([a-z0-9]+\\) +\\1=0x3f800000 \\(1\\)\n")));
  CHECK(std::regex_search(w.err, std::regex("fdiv\\.s (f[a-z0-9]+), .* +\\1=0x[0-9a-f]{8} \\(-?[0-9.e+-]+\\)\n")));
  CHECK(std::regex_search(w.err, std::regex("sb [a-z0-9]+, 0\\([a-z0-9]+\\) +mem8\\[0x10000000\\]=0x66\n")));  // 'f'
  // Writes to x0 show no effect.
  CHECK(w.err.find("zero=") == std::string::npos);
}
