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

enum class Op : uint8_t {
#define FWSIM_ENUM(name, mn, cls, fmt) name,
  FWSIM_OPS(FWSIM_ENUM)
#undef FWSIM_ENUM
  Count
};

struct OpInfo {
  const char* mnemonic;
  InsnClass cls;
  Format format;
};

inline constexpr OpInfo kOpInfo[] = {
#define FWSIM_INFO(name, mn, cls, fmt) {mn, InsnClass::cls, Format::fmt},
    FWSIM_OPS(FWSIM_INFO)
#undef FWSIM_INFO
};

inline const OpInfo& op_info(Op op) { return kOpInfo[static_cast<unsigned>(op)]; }

const char* class_name(InsnClass c);

}  // namespace fwsim
