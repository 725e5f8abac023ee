// The C extension: every RV32C encoding expands to the 32-bit instruction the
// specification says it stands for (compared with that instruction encoded
// independently), reserved encodings are illegal, and compressed code runs
// like its 32-bit expansion in the interpreter and in generated code, with
// one retired instruction per compressed instruction.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "commit_trace.hpp"
#include "compressed.hpp"
#include "disassembler.hpp"
#include "machine.hpp"
#include "rv_encoder.hpp"

using namespace rv;
using fwsim::DecodedInsn;
using fwsim::Op;
using fwsim::StopCause;

namespace {

// --- A compressed-instruction encoder, written from the specification's
// layouts (the inverse direction of compressed.cpp's expansion).
constexpr uint32_t b(uint32_t v, unsigned from, unsigned to) { return ((v >> from) & 1u) << to; }
constexpr uint32_t bits(uint32_t v, unsigned hi, unsigned lo, unsigned to) {
  return ((v >> lo) & ((1u << (hi - lo + 1)) - 1)) << to;
}
constexpr uint16_t h16(uint32_t v) { return static_cast<uint16_t>(v); }
constexpr uint32_t p3(uint32_t reg) { return reg - 8; }  // x8..x15 -> 0..7

constexpr uint16_t ci(uint32_t f3, int32_t imm, uint32_t rd, uint32_t op) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return h16(f3 << 13 | b(u, 5, 12) | rd << 7 | bits(u, 4, 0, 2) | op);
}
constexpr uint16_t c_addi(uint32_t rd, int32_t imm) { return ci(0, imm, rd, 1); }
constexpr uint16_t c_li(uint32_t rd, int32_t imm) { return ci(2, imm, rd, 1); }
constexpr uint16_t c_lui(uint32_t rd, int32_t imm6) { return ci(3, imm6, rd, 1); }
constexpr uint16_t c_addi16sp(int32_t imm) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return h16(3u << 13 | b(u, 9, 12) | 2u << 7 | b(u, 4, 6) | b(u, 6, 5) | bits(u, 8, 7, 3) | b(u, 5, 2) | 1);
}
constexpr uint16_t c_addi4spn(uint32_t rd, uint32_t uimm) {
  return h16(bits(uimm, 5, 4, 11) | bits(uimm, 9, 6, 7) | b(uimm, 2, 6) | b(uimm, 3, 5) | p3(rd) << 2);
}
constexpr uint16_t cl(uint32_t f3, uint32_t r2, uint32_t rs1, uint32_t uimm) {
  return h16(f3 << 13 | bits(uimm, 5, 3, 10) | p3(rs1) << 7 | b(uimm, 2, 6) | b(uimm, 6, 5) | p3(r2) << 2);
}
constexpr uint16_t c_lw(uint32_t rd, uint32_t rs1, uint32_t off) { return cl(2, rd, rs1, off); }
constexpr uint16_t c_flw(uint32_t rd, uint32_t rs1, uint32_t off) { return cl(3, rd, rs1, off); }
constexpr uint16_t c_sw(uint32_t rs2, uint32_t rs1, uint32_t off) { return cl(6, rs2, rs1, off); }
constexpr uint16_t c_fsw(uint32_t rs2, uint32_t rs1, uint32_t off) { return cl(7, rs2, rs1, off); }
constexpr uint16_t cj(uint32_t f3, int32_t off) {
  const uint32_t u = static_cast<uint32_t>(off);
  return h16(f3 << 13 | b(u, 11, 12) | b(u, 4, 11) | bits(u, 9, 8, 9) | b(u, 10, 8) | b(u, 6, 7) | b(u, 7, 6) |
             bits(u, 3, 1, 3) | b(u, 5, 2) | 1);
}
constexpr uint16_t c_j(int32_t off) { return cj(5, off); }
constexpr uint16_t c_jal(int32_t off) { return cj(1, off); }
constexpr uint16_t cb(uint32_t f3, uint32_t rs1, int32_t off) {
  const uint32_t u = static_cast<uint32_t>(off);
  return h16(f3 << 13 | b(u, 8, 12) | bits(u, 4, 3, 10) | p3(rs1) << 7 | bits(u, 7, 6, 5) | bits(u, 2, 1, 3) |
             b(u, 5, 2) | 1);
}
constexpr uint16_t c_beqz(uint32_t rs1, int32_t off) { return cb(6, rs1, off); }
constexpr uint16_t c_bnez(uint32_t rs1, int32_t off) { return cb(7, rs1, off); }
constexpr uint16_t c_shift(uint32_t f2, uint32_t rd, uint32_t sh) {
  return h16(4u << 13 | b(sh, 5, 12) | f2 << 10 | p3(rd) << 7 | bits(sh, 4, 0, 2) | 1);
}
constexpr uint16_t c_srli(uint32_t rd, uint32_t sh) { return c_shift(0, rd, sh); }
constexpr uint16_t c_srai(uint32_t rd, uint32_t sh) { return c_shift(1, rd, sh); }
constexpr uint16_t c_andi(uint32_t rd, int32_t imm) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return h16(4u << 13 | b(u, 5, 12) | 2u << 10 | p3(rd) << 7 | bits(u, 4, 0, 2) | 1);
}
constexpr uint16_t c_alu(uint32_t f, uint32_t rd, uint32_t rs2) {
  return h16(4u << 13 | 3u << 10 | p3(rd) << 7 | f << 5 | p3(rs2) << 2 | 1);
}
constexpr uint16_t c_slli(uint32_t rd, uint32_t sh) { return h16(b(sh, 5, 12) | rd << 7 | bits(sh, 4, 0, 2) | 2); }
constexpr uint16_t c_lwsp(uint32_t rd, uint32_t uimm) {
  return h16(2u << 13 | b(uimm, 5, 12) | rd << 7 | bits(uimm, 4, 2, 4) | bits(uimm, 7, 6, 2) | 2);
}
constexpr uint16_t c_flwsp(uint32_t rd, uint32_t uimm) { return h16(c_lwsp(rd, uimm) | 1u << 13); }
constexpr uint16_t c_swsp(uint32_t rs2, uint32_t uimm) {
  return h16(6u << 13 | bits(uimm, 5, 2, 9) | bits(uimm, 7, 6, 7) | rs2 << 2 | 2);
}
constexpr uint16_t c_fswsp(uint32_t rs2, uint32_t uimm) { return h16(c_swsp(rs2, uimm) | 1u << 13); }
constexpr uint16_t c_jr(uint32_t rs1) { return h16(4u << 13 | rs1 << 7 | 2); }
constexpr uint16_t c_mv(uint32_t rd, uint32_t rs2) { return h16(4u << 13 | rd << 7 | rs2 << 2 | 2); }
constexpr uint16_t c_jalr(uint32_t rs1) { return h16(4u << 13 | 1u << 12 | rs1 << 7 | 2); }
constexpr uint16_t c_add(uint32_t rd, uint32_t rs2) { return h16(4u << 13 | 1u << 12 | rd << 7 | rs2 << 2 | 2); }
constexpr uint16_t c_ebreak() { return 0x9002; }

