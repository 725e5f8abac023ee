#include "disassembler.hpp"

#include <cstdio>

#include "compressed.hpp"
#include "decoder.hpp"

namespace fwsim {
namespace {

constexpr const char* kXNames[32] = {"zero", "ra", "sp", "gp", "tp",  "t0",  "t1", "t2",
                                     "s0",   "s1", "a0", "a1", "a2",  "a3",  "a4", "a5",
                                     "a6",   "a7", "s2", "s3", "s4",  "s5",  "s6", "s7",
                                     "s8",   "s9", "s10", "s11", "t3", "t4", "t5", "t6"};
constexpr const char* kFNames[32] = {"ft0", "ft1", "ft2",  "ft3",  "ft4", "ft5", "ft6",  "ft7",
                                     "fs0", "fs1", "fa0",  "fa1",  "fa2", "fa3", "fa4",  "fa5",
                                     "fa6", "fa7", "fs2",  "fs3",  "fs4", "fs5", "fs6",  "fs7",
                                     "fs8", "fs9", "fs10", "fs11", "ft8", "ft9", "ft10", "ft11"};
constexpr const char* kRmNames[8] = {"rne", "rtz", "rdn", "rup", "rmm", "rm5", "rm6", "dyn"};

}  // namespace

const char* x_reg_name(unsigned i) { return kXNames[i & 31]; }
const char* f_reg_name(unsigned i) { return kFNames[i & 31]; }

std::string disassemble(uint32_t word, uint32_t pc) {
  // A compressed instruction shows as the instruction it expands to.
  const DecodedInsn d = decode_any(word);
  const OpInfo& info = op_info(d.op);
  const char *x_rd = kXNames[d.rd], *x1 = kXNames[d.rs1], *x2 = kXNames[d.rs2];
  const char *f_rd = kFNames[d.rd], *f1 = kFNames[d.rs1], *f2 = kFNames[d.rs2];
  const char* rm = kRmNames[d.rm];
  char buf[96];
  const char* mn = info.mnemonic;
  switch (info.format) {
    case Format::R: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, x_rd, x1, x2); break;
    case Format::I: case Format::Shift: case Format::Jalr:
      std::snprintf(buf, sizeof buf, "%s %s, %s, %d", mn, x_rd, x1, d.imm); break;
    case Format::Load: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", mn, x_rd, d.imm, x1); break;
    case Format::Store: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", mn, x2, d.imm, x1); break;
    case Format::Branch:
      std::snprintf(buf, sizeof buf, "%s %s, %s, 0x%x", mn, x1, x2, pc + static_cast<uint32_t>(d.imm)); break;
    case Format::U:
      std::snprintf(buf, sizeof buf, "%s %s, 0x%x", mn, x_rd, static_cast<uint32_t>(d.imm) >> 12); break;
    case Format::J:
      std::snprintf(buf, sizeof buf, "%s %s, 0x%x", mn, x_rd, pc + static_cast<uint32_t>(d.imm)); break;
    case Format::Csr: std::snprintf(buf, sizeof buf, "%s %s, 0x%x, %s", mn, x_rd, d.imm, x1); break;
    case Format::CsrI: std::snprintf(buf, sizeof buf, "%s %s, 0x%x, %u", mn, x_rd, d.imm, d.rs1); break;
    case Format::FR: std::snprintf(buf, sizeof buf, "%s %s, %s, %s, %s", mn, f_rd, f1, f2, rm); break;
    case Format::FR4:
      std::snprintf(buf, sizeof buf, "%s %s, %s, %s, %s, %s", mn, f_rd, f1, f2, kFNames[d.rs3], rm); break;
    case Format::FUnary: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, f_rd, f1, rm); break;
    case Format::FSgn: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, f_rd, f1, f2); break;
    case Format::FCmp: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, x_rd, f1, f2); break;
    case Format::FCvtXF: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, x_rd, f1, rm); break;
    case Format::FCvtFX: std::snprintf(buf, sizeof buf, "%s %s, %s, %s", mn, f_rd, x1, rm); break;
    case Format::FMvXF: std::snprintf(buf, sizeof buf, "%s %s, %s", mn, x_rd, f1); break;
    case Format::FMvFX: std::snprintf(buf, sizeof buf, "%s %s, %s", mn, f_rd, x1); break;
    case Format::FLoad: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", mn, f_rd, d.imm, x1); break;
    case Format::FStore: std::snprintf(buf, sizeof buf, "%s %s, %d(%s)", mn, f2, d.imm, x1); break;
    case Format::None:
      if (d.op == Op::ILLEGAL && d.length == 2) std::snprintf(buf, sizeof buf, "<illegal 0x%04x>", word & 0xffff);
      else if (d.op == Op::ILLEGAL) std::snprintf(buf, sizeof buf, "<illegal 0x%08x>", word);
      else std::snprintf(buf, sizeof buf, "%s", mn);
      break;
  }
  return buf;
}

}  // namespace fwsim
