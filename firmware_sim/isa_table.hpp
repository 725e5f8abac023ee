// The instruction table: one row per operation the simulator knows.
// Every other part (decoder, interpreter dispatch table, disassembler, cycle
// model classes, instruction-mix statistics) is generated from these rows so
// they cannot drift apart.
#pragma once
#include <cstddef>
#include <cstdint>

namespace fwsim {

// Timing / statistics class of an instruction.
enum class InsnClass : uint8_t {
  Alu, Mul, Div, Load, Store, Branch, Jump, FpAdd, FpMul, FpDiv, FpSqrt,
  FpCvt, FpCmp, FpMove, FpFused, FpLoad, FpStore, Csr, System, Internal,
  Count
};

// Operand layout, used by the disassembler and the load-use hazard check.
enum class Format : uint8_t {
  None, R, I, Shift, Load, Store, Branch, U, J, Jalr, Csr, CsrI,
  FR,      // fd, fs1, fs2, rm
  FR4,     // fd, fs1, fs2, fs3, rm
  FUnary,  // fd, fs1, rm
  FSgn,    // fd, fs1, fs2
  FCmp,    // rd, fs1, fs2
  FCvtXF,  // rd, fs1, rm
  FCvtFX,  // fd, rs1, rm
  FMvXF,   // rd, fs1
  FMvFX,   // fd, rs1
  FLoad, FStore
};

// X(enumerator, mnemonic, class, format)
#define FWSIM_OPS(X)                                   \
  X(UNDECODED, "<undecoded>", Internal, None)          \
  X(ILLEGAL, "<illegal>", Internal, None)              \
  X(FETCH_FAULT, "<fetch fault>", Internal, None)      \
  X(SLOW_CTI, "<far jump>", Internal, None)            \
  X(BREAKPOINT, "<breakpoint>", Internal, None)        \
  X(OUTSIDE_ISA, "<outside the board's ISA>", Internal, None) \
  X(SELF_JUMP, "<jump to itself>", Internal, None)     \
  X(SKIP, "<second half of an instruction>", Internal, None) \
  X(LUI, "lui", Alu, U)                                \
  X(AUIPC, "auipc", Alu, U)                            \
  X(JAL, "jal", Jump, J)                               \
  X(JALR, "jalr", Jump, Jalr)                          \
  X(BEQ, "beq", Branch, Branch)                        \
  X(BNE, "bne", Branch, Branch)                        \
  X(BLT, "blt", Branch, Branch)                        \
  X(BGE, "bge", Branch, Branch)                        \
  X(BLTU, "bltu", Branch, Branch)                      \
  X(BGEU, "bgeu", Branch, Branch)                      \
  X(LB, "lb", Load, Load)                              \
  X(LH, "lh", Load, Load)                              \
  X(LW, "lw", Load, Load)                              \
  X(LBU, "lbu", Load, Load)                            \
  X(LHU, "lhu", Load, Load)                            \
  X(SB, "sb", Store, Store)                            \
  X(SH, "sh", Store, Store)                            \
  X(SW, "sw", Store, Store)                            \
  X(ADDI, "addi", Alu, I)                              \
  X(SLTI, "slti", Alu, I)                              \
  X(SLTIU, "sltiu", Alu, I)                            \
  X(XORI, "xori", Alu, I)                              \
  X(ORI, "ori", Alu, I)                                \
  X(ANDI, "andi", Alu, I)                              \
  X(SLLI, "slli", Alu, Shift)                          \
  X(SRLI, "srli", Alu, Shift)                          \
  X(SRAI, "srai", Alu, Shift)                          \
  X(ADD, "add", Alu, R)                                \
  X(SUB, "sub", Alu, R)                                \
  X(SLL, "sll", Alu, R)                                \
  X(SLT, "slt", Alu, R)                                \
  X(SLTU, "sltu", Alu, R)                              \
  X(XOR, "xor", Alu, R)                                \
  X(SRL, "srl", Alu, R)                                \
  X(SRA, "sra", Alu, R)                                \
  X(OR, "or", Alu, R)                                  \
  X(AND, "and", Alu, R)                                \
  X(FENCE, "fence", System, None)                      \
  X(FENCE_I, "fence.i", System, None)                  \
  X(ECALL, "ecall", System, None)                      \
  X(EBREAK, "ebreak", System, None)                    \
  X(MUL, "mul", Mul, R)                                \
  X(MULH, "mulh", Mul, R)                              \
  X(MULHSU, "mulhsu", Mul, R)                          \
  X(MULHU, "mulhu", Mul, R)                            \
  X(DIV, "div", Div, R)                                \
  X(DIVU, "divu", Div, R)                              \
  X(REM, "rem", Div, R)                                \
  X(REMU, "remu", Div, R)                              \
  X(CSRRW, "csrrw", Csr, Csr)                          \
  X(CSRRS, "csrrs", Csr, Csr)                          \
  X(CSRRC, "csrrc", Csr, Csr)                          \
  X(CSRRWI, "csrrwi", Csr, CsrI)                       \
  X(CSRRSI, "csrrsi", Csr, CsrI)                       \
  X(CSRRCI, "csrrci", Csr, CsrI)                       \
  X(FLW, "flw", FpLoad, FLoad)                         \
  X(FSW, "fsw", FpStore, FStore)                       \
  X(FMADD_S, "fmadd.s", FpFused, FR4)                  \
  X(FMSUB_S, "fmsub.s", FpFused, FR4)                  \
  X(FNMSUB_S, "fnmsub.s", FpFused, FR4)                \
  X(FNMADD_S, "fnmadd.s", FpFused, FR4)                \
  X(FADD_S, "fadd.s", FpAdd, FR)                       \
  X(FSUB_S, "fsub.s", FpAdd, FR)                       \
  X(FMUL_S, "fmul.s", FpMul, FR)                       \
  X(FDIV_S, "fdiv.s", FpDiv, FR)                       \
  X(FSQRT_S, "fsqrt.s", FpSqrt, FUnary)                \
  X(FSGNJ_S, "fsgnj.s", FpMove, FSgn)                  \
  X(FSGNJN_S, "fsgnjn.s", FpMove, FSgn)                \
  X(FSGNJX_S, "fsgnjx.s", FpMove, FSgn)                \
  X(FMIN_S, "fmin.s", FpCmp, FSgn)                     \
  X(FMAX_S, "fmax.s", FpCmp, FSgn)                     \
  X(FCVT_W_S, "fcvt.w.s", FpCvt, FCvtXF)               \
  X(FCVT_WU_S, "fcvt.wu.s", FpCvt, FCvtXF)             \
  X(FMV_X_W, "fmv.x.w", FpMove, FMvXF)                 \
  X(FEQ_S, "feq.s", FpCmp, FCmp)                       \
  X(FLT_S, "flt.s", FpCmp, FCmp)                       \
  X(FLE_S, "fle.s", FpCmp, FCmp)                       \
  X(FCLASS_S, "fclass.s", FpMove, FMvXF)               \
  X(FCVT_S_W, "fcvt.s.w", FpCvt, FCvtFX)               \
  X(FCVT_S_WU, "fcvt.s.wu", FpCvt, FCvtFX)             \
  X(FMV_W_X, "fmv.w.x", FpMove, FMvFX)

// Fused pairs: X(enumerator, first, second). The decode cache gives an
// entry a fused op when it and the next entry are these two instructions;
// the plain interpreter then runs both with one dispatch (the second entry
// keeps its own op, for jumps to it). Everything else (timing, statistics)
// treats a fused entry as its first instruction.
#define FWSIM_FUSED(X)            \
  X(FLW_FLW, FLW, FLW)            \
  X(FLW_FMUL, FLW, FMUL_S)        \
  X(FLW_FADD, FLW, FADD_S)        \
  X(FLW_FSUB, FLW, FSUB_S)        \
  X(FLW_LW, FLW, LW)              \
  X(FLW_FLE, FLW, FLE_S)          \
  X(FMUL_FADD, FMUL_S, FADD_S)    \
  X(FMUL_FMUL, FMUL_S, FMUL_S)    \
  X(FMUL_FLW, FMUL_S, FLW)        \
  X(FADD_FMUL, FADD_S, FMUL_S)    \
  X(FADD_FSGNJX, FADD_S, FSGNJX_S) \
  X(FSUB_FSUB, FSUB_S, FSUB_S)    \
  X(FSUB_FMUL, FSUB_S, FMUL_S)    \
  X(FSGNJX_FLT, FSGNJX_S, FLT_S)  \
  X(FLT_BEQ, FLT_S, BEQ)          \
  X(FLT_BNE, FLT_S, BNE)          \
  X(FLE_XORI, FLE_S, XORI)        \
  X(LW_LW, LW, LW)                \
  X(LW_ADDI, LW, ADDI)            \
  X(LW_ADD, LW, ADD)              \
  X(LW_BEQ, LW, BEQ)              \
  X(LW_FLW, LW, FLW)              \
  X(ADDI_BEQ, ADDI, BEQ)          \
  X(ADDI_BNE, ADDI, BNE)          \
  X(ADDI_ADDI, ADDI, ADDI)        \
  X(ADD_LW, ADD, LW)              \
  X(ADD_BEQ, ADD, BEQ)            \
  X(SLLI_ADD, SLLI, ADD)          \
  X(AND_BEQ, AND, BEQ)            \
  X(BEQ_FLW, BEQ, FLW)            \
  X(BEQ_LW, BEQ, LW)              \
  X(BEQ_BNE, BEQ, BNE)            \
  X(BEQ_ADDI, BEQ, ADDI)          \
  X(BNE_FLW, BNE, FLW)            \
  X(FLW_FLT, FLW, FLT_S)          \
  X(FLW_LUI, FLW, LUI)            \
  X(FLW_FMV_W_X, FLW, FMV_W_X)    \
  X(FMV_W_X_FLT, FMV_W_X, FLT_S)  \
  X(LUI_FLW, LUI, FLW)            \
  X(BGE_ADDI, BGE, ADDI)          \
  X(AND_BNE, AND, BNE)            \
  X(FSW_FLW, FSW, FLW)            \
  X(FSW_FSW, FSW, FSW)            \
  X(FSW_LW, FSW, LW)              \
  X(ADDI_FLW, ADDI, FLW)          \
  X(ADDI_BGE, ADDI, BGE)          \
  X(ADDI_SLT, ADDI, SLT)          \
  X(FLT_XORI, FLT_S, XORI)        \
  X(FLT_FLT, FLT_S, FLT_S)        \
  X(FLT_AND, FLT_S, AND)          \
  X(FMUL_FSUB, FMUL_S, FSUB_S)    \
  X(FSUB_BEQ, FSUB_S, BEQ)        \
  X(LBU_FLW, LBU, FLW)            \
  X(LBU_SLTU, LBU, SLTU)          \
  X(SLTU_ADDI, SLTU, ADDI)        \
  X(SLT_AND, SLT, AND)

enum class Op : uint8_t {
#define FWSIM_ENUM(name, mn, cls, fmt) name,
  FWSIM_OPS(FWSIM_ENUM)
#undef FWSIM_ENUM
  BaseCount,
  FusedBefore = BaseCount - 1,  // the fused ops follow the base ops
#define FWSIM_FUSED_ENUM(name, a, b) name,
  FWSIM_FUSED(FWSIM_FUSED_ENUM)
#undef FWSIM_FUSED_ENUM
  Count
};
inline constexpr unsigned kBaseOpCount = static_cast<unsigned>(Op::BaseCount);

struct OpInfo {
  const char* mnemonic;
  InsnClass cls;
  Format format;
};

inline constexpr OpInfo kBaseOpInfo[] = {
#define FWSIM_INFO(name, mn, cls, fmt) {mn, InsnClass::cls, Format::fmt},
    FWSIM_OPS(FWSIM_INFO)
#undef FWSIM_INFO
};
inline constexpr OpInfo kOpInfo[] = {
#define FWSIM_INFO(name, mn, cls, fmt) {mn, InsnClass::cls, Format::fmt},
    FWSIM_OPS(FWSIM_INFO)
#undef FWSIM_INFO
#define FWSIM_FUSED_INFO(name, a, b) kBaseOpInfo[static_cast<unsigned>(Op::a)],
    FWSIM_FUSED(FWSIM_FUSED_INFO)
#undef FWSIM_FUSED_INFO
};
static_assert(sizeof kOpInfo / sizeof kOpInfo[0] == static_cast<size_t>(Op::Count));

// The first instruction of a fused op (any other op: itself).
constexpr Op base_op(Op op) {
  switch (op) {
#define FWSIM_FUSED_BASE(name, a, b) case Op::name: return Op::a;
    FWSIM_FUSED(FWSIM_FUSED_BASE)
#undef FWSIM_FUSED_BASE
    default: return op;
  }
}
// The fused op for `first` followed by `second`, or Op::UNDECODED (none).
constexpr Op fused_op(Op first, Op second) {
#define FWSIM_FUSED_PAIR(name, a, b) if (first == Op::a && second == Op::b) return Op::name;
  FWSIM_FUSED(FWSIM_FUSED_PAIR)
#undef FWSIM_FUSED_PAIR
  return Op::UNDECODED;
}

inline const OpInfo& op_info(Op op) { return kOpInfo[static_cast<unsigned>(op)]; }

const char* class_name(InsnClass c);

}  // namespace fwsim