// Same meaning: the operation and the operand fields its format uses.
bool same(const DecodedInsn& c, const DecodedInsn& w) {
  if (c.op != w.op || c.length != 2 || w.length != 4) return false;
  switch (fwsim::op_info(w.op).format) {
    case fwsim::Format::R: return c.rd == w.rd && c.rs1 == w.rs1 && c.rs2 == w.rs2;
    case fwsim::Format::I: case fwsim::Format::Shift: case fwsim::Format::Load: case fwsim::Format::Jalr:
    case fwsim::Format::FLoad:
      return c.rd == w.rd && c.rs1 == w.rs1 && c.imm == w.imm;
    case fwsim::Format::Store: case fwsim::Format::FStore: case fwsim::Format::Branch:
      return c.rs1 == w.rs1 && c.rs2 == w.rs2 && c.imm == w.imm;
    case fwsim::Format::U: case fwsim::Format::J: return c.rd == w.rd && c.imm == w.imm;
    default: return true;
  }
}

void expands_to(uint16_t half, uint32_t word) {
  INFO("compressed 0x" << std::hex << half << " vs 0x" << word);
  const DecodedInsn c = fwsim::decode_compressed(half), w = fwsim::decode(word);
  REQUIRE(w.op != Op::ILLEGAL);
  CHECK(same(c, w));
  // The disassembler shows a compressed instruction as its expansion.
  CHECK(fwsim::disassemble(half, 0x100) == fwsim::disassemble(word, 0x100));
}

