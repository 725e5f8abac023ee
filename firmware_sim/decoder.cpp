#include "decoder.hpp"

namespace fwsim {
namespace {

int32_t imm_i(uint32_t w) { return static_cast<int32_t>(w) >> 20; }
int32_t imm_s(uint32_t w) {
  return (static_cast<int32_t>(w) >> 25 << 5) | static_cast<int32_t>((w >> 7) & 0x1f);
}
int32_t imm_b(uint32_t w) {
  uint32_t v = ((w >> 31) & 1) << 12 | ((w >> 7) & 1) << 11 | ((w >> 25) & 0x3f) << 5 |
               ((w >> 8) & 0xf) << 1;
  return static_cast<int32_t>(v << 19) >> 19;
}
int32_t imm_j(uint32_t w) {
  uint32_t v = ((w >> 31) & 1) << 20 | ((w >> 12) & 0xff) << 12 | ((w >> 20) & 1) << 11 |
               ((w >> 21) & 0x3ff) << 1;
  return static_cast<int32_t>(v << 11) >> 11;
}

Op decode_op_imm(uint32_t f3, uint32_t f7) {
  switch (f3) {
    case 0: return Op::ADDI;
    case 2: return Op::SLTI;
    case 3: return Op::SLTIU;
    case 4: return Op::XORI;
    case 6: return Op::ORI;
    case 7: return Op::ANDI;
    case 1: return f7 == 0 ? Op::SLLI : Op::ILLEGAL;
    case 5: return f7 == 0 ? Op::SRLI : f7 == 0x20 ? Op::SRAI : Op::ILLEGAL;
  }
  return Op::ILLEGAL;
}

Op decode_op(uint32_t f3, uint32_t f7) {
  static constexpr Op base[8] = {Op::ADD, Op::SLL, Op::SLT, Op::SLTU,
                                 Op::XOR, Op::SRL, Op::OR,  Op::AND};
  static constexpr Op muldiv[8] = {Op::MUL, Op::MULH, Op::MULHSU, Op::MULHU,
                                   Op::DIV, Op::DIVU, Op::REM,    Op::REMU};
  if (f7 == 0) return base[f3];
  if (f7 == 1) return muldiv[f3];
  if (f7 == 0x20 && f3 == 0) return Op::SUB;
  if (f7 == 0x20 && f3 == 5) return Op::SRA;
  return Op::ILLEGAL;
}

Op decode_fp(uint32_t w, uint32_t f3) {
  uint32_t f7 = w >> 25, rs2 = (w >> 20) & 0x1f;
  switch (f7) {
    case 0x00: return Op::FADD_S;
    case 0x04: return Op::FSUB_S;
    case 0x08: return Op::FMUL_S;
    case 0x0c: return Op::FDIV_S;
    case 0x2c: return rs2 == 0 ? Op::FSQRT_S : Op::ILLEGAL;
    case 0x10: return f3 == 0 ? Op::FSGNJ_S : f3 == 1 ? Op::FSGNJN_S : f3 == 2 ? Op::FSGNJX_S : Op::ILLEGAL;
    case 0x14: return f3 == 0 ? Op::FMIN_S : f3 == 1 ? Op::FMAX_S : Op::ILLEGAL;
    case 0x60: return rs2 == 0 ? Op::FCVT_W_S : rs2 == 1 ? Op::FCVT_WU_S : Op::ILLEGAL;
    case 0x70:
      if (rs2 != 0) return Op::ILLEGAL;
      return f3 == 0 ? Op::FMV_X_W : f3 == 1 ? Op::FCLASS_S : Op::ILLEGAL;
    case 0x50: return f3 == 2 ? Op::FEQ_S : f3 == 1 ? Op::FLT_S : f3 == 0 ? Op::FLE_S : Op::ILLEGAL;
    case 0x68: return rs2 == 0 ? Op::FCVT_S_W : rs2 == 1 ? Op::FCVT_S_WU : Op::ILLEGAL;
    case 0x78: return (rs2 == 0 && f3 == 0) ? Op::FMV_W_X : Op::ILLEGAL;
  }
  return Op::ILLEGAL;
}

}  // namespace

DecodedInsn decode(uint32_t w) {
  DecodedInsn d;
  d.rd = (w >> 7) & 0x1f;
  d.rs1 = (w >> 15) & 0x1f;
  d.rs2 = (w >> 20) & 0x1f;
  d.rs3 = w >> 27;
  d.rm = (w >> 12) & 7;
  const uint32_t f3 = (w >> 12) & 7, f7 = w >> 25;
  if ((w & 3) != 3) return d;  // compressed: decode_compressed
  switch ((w >> 2) & 0x1f) {
    case 0x0d: d.op = Op::LUI; d.imm = static_cast<int32_t>(w & 0xfffff000u); break;
    case 0x05: d.op = Op::AUIPC; d.imm = static_cast<int32_t>(w & 0xfffff000u); break;
    case 0x1b: d.op = Op::JAL; d.imm = imm_j(w); break;
    case 0x19: if (f3 == 0) { d.op = Op::JALR; d.imm = imm_i(w); } break;
    case 0x18: {
      static constexpr Op br[8] = {Op::BEQ, Op::BNE, Op::ILLEGAL, Op::ILLEGAL,
                                   Op::BLT, Op::BGE, Op::BLTU,    Op::BGEU};
      d.op = br[f3];
      d.imm = imm_b(w);
      break;
    }
    case 0x00: {
      static constexpr Op ld[8] = {Op::LB,  Op::LH,  Op::LW,      Op::ILLEGAL,
                                   Op::LBU, Op::LHU, Op::ILLEGAL, Op::ILLEGAL};
      d.op = ld[f3];
      d.imm = imm_i(w);
      break;
    }
    case 0x08: {
      static constexpr Op st[4] = {Op::SB, Op::SH, Op::SW, Op::ILLEGAL};
      d.op = f3 < 4 ? st[f3] : Op::ILLEGAL;
      d.imm = imm_s(w);
      break;
    }
    case 0x04:
      d.op = decode_op_imm(f3, f7);
      d.imm = (f3 == 1 || f3 == 5) ? static_cast<int32_t>(d.rs2) : imm_i(w);
      break;
    case 0x0c: d.op = decode_op(f3, f7); break;
    case 0x03:
      // fence is a no-op here (one hart, no caches to sync); fence.i drops
      // the pre-decoded code so code written before it runs as written.
      if (f3 == 0) d.op = Op::FENCE;
      if (f3 == 1) d.op = Op::FENCE_I;
      break;
    case 0x1c:
      if (f3 == 0) {
        if (w == 0x00000073) d.op = Op::ECALL;
        else if (w == 0x00100073) d.op = Op::EBREAK;
      } else if (f3 != 4) {
        static constexpr Op cs[8] = {Op::ILLEGAL, Op::CSRRW,  Op::CSRRS,  Op::CSRRC,
                                     Op::ILLEGAL, Op::CSRRWI, Op::CSRRSI, Op::CSRRCI};
        d.op = cs[f3];
        d.imm = static_cast<int32_t>(w >> 20);
      }
      break;
    case 0x01: if (f3 == 2) { d.op = Op::FLW; d.imm = imm_i(w); } break;
    case 0x09: if (f3 == 2) { d.op = Op::FSW; d.imm = imm_s(w); } break;
    case 0x10: case 0x11: case 0x12: case 0x13: {
      if (((w >> 25) & 3) != 0) break;  // fmt must be S
      static constexpr Op fused[4] = {Op::FMADD_S, Op::FMSUB_S, Op::FNMSUB_S, Op::FNMADD_S};
      d.op = fused[((w >> 2) & 0x1f) - 0x10];
      break;
    }
    case 0x14: d.op = decode_fp(w, f3); break;
  }
  return d;
}

}  // namespace fwsim
