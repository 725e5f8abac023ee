#include "compressed.hpp"

namespace fwsim {
namespace {

// Bit `from` of `h` moved to bit `to`.
constexpr uint32_t bit(uint32_t h, unsigned from, unsigned to) { return ((h >> from) & 1u) << to; }
// Bits [hi..lo] of `h`.
constexpr uint32_t field(uint32_t h, unsigned hi, unsigned lo) { return (h >> lo) & ((1u << (hi - lo + 1)) - 1); }
constexpr int32_t sign_extend(uint32_t v, unsigned bits) {
  return static_cast<int32_t>(v << (32 - bits)) >> (32 - bits);
}
// The three-bit register fields name x8..x15 (f8..f15).
constexpr uint8_t reg3(uint32_t h, unsigned lo) { return static_cast<uint8_t>(8 + field(h, lo + 2, lo)); }

DecodedInsn make(Op op, unsigned rd, unsigned rs1, unsigned rs2, int32_t imm) {
  DecodedInsn d;
  d.op = op;
  d.rd = static_cast<uint8_t>(rd);
  d.rs1 = static_cast<uint8_t>(rs1);
  d.rs2 = static_cast<uint8_t>(rs2);
  d.imm = imm;
  d.rm = 0;
  d.length = 2;
  return d;
}

DecodedInsn illegal() {
  DecodedInsn d;
  d.length = 2;
  return d;
}

// Offsets of the scaled loads and stores (zero-extended, in bytes).
uint32_t lw_offset(uint32_t h) { return field(h, 12, 10) << 3 | bit(h, 6, 2) | bit(h, 5, 6); }
uint32_t lwsp_offset(uint32_t h) { return bit(h, 12, 5) | field(h, 6, 4) << 2 | field(h, 3, 2) << 6; }
uint32_t swsp_offset(uint32_t h) { return field(h, 12, 9) << 2 | field(h, 8, 7) << 6; }
// The six-bit signed immediate of c.addi, c.li, c.andi: imm[5] = bit 12, imm[4:0] = bits 6..2.
int32_t imm6(uint32_t h) { return sign_extend(bit(h, 12, 5) | field(h, 6, 2), 6); }
// c.j / c.jal: offset[11|4|9:8|10|6|7|3:1|5] in bits 12..2.
int32_t jump_offset(uint32_t h) {
  const uint32_t v = bit(h, 12, 11) | bit(h, 11, 4) | field(h, 10, 9) << 8 | bit(h, 8, 10) | bit(h, 7, 6) |
                     bit(h, 6, 7) | field(h, 5, 3) << 1 | bit(h, 2, 5);
  return sign_extend(v, 12);
}
// c.beqz / c.bnez: offset[8|4:3] in bits 12..10, offset[7:6|2:1|5] in bits 6..2.
int32_t branch_offset(uint32_t h) {
  const uint32_t v = bit(h, 12, 8) | field(h, 11, 10) << 3 | field(h, 6, 5) << 6 | field(h, 4, 3) << 1 | bit(h, 2, 5);
  return sign_extend(v, 9);
}

DecodedInsn quadrant0(uint32_t h) {
  const unsigned rdp = reg3(h, 2), rs1p = reg3(h, 7);
  switch (field(h, 15, 13)) {
    case 0: {  // c.addi4spn: addi rd', x2, nzuimm
      const uint32_t nzuimm = field(h, 12, 11) << 4 | field(h, 10, 7) << 6 | bit(h, 6, 2) | bit(h, 5, 3);
      if (nzuimm == 0) return illegal();  // includes the all-zero instruction
      return make(Op::ADDI, rdp, 2, 0, static_cast<int32_t>(nzuimm));
    }
    case 2: return make(Op::LW, rdp, rs1p, 0, static_cast<int32_t>(lw_offset(h)));
    case 3: return make(Op::FLW, rdp, rs1p, 0, static_cast<int32_t>(lw_offset(h)));
    case 6: return make(Op::SW, 0, rs1p, rdp, static_cast<int32_t>(lw_offset(h)));
    case 7: return make(Op::FSW, 0, rs1p, rdp, static_cast<int32_t>(lw_offset(h)));
    default: return illegal();  // c.fld, c.fsd (D), and the reserved funct3 = 4
  }
}

DecodedInsn quadrant1(uint32_t h) {
  const unsigned rd = field(h, 11, 7), rdp = reg3(h, 7), rs2p = reg3(h, 2);
  switch (field(h, 15, 13)) {
    case 0: return make(Op::ADDI, rd, rd, 0, imm6(h));  // c.addi (c.nop; hints with rd = 0 or imm = 0)
    case 1: return make(Op::JAL, 1, 0, 0, jump_offset(h));  // c.jal (RV32 only)
    case 2: return make(Op::ADDI, rd, 0, 0, imm6(h));  // c.li (hint with rd = 0)
    case 3: {
      if (rd == 2) {  // c.addi16sp: nzimm[9|4|6|8:7|5] in bits 12, 6..2
        const uint32_t v = bit(h, 12, 9) | bit(h, 6, 4) | bit(h, 5, 6) | field(h, 4, 3) << 7 | bit(h, 2, 5);
        if (v == 0) return illegal();
        return make(Op::ADDI, 2, 2, 0, sign_extend(v, 10));
      }
      // c.lui: nzimm[17|16:12] (hint with rd = 0)
      const uint32_t v = bit(h, 12, 17) | field(h, 6, 2) << 12;
      if (v == 0) return illegal();
      return make(Op::LUI, rd, 0, 0, sign_extend(v, 18));
    }
    case 4: {
      const uint32_t shamt = bit(h, 12, 5) | field(h, 6, 2);
      switch (field(h, 11, 10)) {
        case 0:  // c.srli; shamt[5] = 1 is RV64 only; shamt = 0 a hint
          if (shamt & 32) return illegal();
          return make(Op::SRLI, rdp, rdp, 0, static_cast<int32_t>(shamt));
        case 1:
          if (shamt & 32) return illegal();
          return make(Op::SRAI, rdp, rdp, 0, static_cast<int32_t>(shamt));
        case 2: return make(Op::ANDI, rdp, rdp, 0, imm6(h));
        default: {
          if (bit(h, 12, 0)) return illegal();  // c.subw / c.addw (RV64) and reserved
          static constexpr Op kOps[4] = {Op::SUB, Op::XOR, Op::OR, Op::AND};
          return make(kOps[field(h, 6, 5)], rdp, rdp, rs2p, 0);
        }
      }
    }
    case 5: return make(Op::JAL, 0, 0, 0, jump_offset(h));  // c.j
    case 6: return make(Op::BEQ, 0, rdp, 0, branch_offset(h));  // c.beqz
    default: return make(Op::BNE, 0, rdp, 0, branch_offset(h));  // c.bnez
  }
}

DecodedInsn quadrant2(uint32_t h) {
  const unsigned rd = field(h, 11, 7), rs2 = field(h, 6, 2);
  switch (field(h, 15, 13)) {
    case 0: {  // c.slli; shamt[5] = 1 is RV64 only; rd = 0 or shamt = 0 a hint
      const uint32_t shamt = bit(h, 12, 5) | field(h, 6, 2);
      if (shamt & 32) return illegal();
      return make(Op::SLLI, rd, rd, 0, static_cast<int32_t>(shamt));
    }
    case 2:  // c.lwsp; rd = 0 is reserved
      if (rd == 0) return illegal();
      return make(Op::LW, rd, 2, 0, static_cast<int32_t>(lwsp_offset(h)));
    case 3: return make(Op::FLW, rd, 2, 0, static_cast<int32_t>(lwsp_offset(h)));  // c.flwsp
    case 4:
      if (!bit(h, 12, 0)) {
        if (rs2 == 0) {  // c.jr; rs1 = 0 is reserved
          if (rd == 0) return illegal();
          return make(Op::JALR, 0, rd, 0, 0);
        }
        return make(Op::ADD, rd, 0, rs2, 0);  // c.mv (hint with rd = 0)
      }
      if (rs2 == 0) {
        if (rd == 0) {  // c.ebreak
          DecodedInsn d = make(Op::EBREAK, 0, 0, 0, 0);
          return d;
        }
        return make(Op::JALR, 1, rd, 0, 0);  // c.jalr
      }
      return make(Op::ADD, rd, rd, rs2, 0);  // c.add (hint with rd = 0)
    case 6: return make(Op::SW, 0, 2, rs2, static_cast<int32_t>(swsp_offset(h)));  // c.swsp
    case 7: return make(Op::FSW, 0, 2, rs2, static_cast<int32_t>(swsp_offset(h)));  // c.fswsp
    default: return illegal();  // c.fldsp, c.fsdsp (D)
  }
}

}  // namespace

DecodedInsn decode_compressed(uint16_t half) {
  const uint32_t h = half;
  switch (h & 3) {
    case 0: return quadrant0(h);
    case 1: return quadrant1(h);
    case 2: return quadrant2(h);
    default: return illegal();  // not a compressed instruction
  }
}

}  // namespace fwsim