void illegal(uint16_t half) {
  INFO("compressed 0x" << std::hex << half);
  CHECK(fwsim::decode_compressed(half).op == Op::ILLEGAL);
}

}  // namespace

TEST_CASE("compressed: quadrant 0 expands to addi/lw/sw/flw/fsw", "[isa][rvc]") {
  expands_to(c_addi4spn(8, 4), addi(8, 2, 4));
  expands_to(c_addi4spn(15, 1020), addi(15, 2, 1020));  // largest nzuimm
  expands_to(c_addi4spn(9, 0x208), addi(9, 2, 0x208));
  for (uint32_t off : {0u, 4u, 64u, 124u}) {
    expands_to(c_lw(8, 15, off), lw(8, 15, static_cast<int32_t>(off)));
    expands_to(c_sw(13, 9, off), sw(13, 9, static_cast<int32_t>(off)));
    expands_to(c_flw(10, 11, off), flw(10, 11, static_cast<int32_t>(off)));
    expands_to(c_fsw(12, 14, off), fsw(12, 14, static_cast<int32_t>(off)));
  }
}

TEST_CASE("compressed: quadrant 1 expands with sign-extended immediates", "[isa][rvc]") {
  expands_to(c_addi(5, -32), addi(5, 5, -32));
  expands_to(c_addi(31, 31), addi(31, 31, 31));
  expands_to(c_li(10, -1), addi(10, 0, -1));
  expands_to(c_li(1, 17), addi(1, 0, 17));
  // c.addi16sp: nzimm in multiples of 16, -512..496.
  expands_to(c_addi16sp(-512), addi(2, 2, -512));
  expands_to(c_addi16sp(496), addi(2, 2, 496));
  expands_to(c_addi16sp(16), addi(2, 2, 16));
  expands_to(c_addi16sp(-16), addi(2, 2, -16));
  expands_to(c_addi16sp(0x150), addi(2, 2, 0x150));
  // c.lui: nzimm[17:12] sign-extended into the upper immediate.
  expands_to(c_lui(10, 1), lui(10, 1));
  expands_to(c_lui(10, 31), lui(10, 31));
  expands_to(c_lui(3, -1), lui(3, 0xfffff));
  expands_to(c_lui(31, -32), lui(31, 0xfffe0));
  expands_to(c_srli(8, 1), srli(8, 8, 1));
  expands_to(c_srli(15, 31), srli(15, 15, 31));
  expands_to(c_srai(9, 31), srai(9, 9, 31));
  expands_to(c_andi(10, -32), i_type(-32, 10, 7, 10, 0x13));
  expands_to(c_andi(11, 31), i_type(31, 11, 7, 11, 0x13));
  expands_to(c_alu(0, 8, 15), sub(8, 8, 15));
  expands_to(c_alu(1, 9, 14), r_type(0, 14, 9, 4, 9, 0x33));   // xor
  expands_to(c_alu(2, 10, 13), r_type(0, 13, 10, 6, 10, 0x33));  // or
  expands_to(c_alu(3, 11, 12), r_type(0, 12, 11, 7, 11, 0x33));  // and
  // Jumps and branches: the extreme offsets.
  for (int32_t off : {-2048, -2, 2, 2046, 0x2aa, -0x556}) {
    expands_to(c_j(off), jal(0, off));
    expands_to(c_jal(off), jal(1, off));
  }
  for (int32_t off : {-256, -2, 0, 2, 254, 0xaa, -0x56}) {
    expands_to(c_beqz(8, off), beq(8, 0, off));
    expands_to(c_bnez(15, off), bne(15, 0, off));
  }
}

