// RV32I + M semantics through the interpreter: edge cases of division,
// shifts, loads, x0, control flow and counters.
#include <catch2/catch.hpp>

#include "sim_harness.hpp"

using namespace rv;
using fwsim::StopCause;

TEST_CASE("DIV/REM follow the RISC-V rules for zero divisors and overflow", "[isa]") {
  Sim s({div(10, 1, 2), divu(11, 1, 2), rem(12, 1, 2), remu(13, 1, 2),
         div(14, 3, 4), rem(15, 3, 4), div(16, 5, 6), rem(17, 5, 6), divu(18, 3, 6), remu(19, 3, 6)});
  s.x(1) = 1234;
  s.x(2) = 0;
  s.x(3) = 0x80000000u;
  s.x(4) = 0xffffffffu;
  s.x(5) = static_cast<uint32_t>(-7);
  s.x(6) = 2;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 0xffffffffu);
  CHECK(s.x(11) == 0xffffffffu);
  CHECK(s.x(12) == 1234u);
  CHECK(s.x(13) == 1234u);
  CHECK(s.x(14) == 0x80000000u);
  CHECK(s.x(15) == 0u);
  CHECK(s.x(16) == static_cast<uint32_t>(-3));
  CHECK(s.x(17) == static_cast<uint32_t>(-1));
  CHECK(s.x(18) == 0x40000000u);
  CHECK(s.x(19) == 0u);
}

TEST_CASE("MUL high halves for all signedness combinations", "[isa]") {
  Sim s({mul(10, 1, 2), mulh(11, 1, 2), mulhu(12, 1, 2), mulhsu(13, 1, 2), mulh(14, 3, 3)});
  s.x(1) = 0xffffffffu;
  s.x(2) = 0xffffffffu;
  s.x(3) = 0x80000000u;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 1u);
  CHECK(s.x(11) == 0u);            // -1 * -1
  CHECK(s.x(12) == 0xfffffffeu);   // (2^32-1)^2
  CHECK(s.x(13) == 0xffffffffu);   // -1 * (2^32-1)
  CHECK(s.x(14) == 0x40000000u);   // INT_MIN^2 = 2^62
}

TEST_CASE("shifts use the low five bits and sign-extend arithmetic shifts", "[isa]") {
  Sim s({slli(10, 1, 31), srli(11, 2, 31), srai(12, 2, 31), sll(13, 1, 3), srl(14, 2, 3), sra(15, 2, 3),
         sra(16, 2, 4)});
  s.x(1) = 1;
  s.x(2) = 0x80000000u;
  s.x(3) = 33;  // shifts by 1
  s.x(4) = 31;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 0x80000000u);
  CHECK(s.x(11) == 1u);
  CHECK(s.x(12) == 0xffffffffu);
  CHECK(s.x(13) == 2u);
  CHECK(s.x(14) == 0x40000000u);
  CHECK(s.x(15) == 0xc0000000u);
  CHECK(s.x(16) == 0xffffffffu);
}

TEST_CASE("loads sign- or zero-extend, stores write only their width", "[isa]") {
  Sim s({sw(2, 1, 0), lb(10, 1, 0), lbu(11, 1, 0), lh(12, 1, 2), lhu(13, 1, 2), lw(14, 1, 0),
         sb(0, 1, 0), sh(0, 1, 2), lw(15, 1, 0), lb(16, 1, 1)});
  s.x(1) = fwsim::kRamBase + 0x1000;
  s.x(2) = 0x8001ff80u;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 0xffffff80u);
  CHECK(s.x(11) == 0x80u);
  CHECK(s.x(12) == 0xffff8001u);
  CHECK(s.x(13) == 0x8001u);
  CHECK(s.x(14) == 0x8001ff80u);
  CHECK(s.x(15) == 0x0000ff00u);
  CHECK(s.x(16) == 0xffffffffu);
}

TEST_CASE("writes to x0 are discarded, including loads and links", "[isa]") {
  Sim s({addi(0, 0, 5), lui(0, 0x12345), lw(0, 1, 0), jal(0, 4), add(10, 0, 0), mul(0, 2, 2), addi(11, 0, 0)});
  s.x(1) = fwsim::kRamBase;
  s.x(2) = 7;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(0) == 0u);
  CHECK(s.x(10) == 0u);
  CHECK(s.x(11) == 0u);
}

