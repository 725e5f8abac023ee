#include "commit_trace.hpp"

#include <bit>
#include <string>

#include "compressed.hpp"
#include "decoder.hpp"
#include "disassembler.hpp"
#include "isa_table.hpp"

namespace fwsim {

// A compressed instruction (`word` holds it in its low half) shows its 16
// bits, as spike's log does.
void write_commit_trace(std::FILE* out, uint32_t pc, uint32_t word, const HartState& hart) {
  const DecodedInsn d = decode_any(word);
  char hex[16];
  if (d.length == 2) std::snprintf(hex, sizeof hex, "    %04x", word & 0xffff);
  else std::snprintf(hex, sizeof hex, "%08x", word);
  const std::string text = disassemble(word, pc);
  char effect[96] = "";
  switch (op_info(d.op).format) {
    case Format::R: case Format::I: case Format::Shift: case Format::Load: case Format::U:
    case Format::J: case Format::Jalr: case Format::Csr: case Format::CsrI: case Format::FCmp:
    case Format::FCvtXF: case Format::FMvXF:
      if (d.rd != 0) std::snprintf(effect, sizeof effect, "%s=0x%08x", x_reg_name(d.rd), hart.x[d.rd]);
      break;
    case Format::FR: case Format::FR4: case Format::FUnary: case Format::FSgn: case Format::FCvtFX:
    case Format::FMvFX: case Format::FLoad: {
      const uint32_t bits = hart.f[d.rd];
      std::snprintf(effect, sizeof effect, "%s=0x%08x (%.9g)", f_reg_name(d.rd), bits,
                    static_cast<double>(std::bit_cast<float>(bits)));
      break;
    }
    case Format::Store: case Format::FStore: {
      const uint32_t addr = hart.x[d.rs1] + static_cast<uint32_t>(d.imm);
      const uint32_t value = op_info(d.op).format == Format::FStore ? hart.f[d.rs2] : hart.x[d.rs2];
      if (d.op == Op::SB) std::snprintf(effect, sizeof effect, "mem8[0x%08x]=0x%02x", addr, value & 0xff);
      else if (d.op == Op::SH) std::snprintf(effect, sizeof effect, "mem16[0x%08x]=0x%04x", addr, value & 0xffff);
      else std::snprintf(effect, sizeof effect, "mem32[0x%08x]=0x%08x", addr, value);
      break;
    }
    default:
      break;
  }
  if (effect[0]) std::fprintf(out, "%08x: %s  %-32s %s\n", pc, hex, text.c_str(), effect);
  else std::fprintf(out, "%08x: %s  %s\n", pc, hex, text.c_str());
}

void write_spike_commit(std::FILE* out, uint32_t pc, uint32_t word, const HartState& hart) {
  const DecodedInsn d = decode_any(word);
  if (d.length == 2) std::fprintf(out, "core   0: 3 0x%08x (0x%04x)", pc, word & 0xffff);
  else std::fprintf(out, "core   0: 3 0x%08x (0x%08x)", pc, word);
  switch (op_info(d.op).format) {
    case Format::R: case Format::I: case Format::Shift: case Format::Load: case Format::U:
    case Format::J: case Format::Jalr: case Format::Csr: case Format::CsrI: case Format::FCmp:
    case Format::FCvtXF: case Format::FMvXF:
      if (d.rd != 0) std::fprintf(out, " x%-2u 0x%08x", static_cast<unsigned>(d.rd), hart.x[d.rd]);
      break;
    case Format::FR: case Format::FR4: case Format::FUnary: case Format::FSgn: case Format::FCvtFX:
    case Format::FMvFX: case Format::FLoad:
      std::fprintf(out, " f%-2u 0x%08x", static_cast<unsigned>(d.rd), hart.f[d.rd]);
      break;
    case Format::Store: case Format::FStore: {
      const uint32_t addr = hart.x[d.rs1] + static_cast<uint32_t>(d.imm);
      const uint32_t value = op_info(d.op).format == Format::FStore ? hart.f[d.rs2] : hart.x[d.rs2];
      if (d.op == Op::SB) std::fprintf(out, " mem 0x%08x 0x%02x", addr, value & 0xff);
      else if (d.op == Op::SH) std::fprintf(out, " mem 0x%08x 0x%04x", addr, value & 0xffff);
      else std::fprintf(out, " mem 0x%08x 0x%08x", addr, value);
      break;
    }
    default:
      break;
  }
  std::fputc('\n', out);
}

}  // namespace fwsim