TEST_CASE("compressed: quadrant 2 expands to slli/lwsp/swsp/jr/jalr/mv/add/ebreak", "[isa][rvc]") {
  expands_to(c_slli(1, 1), slli(1, 1, 1));
  expands_to(c_slli(31, 31), slli(31, 31, 31));
  for (uint32_t off : {0u, 4u, 0x80u, 252u}) {
    expands_to(c_lwsp(1, off), lw(1, 2, static_cast<int32_t>(off)));
    expands_to(c_flwsp(0, off), flw(0, 2, static_cast<int32_t>(off)));  // f0 is allowed
    expands_to(c_swsp(31, off), sw(31, 2, static_cast<int32_t>(off)));
    expands_to(c_fswsp(7, off), fsw(7, 2, static_cast<int32_t>(off)));
  }
  expands_to(c_jr(1), jalr(0, 1, 0));
  expands_to(c_jr(31), jalr(0, 31, 0));
  expands_to(c_jalr(5), jalr(1, 5, 0));
  expands_to(c_mv(10, 11), add(10, 0, 11));
  expands_to(c_add(10, 11), add(10, 10, 11));
  expands_to(c_ebreak(), ebreak());
}

TEST_CASE("compressed: hints expand to instructions without effect", "[isa][rvc]") {
  expands_to(0x0001, addi(0, 0, 0));  // c.nop
  expands_to(c_addi(0, 5), addi(0, 0, 5));
  expands_to(c_addi(7, 0), addi(7, 7, 0));
  expands_to(c_li(0, 3), addi(0, 0, 3));
  expands_to(c_lui(0, 1), lui(0, 1));
  expands_to(c_mv(0, 5), add(0, 0, 5));
  expands_to(c_add(0, 5), add(0, 0, 5));
  expands_to(c_slli(0, 3), slli(0, 0, 3));
  expands_to(c_slli(9, 0), slli(9, 9, 0));
  expands_to(c_srli(9, 0), srli(9, 9, 0));
  expands_to(c_srai(9, 0), srai(9, 9, 0));
}

TEST_CASE("compressed: reserved, RV64-only and D encodings are illegal", "[isa][rvc]") {
  illegal(0x0000);               // the all-zero parcel
  illegal(c_addi4spn(9, 0));     // nzuimm = 0 with rd' != 0
  illegal(c_addi16sp(0));        // nzimm = 0
  illegal(c_lui(5, 0));          // nzimm = 0
  illegal(c_lwsp(0, 4));         // rd = 0
  illegal(c_jr(0));              // rs1 = 0
  illegal(c_srli(8, 32));        // shamt[5] = 1 on RV32
  illegal(c_srai(8, 33));
  illegal(c_slli(5, 32));
  illegal(h16(4u << 13));        // quadrant 0, funct3 = 4 (reserved)
  illegal(h16(1u << 13 | 0x40));  // c.fld
  illegal(h16(5u << 13 | 0x40));  // c.fsd
  illegal(h16(1u << 13 | 1u << 7 | 2));  // c.fldsp
  illegal(h16(5u << 13 | 2));    // c.fsdsp
  illegal(h16(c_alu(0, 8, 9) | 1u << 12));  // c.subw (RV64)
  illegal(h16(c_alu(1, 8, 9) | 1u << 12));  // c.addw (RV64)
  illegal(h16(c_alu(2, 8, 9) | 1u << 12));  // reserved
  illegal(h16(c_alu(3, 8, 9) | 1u << 12));  // reserved
}

namespace {

// A machine with the C extension and code laid out parcel by parcel.
struct CSim {
  fwsim::Machine m{1u << 20};
  std::vector<uint8_t> code;
  explicit CSim(bool c = true) {
    fwsim::IsaSpec isa;
    isa.c = c;
    m.set_isa(isa);
    m.hart().pc = fwsim::kRamBase;
  }
  uint32_t here() const { return fwsim::kRamBase + static_cast<uint32_t>(code.size()); }
  CSim& c(uint16_t h) {
    code.push_back(static_cast<uint8_t>(h));
    code.push_back(static_cast<uint8_t>(h >> 8));
    return *this;
  }
  CSim& w(uint32_t word) {
    for (int i = 0; i < 4; ++i) code.push_back(static_cast<uint8_t>(word >> (8 * i)));
    return *this;
  }
  fwsim::StopInfo run(uint64_t limit = 1'000'000) {
    std::memcpy(m.bus().ram(), code.data(), code.size());
    return m.run(limit);
  }
  uint32_t& x(unsigned i) { return m.hart().x[i]; }
};

}  // namespace