TEST_CASE("branches, jal and jalr link and jump", "[isa]") {
  // 0: blt x1,x2,+8 (taken)  4: addi x10,x0,1 (skipped)  8: jal x1,+8  12: ebreak(never)
  // 16: auipc x12,0  20: jalr x13, x5, 0 -> x5 = base+28  24: addi x11,x0,9(skipped)  28: lui x14,1
  Sim s({blt(1, 2, 8), addi(10, 0, 1), jal(1, 8), ebreak(), auipc(12, 0), jalr(13, 5, 0), addi(11, 0, 9), lui(14, 1)});
  s.x(1) = static_cast<uint32_t>(-5);
  s.x(2) = 3;
  s.x(5) = fwsim::kRamBase + 28;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 0u);
  CHECK(s.x(1) == fwsim::kRamBase + 12);
  CHECK(s.x(12) == fwsim::kRamBase + 16);
  CHECK(s.x(13) == fwsim::kRamBase + 24);
  CHECK(s.x(11) == 0u);
  CHECK(s.x(14) == 0x1000u);
}

TEST_CASE("a counted loop retires exactly the expected instructions", "[isa][counters]") {
  // x1 = 1000; loop: addi x1,x1,-1; bne x1,x0,-4; then read instret
  Sim s({addi(1, 0, 1000), addi(1, 1, -1), bne(1, 0, -4), csrrs(10, kInstret, 0), csrrs(11, kInstretH, 0),
         csrrs(12, kCycle, 0)});
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 1 + 2 * 1000);
  CHECK(s.x(11) == 0u);
  CHECK(s.x(12) == s.x(10) + 2);  // no cycle model: one cycle per instruction
  CHECK(s.m.hart().instret == 1 + 2000 + 3);
}

TEST_CASE("faults stop the run with cause, pc and address", "[isa][faults]") {
  SECTION("misaligned load") {
    Sim s({addi(2, 0, 1), lw(3, 1, 2)});
    s.x(1) = fwsim::kRamBase;
    auto st = s.run();
    CHECK(st.cause == StopCause::MisalignedLoad);
    CHECK(st.pc == fwsim::kRamBase + 4);
    CHECK(st.addr == fwsim::kRamBase + 2);
  }
  SECTION("store outside RAM and devices") {
    Sim s({sw(0, 1, 0)});
    s.x(1) = 0x20000000;
    auto st = s.run();
    CHECK(st.cause == StopCause::StoreFault);
    CHECK(st.addr == 0x20000000u);
  }
  SECTION("illegal instruction and ecall") {
    Sim s({0xffffffffu});
    CHECK(s.run().cause == StopCause::IllegalInstruction);
    Sim e({ecall()});
    CHECK(e.run().cause == StopCause::Ecall);
  }
  SECTION("jump outside RAM") {
    Sim s({jalr(0, 1, 0)});
    s.x(1) = 0x1000;
    auto st = s.run();
    CHECK(st.cause == StopCause::FetchFault);
    CHECK(st.addr == 0x1000u);
  }
  SECTION("misaligned jump target") {
    Sim s({jal(0, 6)});
    CHECK(s.run().cause == StopCause::MisalignedFetch);
  }
  SECTION("write to a read-only counter is illegal") {
    Sim s({csrrw(0, kCycle, 1)});
    CHECK(s.run().cause == StopCause::IllegalInstruction);
  }
  SECTION("instruction limit") {
    Sim s({jal(0, 0)});
    auto st = s.run(5000);
    CHECK(st.cause == StopCause::InstructionLimit);
    CHECK(s.m.hart().instret == 5001);
  }
}

TEST_CASE("counter high halves carry past 32 bits", "[isa][counters]") {
  Sim s({csrrs(10, kInstretH, 0), csrrs(11, kInstret, 0), csrrs(12, 0xc80, 0), csrrs(13, 0xc81, 0)});
  s.m.hart().instret = 0x1fffffffeull;  // two instructions before the low half wraps
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(10) == 1u);
  CHECK(s.x(11) == 0xffffffffu);
  CHECK(s.x(12) == 2u);  // cycleh: plain mode counts one cycle per instruction
  CHECK(s.x(13) == 0u);  // timeh: 10 MHz timebase of a 100 MHz clock
}
