// --load-hex: $readmemh and .coe images of 32-bit words run like the ELF
// they were made from; bad images are FILE:LINE errors.
#include <catch2/catch.hpp>

#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
// isa_probe.S with PROBE=1: li a0, 6; li a1, 7; mul; exit 42 by the finisher.
const char* const kWords[] = {"00600513", "00700593", "02b50533", "01051513", "000032b7",
                              "33328293", "00556533", "001002b7", "00a2a023"};
}  // namespace

TEST_CASE("readmemh and coe images run from the reset address", "[cli][hex]") {
  std::string hex = "// isa probe\n@0\n";
  std::string coe = "; isa probe\nmemory_initialization_radix = 16;\nmemory_initialization_vector =\n";
  for (const char* w : kWords) {
    hex += std::string(w) + " /* word */\n";
    coe += std::string(w) + (std::string(w) == "00a2a023" ? ";\n" : ",\n");
  }
  const std::string hex_path = temp_path("probe.hex"), coe_path = temp_path("probe.coe");
  spit(hex_path, hex);
  spit(coe_path, coe);
  const Result h = sim("--stats --load-hex " + hex_path);
  CHECK(h.status == 42);
  CHECK(stat_value(h.err, "instructions") == 9);
  CHECK(sim("--load-hex " + coe_path).status == 42);
  // On a board the image goes to its reset address, and the ISA applies.
  const std::string board = std::string(FWSIM_BOARD_DIR) + "/";
  CHECK(sim("--board " + board + "rv32im.board --load-hex " + hex_path).status == 42);
  const Result rv32i = sim("--board " + board + "rv32i.board --load-hex " + hex_path);
  CHECK(rv32i.status == 4);
  CHECK_THAT(rv32i.err, Catch::Contains("needs the M extension"));
  // @ADDR moves on in words: a gap of one word before the program.
  spit(hex_path, "@1\n00000013\n");
  const Result gap = sim("--load-hex " + hex_path);
  CHECK(gap.status == 4);  // the word at the reset address is 0: illegal
  std::remove(hex_path.c_str());
  std::remove(coe_path.c_str());
}

TEST_CASE("bad images are one-line errors naming the line", "[cli][hex]") {
  const std::string path = temp_path("bad.hex");
  spit(path, "00000013\n// fine\n0x13\n");
  const Result r = sim("--load-hex " + path);
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::Contains(path + ":3: bad hex word '0x13'"));
  spit(path, "@ffffffff\n00000013\n");
  CHECK_THAT(sim("--load-hex " + path).err, Catch::Contains(":2: word 4294967295 at 0x"));
  const Result both = sim("--load-hex " + path + " " + kElf);
  CHECK(both.status == 2);
  std::remove(path.c_str());
}