TEST_CASE("compressed: mixed code counts one instruction each and steps pc by 2 or 4", "[isa][rvc]") {
  CSim s;
  s.c(c_li(10, 5)).w(addi(11, 10, 1)).c(c_addi(10, -1)).c(c_mv(12, 11)).w(lui(13, 0x12345)).c(c_addi(13, 1));
  const uint32_t end = s.here();
  s.c(c_ebreak());
  const fwsim::StopInfo st = s.run();
  REQUIRE(st.cause == StopCause::Ebreak);
  CHECK(st.pc == end);
  CHECK(s.m.hart().instret == 6);
  CHECK(s.x(10) == 4);
  CHECK(s.x(11) == 6);
  CHECK(s.x(12) == 6);
  CHECK(s.x(13) == 0x12345001u);
}

TEST_CASE("compressed: c.jal and c.jalr link pc + 2, 32-bit jumps at halfwords link pc + 4", "[isa][rvc]") {
  CSim s;
  const uint32_t base = s.here();
  s.c(c_jal(8));                 // 0: -> 8, ra = 2
  s.c(c_li(11, 1));              // 2: returned here
  s.w(jal(0, 12));               // 4: -> 16
  s.c(c_li(12, 7));              // 8: subroutine
  s.c(c_mv(5, 1));               // 10: x5 = ra
  s.c(c_jr(1));                  // 12: back to 2
  s.c(0x0001);                   // 14: c.nop (skipped)
  s.w(auipc(6, 0));              // 16: x6 = 16
  s.c(c_addi(6, 12));            // 20: x6 = 28
  s.c(c_jalr(6));                // 22: -> 28, ra = 24
  s.c(c_ebreak());               // 24: not reached
  s.c(0x0001);                   // 26
  s.w(jalr(7, 1, 0));            // 28: -> 24 via ra, x7 = 32
  const fwsim::StopInfo st = s.run();
  REQUIRE(st.cause == StopCause::Ebreak);
  CHECK(st.pc == base + 24);
  CHECK(s.x(5) == base + 2);
  CHECK(s.x(1) == base + 24);
  CHECK(s.x(7) == base + 32);
  CHECK(s.x(11) == 1);
  CHECK(s.x(12) == 7);
  CHECK(s.m.hart().instret == 10);
}

TEST_CASE("compressed: loops of c.bnez/c.beqz count exactly, with and without generated code", "[isa][rvc][jit]") {
  for (bool jit : {false, true}) {
    CSim s;
    s.m.set_jit(jit);
    s.c(c_li(8, 0));                       // 0
    s.w(addi(9, 0, 300));                  // 2
    const uint32_t loop = s.here();
    s.c(c_addi(8, 3));                     // 6
    s.w(addi(9, 9, -1));                   // 8: 32-bit at a halfword
    s.c(c_beqz(9, 6));                     // 12: -> 18 when done
    s.c(c_j(static_cast<int32_t>(loop - s.here())));  // 14
    s.c(0x0001);                           // 16 (not reached)
    s.c(c_ebreak());                       // 18
    const fwsim::StopInfo st = s.run();
    INFO("jit " << jit);
    REQUIRE(st.cause == StopCause::Ebreak);
    CHECK(s.x(8) == 900);
    CHECK(s.m.hart().instret == 2 + 300 * 4 - 1);
    if (jit) CHECK(s.m.jit_blocks() > 0);
  }
}

TEST_CASE("compressed: illegal compressed encodings trap at their pc", "[isa][rvc]") {
  for (uint16_t bad : {uint16_t{0x0000}, c_addi16sp(0), c_lwsp(0, 8), c_jr(0), c_slli(3, 32)}) {
    CSim s;
    s.c(c_li(10, 1));
    const uint32_t at = s.here();
    s.c(bad).c(c_ebreak());
    const fwsim::StopInfo st = s.run();
    INFO("0x" << std::hex << bad);
    CHECK(st.cause == StopCause::IllegalInstruction);
    CHECK(st.pc == at);
    CHECK(s.m.hart().instret == 1);
  }
}

TEST_CASE("compressed: without C in the ISA a compressed instruction is outside it", "[isa][rvc]") {
  CSim s(false);
  s.c(c_li(10, 1)).c(0x0001).c(c_ebreak()).c(0x0001);
  const fwsim::StopInfo st = s.run();
  CHECK(st.cause == StopCause::OutsideIsa);
  REQUIRE(st.detail != nullptr);
  CHECK(std::string(st.detail) == "the C extension");
}

