// End-to-end tests of the memory-map options (--ram, --uart, --finisher,
// --machine), the boot block's independence from the ELF path's spelling,
// and output paths checked before the run.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
const std::string kRelocated = FWSIM_RELOCATED_ELF;
const std::string kMachineFile = std::string(FWSIM_SOURCE_DIR) + "/test/sim/firmware/relocated.machine";
const std::string kRelocatedOut = "relocated: main at 0x0000";
}  // namespace

TEST_CASE("a program linked at address 0 runs when the map puts RAM there", "[cli][map]") {
  // The board's map has no RAM at 0: the loader refuses the segment.
  Result board = sim(kRelocated);
  CHECK(board.status == 3);
  CHECK_THAT(board.err, Catch::Contains("lies outside RAM 0x80000000..0x80400000"));

  Result r = sim("--ram 0:1M --uart 0x20000000 --finisher 0x30000000 " + kRelocated + " -- a bc");
  CHECK(r.status == 7);
  CHECK(r.out.rfind(kRelocatedOut, 0) == 0);
  CHECK_THAT(r.out, Catch::EndsWith(", pc 0x00000000, args a bc\n"));
  CHECK(r.err.empty());
  // The same map from a machine file.
  Result f = sim("--machine " + kMachineFile + " " + kRelocated + " -- a bc");
  CHECK(f.status == 7);
  CHECK(f.out == r.out);
  // Options override the file: without the UART where the program expects
  // it, its first UART access is a fault at that address.
  Result moved = sim("--machine " + kMachineFile + " --uart 0x40000000 " + kRelocated);
  CHECK(moved.status == 4);
  CHECK_THAT(moved.err, Catch::Contains("load access fault"));
  CHECK_THAT(moved.err, Catch::Contains("address 0x20000005"));
}

TEST_CASE("the default map is the board's, and the options can restate it", "[cli][map]") {
  Result plain = sim("--stats " + kElf);
  Result stated = sim("--stats --ram 0x80000000:4M --uart 0x10000000 --finisher 0x100000 " + kElf);
  REQUIRE(plain.status == 0);
  CHECK(stated.status == 0);
  CHECK(plain.out == stated.out);
  CHECK(stat_value(plain.err, "instructions") == stat_value(stated.err, "instructions"));
  // The finisher moved away: the board firmware's exit store faults.
  Result r = sim("--finisher 0x200000 " + kElf + " -- exit 0");
  CHECK(r.status == 4);
  CHECK_THAT(r.err, Catch::Contains("store access fault"));
  CHECK_THAT(r.err, Catch::Contains("address 0x00100000"));
}

TEST_CASE("bad memory maps are one-line errors with status 2", "[cli][map][usage]") {
  const std::string bad_file = temp_path("bad.machine");
  spit(bad_file, "ram = 0:1M\nuart = 0x20000000\nflash = 0\n");
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"--ram 0 ", "--ram needs BASE:SIZE"},
      {"--ram 0:1X ", "RAM size needs a number, got '1X'"},
      {"--ram 0x123:1M ", "multiples of 4096"},
      {"--ram 0xfff00000:2M ", "must end below the top of the 32-bit address space"},
      {"--ram 0xfff00000:1M ", "must end below the top of the 32-bit address space"},
      {"--uart 0x80000100 ", "RAM 0x80000000..0x80400000 overlaps UART 0x80000100..0x80000200"},
      {"--finisher 0x10000000 ", "overlaps finisher"},
      {"--uart zzz ", "--uart needs a number, got 'zzz'"},
      {"--machine /nonexistent/m.machine ", "/nonexistent/m.machine: cannot read machine file"},
      {"--machine " + bad_file + " ", bad_file + ":3: unknown key 'flash'"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    Result r = sim(c.args + kElf);
    CHECK(r.status == 2);
    CHECK(r.err.rfind("firmware-sim: error: ", 0) == 0);
    CHECK_THAT(r.err, Catch::Contains(c.message));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  std::remove(bad_file.c_str());
}

