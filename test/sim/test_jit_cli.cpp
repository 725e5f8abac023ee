// --no-jit on the command line: the same firmware runs give the same UART
// output, stop messages, exit status and counts with and without generated
// code, plain and timed (cycles, statistics and profiles too), and --stats
// says which ran.
#include <catch2/catch.hpp>

#include <cstdio>
#include <regex>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

TEST_CASE("runs with and without generated code end alike", "[cli][jit]") {
  const char* const runs[] = {"", " -- illegal", " -- load-fault", " -- misaligned", " -- ebreak",
                              " -- ecall", " -- exit 42", " -- args alpha beta"};
  for (const char* args : runs) {
    INFO("firmware arguments:" << args);
    const Result jit = sim(kElf + args);
    const Result plain = sim("--no-jit " + kElf + args);
    CHECK(jit.status == plain.status);
    CHECK(jit.out == plain.out);
    CHECK(jit.err == plain.err);  // stop messages carry the instruction count
  }
  // The instruction limit stops a spinning loop (translated code) at the same point.
  const Result spin = sim("--max-instructions 100000 " + kElf + " -- spin");
  CHECK(spin.status == 5);
  CHECK(spin.err == sim("--no-jit --max-instructions 100000 " + kElf + " -- spin").err);
}

TEST_CASE("stats report the translated blocks", "[cli][jit]") {
  const Result jit = sim("--stats " + kElf);
  const Result plain = sim("--stats --no-jit " + kElf);
  REQUIRE(jit.status == 0);
  REQUIRE(plain.status == 0);
  CHECK(stat_value(jit.err, "instructions") == stat_value(plain.err, "instructions"));
  CHECK(std::regex_search(jit.err, std::regex("\njit: [1-9][0-9]* blocks translated\n")));
  CHECK(plain.err.find("\njit: off (--no-jit)\n") != std::string::npos);
  // Timed runs use it with a static predictor and no caches, not with caches.
  const Result timed = sim("--stats --cycle-model default " + kElf);
  CHECK(std::regex_search(timed.err, std::regex("\njit: [1-9][0-9]* blocks translated\n")));
  const std::string cfg = temp_path("jit-cache.cfg");
  spit(cfg, "dcache_size = 1024\n");
  CHECK(sim("--stats --cycle-model " + cfg + " " + kElf).err.find("\njit: 0 blocks translated\n") != std::string::npos);
  std::remove(cfg.c_str());
}

namespace {
// --stats output without the lines that vary from run to run (host speed)
// or name the code generator.
std::string stable_stats(const std::string& err) {
  std::string out;
  size_t pos = 0;
  while (pos < err.size()) {
    size_t end = err.find('\n', pos);
    if (end == std::string::npos) end = err.size();
    const std::string line = err.substr(pos, end - pos);
    if (line.rfind("host ", 0) != 0 && line.rfind("jit: ", 0) != 0) out += line + "\n";
    pos = end + 1;
  }
  return out;
}
}  // namespace

TEST_CASE("timed and profiled runs report the same without generated code", "[cli][jit][cycle]") {
  // Every trap and exit with the default model and all profile outputs.
  const char* const runs[] = {"", " -- illegal", " -- load-fault", " -- exit 42", " -- args alpha beta"};
  for (const char* args : runs) {
    INFO("firmware arguments:" << args);
    std::string outputs[2];
    Result r[2];
    for (int no_jit = 0; no_jit < 2; ++no_jit) {
      const std::string cg = temp_path("jit-timed.cg"), folded = temp_path("jit-timed.folded");
      r[no_jit] = sim(std::string(no_jit ? "--no-jit " : "") + "--stats --cycle-model default --profile-out " + cg +
                      " --folded-out " + folded + " " + kElf + args);
      outputs[no_jit] = slurp(cg) + slurp(folded);
      std::remove(cg.c_str());
      std::remove(folded.c_str());
    }
    CHECK(r[0].status == r[1].status);
    CHECK(r[0].out == r[1].out);
    CHECK(stable_stats(r[0].err) == stable_stats(r[1].err));
    CHECK(stat_value(r[0].err, "cycles") > stat_value(r[0].err, "instructions"));
    CHECK(outputs[0] == outputs[1]);
    CHECK(!outputs[0].empty());
  }
}

#ifdef FWSIM_RENDERER_ELF
TEST_CASE("the renderer's image and count are the same without generated code", "[cli][jit]") {
  std::string image[2];
  uint64_t count[2] = {};
  for (int no_jit = 0; no_jit < 2; ++no_jit) {
    const std::string out = temp_path("jit-render.ppm");
    const Result r = sim(std::string(no_jit ? "--no-jit " : "") + "--stats --uart-in " + FWSIM_RENDER_SCENE +
                         " --uart-out " + out + " " + FWSIM_RENDERER_ELF + " -- --size 48x48 --format p6");
    CHECK(r.status == 0);
    image[no_jit] = slurp(out);
    count[no_jit] = stat_value(r.err, "instructions");
    std::remove(out.c_str());
  }
  CHECK(image[0].size() > 48 * 48 * 3);
  CHECK(image[0] == image[1]);
  CHECK(count[0] == count[1]);
}

TEST_CASE("the renderer's timed report and profile are the same without generated code", "[cli][jit][cycle]") {
  std::string image[2], report[2], profile[2];
  for (int no_jit = 0; no_jit < 2; ++no_jit) {
    const std::string out = temp_path("jit-render.ppm"), cg = temp_path("jit-render.cg"),
                      folded = temp_path("jit-render.folded");
    const Result r = sim(std::string(no_jit ? "--no-jit " : "") + "--stats --cycle-model default --profile-out " +
                         cg + " --folded-out " + folded + " --uart-in " + FWSIM_RENDER_SCENE + " --uart-out " + out +
                         " " + FWSIM_RENDERER_ELF + " -- --size 48x48 --format p6");
    CHECK(r.status == 0);
    image[no_jit] = slurp(out);
    report[no_jit] = stable_stats(r.err);
    profile[no_jit] = slurp(cg) + slurp(folded);
    if (!no_jit) CHECK(std::regex_search(r.err, std::regex("\njit: [1-9][0-9]* blocks translated\n")));
    for (const std::string& path : {out, cg, folded}) std::remove(path.c_str());
  }
  CHECK(image[0].size() > 48 * 48 * 3);
  CHECK(image[0] == image[1]);
  CHECK(report[0].find("top functions:") != std::string::npos);  // the per-function table
  CHECK(report[0] == report[1]);
  CHECK(profile[0] == profile[1]);
}
#endif