TEST_CASE("compressed: a 32-bit instruction running off the end of code memory faults", "[isa][rvc]") {
  CSim s;
  const uint32_t last = fwsim::kRamBase + (1u << 20) - 2;
  s.m.hart().pc = last;
  s.m.bus().ram()[(1u << 20) - 2] = 0x13;  // low half of an addi
  s.m.bus().ram()[(1u << 20) - 1] = 0x00;
  const fwsim::StopInfo st = s.m.run(100);
  CHECK(st.cause == StopCause::FetchFault);
  CHECK(st.pc == last);
}

TEST_CASE("compressed: the commit log shows the 16-bit instruction", "[isa][rvc]") {
  char* buf = nullptr;
  size_t len = 0;
  std::FILE* out = open_memstream(&buf, &len);
  fwsim::HartState h{};
  h.x[10] = 5;
  fwsim::write_commit_trace(out, 0x80000002u, c_li(10, 5), h);
  fwsim::write_spike_commit(out, 0x80000002u, c_li(10, 5), h);
  std::fclose(out);
  const std::string text(buf, len);
  std::free(buf);
  CHECK(text.find("80000002:     4515  addi a0, zero, 5") != std::string::npos);
  CHECK(text.find("core   0: 3 0x80000002 (0x4515) x10 0x00000005") != std::string::npos);
}

namespace {

// The 32-bit word of a decoded instruction (the ops compressed ones expand to).
uint32_t encode32(const DecodedInsn& d) {
  switch (d.op) {
    case Op::ADDI: return addi(d.rd, d.rs1, d.imm);
    case Op::ANDI: return i_type(d.imm, d.rs1, 7, d.rd, 0x13);
    case Op::SLLI: return slli(d.rd, d.rs1, static_cast<uint32_t>(d.imm));
    case Op::SRLI: return srli(d.rd, d.rs1, static_cast<uint32_t>(d.imm));
    case Op::SRAI: return srai(d.rd, d.rs1, static_cast<uint32_t>(d.imm));
    case Op::LUI: return lui(d.rd, static_cast<uint32_t>(d.imm) >> 12);
    case Op::ADD: return add(d.rd, d.rs1, d.rs2);
    case Op::SUB: return sub(d.rd, d.rs1, d.rs2);
    case Op::XOR: return r_type(0, d.rs2, d.rs1, 4, d.rd, 0x33);
    case Op::OR: return r_type(0, d.rs2, d.rs1, 6, d.rd, 0x33);
    case Op::AND: return r_type(0, d.rs2, d.rs1, 7, d.rd, 0x33);
    case Op::LW: return lw(d.rd, d.rs1, d.imm);
    case Op::SW: return sw(d.rs2, d.rs1, d.imm);
    case Op::FLW: return flw(d.rd, d.rs1, d.imm);
    case Op::FSW: return fsw(d.rs2, d.rs1, d.imm);
    default: FAIL("no 32-bit form for op " << static_cast<int>(d.op)); return 0;
  }
}

// x2 (sp) and x8 point at the data; x31 counts the loop. Random compressed
// instructions that keep them (c.addi16sp comes in pairs that cancel).
bool keeps_bases(const DecodedInsn& d) {
  const fwsim::Format f = fwsim::op_info(d.op).format;
  const bool writes_x = f == fwsim::Format::R || f == fwsim::Format::I || f == fwsim::Format::Shift ||
                        f == fwsim::Format::U || f == fwsim::Format::Load;
  return !writes_x || (d.rd != 2 && d.rd != 8 && d.rd != 31);
}

}  // namespace

