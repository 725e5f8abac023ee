// --commit-log: spike's --log-commits layout, line for line, on a
// hand-written program whose effects are known.
#include <catch2/catch.hpp>

#include <string>

#include "cli_runner.hpp"

using namespace cli;

TEST_CASE("the commit log (--commit-log) has spike's commit-log lines", "[cli][trace]") {
  const std::string log = temp_path("commit.log");
  const Result r = sim("--commit-log " + log + " " + std::string(FWSIM_BOARD_ELF_DIR) + "/isa-probe-1.elf");
  CHECK(r.status == 42);
  CHECK(r.err.empty());
  CHECK(slurp(log) ==
        "core   0: 3 0x80000000 (0x00600513) x10 0x00000006\n"   // li a0, 6
        "core   0: 3 0x80000004 (0x00700593) x11 0x00000007\n"   // li a1, 7
        "core   0: 3 0x80000008 (0x02b50533) x10 0x0000002a\n"   // mul a0, a0, a1
        "core   0: 3 0x8000000c (0x01051513) x10 0x002a0000\n"   // slli a0, a0, 16
        "core   0: 3 0x80000010 (0x000032b7) x5  0x00003000\n"   // lui t0, 3
        "core   0: 3 0x80000014 (0x33328293) x5  0x00003333\n"   // addi t0, t0, 0x333
        "core   0: 3 0x80000018 (0x00556533) x10 0x002a3333\n"   // or a0, a0, t0
        "core   0: 3 0x8000001c (0x001002b7) x5  0x00100000\n"   // lui t0, 0x100
        "core   0: 3 0x80000020 (0x00a2a023) mem 0x00100000 0x002a3333\n");  // sw: the finisher
  std::remove(log.c_str());
}

TEST_CASE("the commit log lists byte stores and FP writes at their width", "[cli][trace]") {
  const std::string log = temp_path("commit2.log");
  const Result r = sim("--commit-log " + log + " --board " + std::string(FWSIM_BOARD_DIR) + "/qemu-virt.board " +
                       std::string(FWSIM_BOARD_ELF_DIR) + "/echo-ns16550.elf", "A\n");
  CHECK(r.status == 2);
  CHECK(r.out == "A\n");
  const std::string text = slurp(log);
  CHECK(text.find(" (0x00a40023) mem 0x10000000 0x41\n") != std::string::npos);  // sb a0, 0(s0)
  const Result fp = sim("--commit-log " + log + " " + std::string(FWSIM_BOARD_ELF_DIR) + "/isa-probe-5.elf");
  CHECK(fp.status == 12);
  CHECK(slurp(log).find(") f0  0x41400000\n") != std::string::npos);  // fadd.s ft0: 12.0f
  std::remove(log.c_str());
  const Result both = sim("--trace --commit-log " + log + " " + kElf);
  CHECK(both.status == 2);
}
