// Tiny RV32IMF instruction encoder for the simulator tests: builds machine
// words from mnemonics so each test states its program inline.
#pragma once
#include <cstdint>

namespace rv {

enum Rm : uint32_t { RNE = 0, RTZ = 1, RDN = 2, RUP = 3, RMM = 4, DYN = 7 };

constexpr uint32_t r_type(uint32_t f7, uint32_t rs2, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opc) {
  return f7 << 25 | rs2 << 20 | rs1 << 15 | f3 << 12 | rd << 7 | opc;
}
constexpr uint32_t i_type(int32_t imm, uint32_t rs1, uint32_t f3, uint32_t rd, uint32_t opc) {
  return (static_cast<uint32_t>(imm) & 0xfff) << 20 | rs1 << 15 | f3 << 12 | rd << 7 | opc;
}
constexpr uint32_t s_type(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3, uint32_t opc) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return (u >> 5 & 0x7f) << 25 | rs2 << 20 | rs1 << 15 | f3 << 12 | (u & 0x1f) << 7 | opc;
}
constexpr uint32_t b_type(int32_t imm, uint32_t rs2, uint32_t rs1, uint32_t f3) {
  const uint32_t u = static_cast<uint32_t>(imm);
  return (u >> 12 & 1) << 31 | (u >> 5 & 0x3f) << 25 | rs2 << 20 | rs1 << 15 | f3 << 12 |
         (u >> 1 & 0xf) << 8 | (u >> 11 & 1) << 7 | 0x63;
}