TEST_CASE("compressed: random compressed code runs like its 32-bit expansion, interpreted and generated", "[isa][rvc][jit]") {
  constexpr uint32_t kData = 0x40000;
  uint64_t blocks = 0;
  for (uint32_t seed = 1; seed <= 150; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    // The body: compressed instructions (ALU, loads and stores through x2
    // and x8), and forward c.beqz/c.bnez over the next instruction.
    struct Item {
      uint16_t half;
      bool skip_branch;
    };
    std::vector<Item> body;
    while (body.size() < 30) {
      const uint32_t r = rng();
      if (r % 9 == 0 && !body.empty()) {
        const uint32_t reg = 9 + rng() % 7;
        body.push_back({rng() % 2 ? c_beqz(reg, 4) : c_bnez(reg, 4), true});
        continue;
      }
      if (r % 13 == 0) {
        if (!body.empty() && body.back().skip_branch) body.push_back({0x0001, false});  // not into a pair
        const int32_t k = static_cast<int32_t>(rng() % 8 + 1) * 16;
        body.push_back({c_addi16sp(k), false});
        body.push_back({c_lwsp(9 + rng() % 7, (rng() % 64) * 4), false});
        body.push_back({c_addi16sp(-k), false});
        continue;
      }
      const uint16_t h = static_cast<uint16_t>(rng());
      if ((h & 3) == 3) continue;
      const DecodedInsn d = fwsim::decode_compressed(h);
      const fwsim::InsnClass cls = fwsim::op_info(d.op).cls;
      if (d.op == Op::ILLEGAL || cls == fwsim::InsnClass::Jump || cls == fwsim::InsnClass::Branch ||
          cls == fwsim::InsnClass::System || !keeps_bases(d))
        continue;
      // Memory only through x2 and x8 (the data); other bases are random.
      const fwsim::Format f = fwsim::op_info(d.op).format;
      const bool mem = f == fwsim::Format::Load || f == fwsim::Format::Store || f == fwsim::Format::FLoad ||
                       f == fwsim::Format::FStore;
      if (mem && d.rs1 != 2 && d.rs1 != 8) continue;
      body.push_back({h, false});
    }
    // A skip branch jumps over one compressed instruction: never over the
    // loop's 32-bit decrement.
    if (body.back().skip_branch) body.push_back({0x0001, false});
    // Variant 0: compressed; variant 1: each expanded to its 32-bit form.
    fwsim::HartState results[2][2];
    std::vector<uint8_t> data_after[2][2];
    uint64_t counts[2][2];
    for (int variant = 0; variant < 2; ++variant) {
      for (int jit = 0; jit < 2; ++jit) {
        CSim s;
        s.m.set_jit(jit != 0);
        const uint32_t loop = s.here();
        for (size_t i = 0; i < body.size(); ++i) {
          const Item& it = body[i];
          if (variant == 0) {
            s.c(it.half);
            continue;
          }
          const DecodedInsn d = fwsim::decode_compressed(it.half);
          if (it.skip_branch) {
            s.w(d.op == Op::BEQ ? beq(d.rs1, 0, 8) : bne(d.rs1, 0, 8));  // over one 4-byte instruction
          } else {
            s.w(encode32(d));
          }
        }
        s.w(addi(31, 31, -1));
        s.w(bne(31, 0, static_cast<int32_t>(loop) - static_cast<int32_t>(s.here())));
        s.c(c_ebreak());
        std::mt19937 init(seed * 7919u);
        for (unsigned r = 1; r < 32; ++r) s.x(r) = init();
        for (unsigned r = 0; r < 32; ++r) s.m.hart().f[r] = init();
        s.x(2) = fwsim::kRamBase + kData;
        s.x(8) = fwsim::kRamBase + kData + 0x400;
        s.x(31) = 40;
        for (uint32_t i = 0; i < 0x1000; ++i) s.m.bus().ram()[kData - 0x800 + i] = static_cast<uint8_t>(init());
        const fwsim::StopInfo st = s.run();
        REQUIRE(st.cause == StopCause::Ebreak);
        if (jit) blocks += s.m.jit_blocks();
        results[variant][jit] = s.m.hart();
        counts[variant][jit] = s.m.hart().instret;
        data_after[variant][jit].assign(s.m.bus().ram() + kData - 0x800, s.m.bus().ram() + kData + 0x800);
      }
    }
    for (int variant = 0; variant < 2; ++variant)
      for (int jit = 0; jit < 2; ++jit) {
        INFO("variant " << variant << " jit " << jit);
        CHECK(counts[variant][jit] == counts[0][0]);
        CHECK(std::memcmp(results[variant][jit].x, results[0][0].x, sizeof results[0][0].x) == 0);
        CHECK(std::memcmp(results[variant][jit].f, results[0][0].f, sizeof results[0][0].f) == 0);
        CHECK(data_after[variant][jit] == data_after[0][0]);
      }
  }
  CHECK(blocks >= 300);  // the loops did run as generated code
}
