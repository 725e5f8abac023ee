// End-to-end tests of --board: each UART kind echoes bytes back, each halt
// kind ends the run with the firmware's status, instructions outside the
// board's ISA trap with a message naming them, a ROM holds the code.
#include <catch2/catch.hpp>

#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
std::string board(const std::string& name) { return std::string(FWSIM_BOARD_DIR) + "/" + name + ".board"; }
std::string program(const std::string& name) { return std::string(FWSIM_BOARD_ELF_DIR) + "/" + name + ".elf"; }
Result on_board(const std::string& b, const std::string& elf, const std::string& input = "") {
  return sim("--board " + board(b) + " " + program(elf), input);
}
const std::string kLine = "round trip \x01\xff\n";  // 14 bytes: status 14
bool r_ok(const Result& r) { return r.status == 14 && r.err.empty(); }
}  // namespace

TEST_CASE("every UART kind round-trips bytes and every halt kind gives the status", "[cli][board]") {
  struct Case {
    const char* board;
    const char* elf;
  };
  // ns16550 + finisher, litex + store (code in ROM), sifive + ecall,
  // generic byte-wide + loop, generic 32-bit + finisher elsewhere.
  const Case cases[] = {{"qemu-virt", "echo-ns16550"},
                        {"litex-rom", "echo-litex"},
                        {"sifive", "echo-sifive"},
                        {"generic-byte", "echo-generic-byte"},
                        {"generic-word", "echo-generic-word"}};
  for (const Case& c : cases) {
    INFO(c.board);
    const Result r = on_board(c.board, c.elf, kLine + "not read");
    CHECK(r.status == 14);
    CHECK(r.out == kLine);
    CHECK(r.err.empty());
  }
}

TEST_CASE("a UART that must be enabled drops bytes until the firmware writes the board's uart_init", "[cli][board]") {
  const std::string neorv32 = std::string("--board ") + FWSIM_NEORV32_BOARD + " ";
  const Result on = sim(neorv32 + program("echo-neorv32"), kLine + "not read");
  CHECK(r_ok(on));
  CHECK(on.out == kLine);
  // Built from the board file without its uart_init line: nothing comes
  // back, the input is lost, and the run ends stalled on the UART.
  const Result off = sim(neorv32 + program("echo-neorv32-no-init"), kLine);
  CHECK(off.out.empty());
  CHECK(off.status == 6);
  CHECK_THAT(off.err, Catch::Contains("bytes dropped while the UART was off"));
}

TEST_CASE("a board's UART and halt device are only where the board puts them", "[cli][board]") {
  // The litex program on the reference board: its code lies outside RAM.
  const Result wrong_map = on_board("qemu-virt", "echo-litex");
  CHECK(wrong_map.status == 3);
  // The sifive program's ecall is a trap on a board that halts otherwise.
  const Result no_ecall = on_board("generic-word", "echo-sifive", "x\n");
  CHECK(no_ecall.status == 4);
  // Without halt = loop a jump to itself runs until the instruction limit.
  const Result spins = sim("--board " + board("generic-word") + " --max-instructions 100000 " +
                           program("echo-generic-byte"), "x\n");
  CHECK(spins.status == 3);  // linked at 0x2000: outside that board's RAM
}

TEST_CASE("the ROM is read-only to the firmware", "[cli][board]") {
  // isa-probe-1 links at 0x80000000; on the litex board that is no memory.
  const Result r = on_board("litex-rom", "isa-probe-1");
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::Contains("outside RAM 0x40000000..0x40010000 and ROM"));
}

TEST_CASE("mul traps on an rv32i board and runs on rv32im", "[cli][board][isa]") {
  const Result rv32i = on_board("rv32i", "isa-probe-1");
  CHECK(rv32i.status == 4);
  CHECK_THAT(rv32i.err, Catch::Contains("instruction outside the board's ISA at pc 0x80000008"));
  CHECK_THAT(rv32i.err, Catch::Contains("mul a0, a0, a1: needs the M extension"));
  const Result rv32im = on_board("rv32im", "isa-probe-1");
  CHECK(rv32im.status == 42);
  CHECK(rv32im.err.empty());
}

TEST_CASE("each missing extension traps with its name", "[cli][board][isa]") {
  struct Case {
    const char* board;
    const char* elf;
    int status;
    const char* message;
  };
  const Case cases[] = {
      {"rv32e", "isa-probe-2", 4, "addi a6, a1, 0: needs registers x16..x31"},
      {"rv32i", "isa-probe-2", 13, ""},
      {"no-zicsr", "isa-probe-3", 4, "csrrs t0, 0x340, zero: needs the Zicsr extension"},
      {"rv32i", "isa-probe-3", 20, ""},
      {"rv32im", "isa-probe-4", 4, "compressed instruction 0x0511: needs the C extension ["},
      {"rv32imfc", "isa-probe-4", 10, ""},  // c.addi runs
      {"rv32im", "isa-probe-5", 4, "fcvt.s.w ft0, a0, dyn: needs the F extension"},
      {"qemu-virt", "isa-probe-5", 12, ""},
      {"rv32im", "isa-probe-6", 4, "needs the Zifencei extension"},
      {"qemu-virt", "isa-probe-6", 13, ""},
  };
  for (const Case& c : cases) {
    INFO(c.board << " " << c.elf);
    const Result r = on_board(c.board, c.elf);
    CHECK(r.status == c.status);
    if (*c.message) CHECK_THAT(r.err, Catch::Contains(c.message));
    else CHECK(r.err.empty());
  }
}

TEST_CASE("the reference board file runs the test firmware exactly like no board", "[cli][board]") {
  const Result plain = sim("--stats " + kElf, "");
  const Result boarded = sim("--stats --board " + board("qemu-virt") + " " + kElf, "");
  CHECK(plain.status == boarded.status);
  CHECK(plain.out == boarded.out);
  CHECK(stat_value(plain.err, "instructions") == stat_value(boarded.err, "instructions"));
  CHECK(stat_value(plain.err, "instructions") != ~uint64_t{0});
}

TEST_CASE("a bad board file is named with its line", "[cli][board]") {
  const std::string path = temp_path("bad.board");
  spit(path, "name = x\nisa = rv32q\n");
  const Result r = sim("--board " + path + " " + kElf);
  CHECK(r.status == 2);
  CHECK_THAT(r.err, Catch::Contains(path + ":2: isa must be one of"));
  const Result both = sim("--board " + board("rv32i") + " --machine " + path + " " + kElf);
  CHECK(both.status == 2);
  CHECK_THAT(both.err, Catch::Contains("--board and --machine cannot be combined"));
  std::remove(path.c_str());
}
