// --no-jit on the command line: the same firmware runs give the same UART
// output, stop messages, exit status and counts with and without generated
// code, and --stats says which ran.
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
  // Timed runs never use it.
  CHECK(sim("--stats --cycle-model default " + kElf).err.find("\njit: 0 blocks translated\n") != std::string::npos);
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
#endif