TEST_CASE("the instruction count does not depend on how the ELF path is spelled", "[cli][args]") {
  // The firmware's crt0 fills its stack up to sp: before the fix, sp sat
  // just below the argument strings, so a longer path meant a lower sp and
  // fewer fill iterations. Spell one file three ways of different lengths.
  char cwd[4096];
  REQUIRE(::getcwd(cwd, sizeof cwd) != nullptr);
  const std::string absolute = kElf.front() == '/' ? kElf : std::string(cwd) + "/" + kElf;
  const std::string dir = absolute.substr(0, absolute.rfind('/'));
  const std::string name = absolute.substr(absolute.rfind('/') + 1);
  const std::string longer = dir + "/./././././././././././././././" + name;
  const std::string shorter = "$(realpath --relative-to=. " + absolute + ")";
  uint64_t counts[3];
  const std::string spellings[3] = {absolute, longer, shorter};
  for (int i = 0; i < 3; ++i) {
    CAPTURE(spellings[i]);
    Result r = sim("--stats " + spellings[i] + " -- args x yz");
    REQUIRE(r.status == 0);
    CHECK(r.out == "4 args x yz\n");
    counts[i] = stat_value(r.err, "instructions");
  }
  CHECK(counts[0] == counts[1]);
  CHECK(counts[0] == counts[2]);
#ifdef FWSIM_RENDERER_ELF
  // The renderer firmware's crt0 is the one that showed it.
  const std::string fw = FWSIM_RENDERER_ELF;
  const std::string fw_longer = fw.substr(0, fw.rfind('/')) + "/./././././././././." + fw.substr(fw.rfind('/'));
  const std::string run = " --uart-in " + std::string(FWSIM_RENDER_SCENE) + " --uart-out /dev/null ";
  Result a = sim("--stats" + run + fw + " -- --size 8x8");
  Result b = sim("--stats" + run + fw_longer + " -- --size 8x8");
  REQUIRE(a.status == 0);
  REQUIRE(b.status == 0);
  CHECK(stat_value(a.err, "instructions") == stat_value(b.err, "instructions"));
#endif
}

TEST_CASE("output paths are checked before the run", "[cli][usage]") {
  for (const char* opt : {"--profile-out", "--folded-out", "--flame-out"}) {
    CAPTURE(opt);
    // A run that would take long: the error must come first, not after it.
    Result r = sim(std::string(opt) + " /nonexistent/x.out --max-instructions 100000000000 " + kElf + " -- spin");
    CHECK(r.status == 2);
    CHECK(r.err == "firmware-sim: error: /nonexistent/x.out: No such file or directory\n");
    Result dir = sim(std::string(opt) + " /tmp " + kElf);
    CHECK(dir.status == 2);
    CHECK(dir.err == "firmware-sim: error: /tmp: Is a directory\n");
  }
  Result file_as_dir = sim("--profile-out " + kElf + "/x.cg " + kElf);
  CHECK(file_as_dir.status == 2);
  CHECK(file_as_dir.err == "firmware-sim: error: " + kElf + "/x.cg: Not a directory\n");
}

TEST_CASE("help and version exit 0 on stdout", "[cli][usage]") {
  for (const char* opt : {"--help", "-h"}) {
    Result r = sim(opt);
    CHECK(r.status == 0);
    CHECK(r.out.rfind("Usage: firmware-sim", 0) == 0);
    CHECK(r.out.find("--ram BASE:SIZE") != std::string::npos);
    CHECK(r.out.find("--gdb PORT") != std::string::npos);
    CHECK(r.err.empty());
  }
  Result v = sim("--version");
  CHECK(v.status == 0);
  CHECK(std::regex_match(v.out, std::regex("firmware-sim [0-9]+(\\.[0-9]+)*\n")));
}