// RV32I
constexpr uint32_t lui(uint32_t rd, uint32_t imm20) { return imm20 << 12 | rd << 7 | 0x37; }
constexpr uint32_t auipc(uint32_t rd, uint32_t imm20) { return imm20 << 12 | rd << 7 | 0x17; }
constexpr uint32_t jal(uint32_t rd, int32_t off) {
  const uint32_t u = static_cast<uint32_t>(off);
  return (u >> 20 & 1) << 31 | (u >> 1 & 0x3ff) << 21 | (u >> 11 & 1) << 20 | (u >> 12 & 0xff) << 12 | rd << 7 | 0x6f;
}
constexpr uint32_t jalr(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 0, rd, 0x67); }
constexpr uint32_t beq(uint32_t a, uint32_t b, int32_t off) { return b_type(off, b, a, 0); }
constexpr uint32_t bne(uint32_t a, uint32_t b, int32_t off) { return b_type(off, b, a, 1); }
constexpr uint32_t blt(uint32_t a, uint32_t b, int32_t off) { return b_type(off, b, a, 4); }
constexpr uint32_t bgeu(uint32_t a, uint32_t b, int32_t off) { return b_type(off, b, a, 7); }
constexpr uint32_t lb(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 0, rd, 0x03); }
constexpr uint32_t lh(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 1, rd, 0x03); }
constexpr uint32_t lw(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 2, rd, 0x03); }
constexpr uint32_t lbu(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 4, rd, 0x03); }
constexpr uint32_t lhu(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 5, rd, 0x03); }
constexpr uint32_t sb(uint32_t rs2, uint32_t rs1, int32_t imm) { return s_type(imm, rs2, rs1, 0, 0x23); }
constexpr uint32_t sh(uint32_t rs2, uint32_t rs1, int32_t imm) { return s_type(imm, rs2, rs1, 1, 0x23); }
constexpr uint32_t sw(uint32_t rs2, uint32_t rs1, int32_t imm) { return s_type(imm, rs2, rs1, 2, 0x23); }
constexpr uint32_t addi(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 0, rd, 0x13); }
constexpr uint32_t slli(uint32_t rd, uint32_t rs1, uint32_t sh) { return i_type(static_cast<int32_t>(sh), rs1, 1, rd, 0x13); }
constexpr uint32_t srli(uint32_t rd, uint32_t rs1, uint32_t sh) { return i_type(static_cast<int32_t>(sh), rs1, 5, rd, 0x13); }
constexpr uint32_t srai(uint32_t rd, uint32_t rs1, uint32_t sh) { return i_type(static_cast<int32_t>(sh | 0x400), rs1, 5, rd, 0x13); }
constexpr uint32_t add(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0, b, a, 0, rd, 0x33); }
constexpr uint32_t sub(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0x20, b, a, 0, rd, 0x33); }
constexpr uint32_t sll(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0, b, a, 1, rd, 0x33); }
constexpr uint32_t slt(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0, b, a, 2, rd, 0x33); }
constexpr uint32_t sltu(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0, b, a, 3, rd, 0x33); }
constexpr uint32_t srl(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0, b, a, 5, rd, 0x33); }
constexpr uint32_t sra(uint32_t rd, uint32_t a, uint32_t b) { return r_type(0x20, b, a, 5, rd, 0x33); }
constexpr uint32_t ebreak() { return 0x00100073; }
constexpr uint32_t ecall() { return 0x00000073; }
constexpr uint32_t fence_i() { return 0x0000100f; }
// M
constexpr uint32_t mul(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 0, rd, 0x33); }
constexpr uint32_t mulh(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 1, rd, 0x33); }
constexpr uint32_t mulhsu(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 2, rd, 0x33); }
constexpr uint32_t mulhu(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 3, rd, 0x33); }
constexpr uint32_t div(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 4, rd, 0x33); }
constexpr uint32_t divu(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 5, rd, 0x33); }
constexpr uint32_t rem(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 6, rd, 0x33); }
constexpr uint32_t remu(uint32_t rd, uint32_t a, uint32_t b) { return r_type(1, b, a, 7, rd, 0x33); }
// Zicsr
constexpr uint32_t csrrw(uint32_t rd, uint32_t csr, uint32_t rs1) { return csr << 20 | rs1 << 15 | 1 << 12 | rd << 7 | 0x73; }
constexpr uint32_t csrrs(uint32_t rd, uint32_t csr, uint32_t rs1) { return csr << 20 | rs1 << 15 | 2 << 12 | rd << 7 | 0x73; }
constexpr uint32_t csrrwi(uint32_t rd, uint32_t csr, uint32_t imm) { return csr << 20 | imm << 15 | 5 << 12 | rd << 7 | 0x73; }
// F
constexpr uint32_t flw(uint32_t rd, uint32_t rs1, int32_t imm) { return i_type(imm, rs1, 2, rd, 0x07); }
constexpr uint32_t fsw(uint32_t rs2, uint32_t rs1, int32_t imm) { return s_type(imm, rs2, rs1, 2, 0x27); }
constexpr uint32_t fp(uint32_t f7, uint32_t rd, uint32_t a, uint32_t b, uint32_t rm) { return r_type(f7, b, a, rm, rd, 0x53); }
constexpr uint32_t fadd(uint32_t rd, uint32_t a, uint32_t b, uint32_t rm = DYN) { return fp(0x00, rd, a, b, rm); }
constexpr uint32_t fsub(uint32_t rd, uint32_t a, uint32_t b, uint32_t rm = DYN) { return fp(0x04, rd, a, b, rm); }
constexpr uint32_t fmul(uint32_t rd, uint32_t a, uint32_t b, uint32_t rm = DYN) { return fp(0x08, rd, a, b, rm); }
constexpr uint32_t fdiv(uint32_t rd, uint32_t a, uint32_t b, uint32_t rm = DYN) { return fp(0x0c, rd, a, b, rm); }
constexpr uint32_t fsqrt(uint32_t rd, uint32_t a, uint32_t rm = DYN) { return fp(0x2c, rd, a, 0, rm); }
constexpr uint32_t fsgnj(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x10, rd, a, b, 0); }
constexpr uint32_t fsgnjn(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x10, rd, a, b, 1); }
constexpr uint32_t fsgnjx(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x10, rd, a, b, 2); }
constexpr uint32_t fmin(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x14, rd, a, b, 0); }
constexpr uint32_t fmax(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x14, rd, a, b, 1); }
constexpr uint32_t fcvt_w_s(uint32_t rd, uint32_t a, uint32_t rm = DYN) { return fp(0x60, rd, a, 0, rm); }
constexpr uint32_t fcvt_wu_s(uint32_t rd, uint32_t a, uint32_t rm = DYN) { return fp(0x60, rd, a, 1, rm); }
constexpr uint32_t fcvt_s_w(uint32_t rd, uint32_t a, uint32_t rm = DYN) { return fp(0x68, rd, a, 0, rm); }
constexpr uint32_t fcvt_s_wu(uint32_t rd, uint32_t a, uint32_t rm = DYN) { return fp(0x68, rd, a, 1, rm); }
constexpr uint32_t fmv_x_w(uint32_t rd, uint32_t a) { return fp(0x70, rd, a, 0, 0); }
constexpr uint32_t fclass(uint32_t rd, uint32_t a) { return fp(0x70, rd, a, 0, 1); }
constexpr uint32_t fmv_w_x(uint32_t rd, uint32_t a) { return fp(0x78, rd, a, 0, 0); }
constexpr uint32_t feq(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x50, rd, a, b, 2); }
constexpr uint32_t flt(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x50, rd, a, b, 1); }
constexpr uint32_t fle(uint32_t rd, uint32_t a, uint32_t b) { return fp(0x50, rd, a, b, 0); }
constexpr uint32_t fused(uint32_t opc, uint32_t rd, uint32_t a, uint32_t b, uint32_t c, uint32_t rm) {
  return c << 27 | b << 20 | a << 15 | rm << 12 | rd << 7 | opc;
}
constexpr uint32_t fmadd(uint32_t rd, uint32_t a, uint32_t b, uint32_t c, uint32_t rm = DYN) { return fused(0x43, rd, a, b, c, rm); }
constexpr uint32_t fmsub(uint32_t rd, uint32_t a, uint32_t b, uint32_t c, uint32_t rm = DYN) { return fused(0x47, rd, a, b, c, rm); }
constexpr uint32_t fnmsub(uint32_t rd, uint32_t a, uint32_t b, uint32_t c, uint32_t rm = DYN) { return fused(0x4b, rd, a, b, c, rm); }
constexpr uint32_t fnmadd(uint32_t rd, uint32_t a, uint32_t b, uint32_t c, uint32_t rm = DYN) { return fused(0x4f, rd, a, b, c, rm); }

constexpr uint32_t kFflags = 0x001, kFrm = 0x002, kFcsr = 0x003, kCycle = 0xc00, kInstret = 0xc02,
                   kInstretH = 0xc82;

}  // namespace rv
