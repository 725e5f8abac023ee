// Board description parser (board_file.hpp): the reference board equals the
// built-in map, every key is read, bad files are named with their line.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include "board_file.hpp"

using namespace fwsim;

namespace {
const std::string kReference =
    "name = qemu-virt\n"
    "mirrors = QEMU virt machine (qemu-system-riscv32 -M virt)\n"
    "isa = rv32imf\n"
    "reset = 0x80000000\n"
    "ram_base = 0x80000000\n"
    "ram_size = 0x400000\n"
    "uart = ns16550\n"
    "uart_base = 0x10000000\n"
    "halt = finisher:0x100000\n";

std::string error_of(const std::string& text) {
  try {
    parse_board_file(text, "b.board");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("the reference board file is the built-in map", "[board]") {
  const Board b = parse_board_file(kReference, "ref.board");
  const MemoryMap def;
  CHECK(b.name == "qemu-virt");
  CHECK(b.reset == 0x80000000u);
  CHECK(b.map.ram_base == def.ram_base);
  CHECK(b.map.ram_size == def.ram_size);
  CHECK(b.map.uart_base == def.uart_base);
  CHECK(b.map.finisher_base == def.finisher_base);
  CHECK(b.map.rom_size == 0);
  CHECK(b.map.halt == HaltKind::Finisher);
  CHECK(b.map.uart.kind == UartKind::Ns16550);
  CHECK(isa_name(b.isa) == "rv32imf");
  CHECK(!b.uart_divisor);
}

TEST_CASE("board keys: ISA names, generic UART, halts, ROM", "[board]") {
  for (const char* isa : {"rv32i", "rv32im", "rv32imc", "rv32imf", "rv32imfc", "rv32e", "rv32em", "rv32emc"}) {
    IsaSpec s;
    REQUIRE(parse_isa(isa, s));
    CHECK(isa_name(s) == isa);
  }
  const Board b = parse_board_file(
      "name = g  # comment\n\nisa = rv32em\nzicsr = no\nreset = 0x100\nrom_base = 0\nrom_size = 0x1000\n"
      "ram_base = 0x10000000\nram_size = 65536\nuart = generic\nuart_base = 0x20000000\nuart_data = 4\n"
      "uart_status = 8\nuart_tx_ready = 1\nuart_rx_ready = 2\nuart_width = 4\nuart_divisor = 27\nhalt = store:0x30000000\n",
      "g.board");
  CHECK(isa_name(b.isa) == "rv32em without Zicsr");
  CHECK(b.map.rom_size == 0x1000);
  CHECK(b.map.ram_size == 65536);
  CHECK(b.map.uart.kind == UartKind::Generic);
  CHECK(b.map.uart.data == 4);
  CHECK(b.map.uart.status == 8);
  CHECK(b.map.halt == HaltKind::Store);
  CHECK(b.map.finisher_base == 0x30000000u);
  CHECK(b.uart_divisor == 27u);
  std::string text = kReference;
  text.replace(text.find("finisher:0x100000"), 17, "loop");
  CHECK(parse_board_file(text, "l.board").map.halt == HaltKind::Loop);
  text.replace(text.find("halt = loop"), 11, "halt = ecall");
  CHECK(parse_board_file(text, "e.board").map.halt == HaltKind::Ecall);
}

TEST_CASE("bad board files name the file and line", "[board]") {
  CHECK(error_of(kReference + "colour = red\n") == "b.board:10: unknown key 'colour'");
  CHECK(error_of(kReference + "isa = rv32i\n") == "b.board:10: 'isa' given twice (first on line 3)");
  CHECK(error_of("name = x\nisa = rv64gc\n") ==
        "b.board:2: isa must be one of rv32i, rv32im, rv32imc, rv32imf, rv32imfc, rv32e, rv32em, rv32emc, got 'rv64gc'");
  CHECK(error_of("name = x\n") == "b.board:1: missing required key 'isa'");
  CHECK(error_of(kReference + "uart_width = 4\n") == "b.board:10: 'uart_width' applies only to uart = generic");
  CHECK(error_of(kReference + "zicsr = maybe\n") == "b.board:10: zicsr must be yes or no, got 'maybe'");
  CHECK(error_of("ram_size = 12q\n") == "b.board:1: ram_size needs a 32-bit number (decimal or 0x hex), got '12q'");
  CHECK(error_of("just words\n") == "b.board:1: expected 'key = value', got 'just words'");
  std::string bad_halt = kReference;
  bad_halt.replace(bad_halt.find("finisher:0x100000"), 17, "reboot");
  CHECK(error_of(bad_halt) == "b.board:9: halt must be finisher:ADDR, ecall, store:ADDR or loop, got 'reboot'");
  std::string overlap = kReference;
  overlap.replace(overlap.find("uart_base = 0x10000000"), 22, "uart_base = 0x80001000");
  CHECK(error_of(overlap).rfind("b.board: RAM 0x80000000..0x80400000 overlaps UART", 0) == 0);
  std::string reset = kReference;
  reset.replace(reset.find("reset = 0x80000000"), 18, "reset = 0x00000000");
  CHECK(error_of(reset) == "b.board:4: reset address must be a word in RAM");
  std::string generic = kReference;
  generic.replace(generic.find("uart = ns16550"), 14, "uart = generic");
  CHECK(error_of(generic) == "b.board:9: uart = generic needs 'uart_data'");
}
