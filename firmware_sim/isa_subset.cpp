#include "isa_subset.hpp"

namespace fwsim {
namespace {

bool uses_high_register(const DecodedInsn& d) {
  auto high = [](uint8_t r) { return r >= 16; };
  switch (op_info(d.op).format) {
    case Format::R: return high(d.rd) || high(d.rs1) || high(d.rs2);
    case Format::I: case Format::Shift: case Format::Load: case Format::Jalr: case Format::Csr:
      return high(d.rd) || high(d.rs1);
    case Format::Store: case Format::Branch: return high(d.rs1) || high(d.rs2);
    case Format::U: case Format::J: case Format::CsrI: case Format::FCmp: case Format::FCvtXF:
    case Format::FMvXF:
      return high(d.rd);
    case Format::FCvtFX: case Format::FMvFX: case Format::FLoad: case Format::FStore:
      return high(d.rs1);
    default: return false;
  }
}

}  // namespace

bool parse_isa(const std::string& text, IsaSpec& isa) {
  static const char* const kNames[] = {"rv32i", "rv32im", "rv32imc", "rv32imf", "rv32imfc",
                                       "rv32e", "rv32em", "rv32emc"};
  bool known = false;
  for (const char* n : kNames) known = known || text == n;
  if (!known) return false;
  const std::string ext = text.substr(5);
  isa.rv32e = text[4] == 'e';
  isa.m = ext.find('m') != std::string::npos;
  isa.f = ext.find('f') != std::string::npos;
  isa.c = ext.find('c') != std::string::npos;
  return true;
}

std::string isa_name(const IsaSpec& isa) {
  std::string s = isa.rv32e ? "rv32e" : "rv32i";
  if (isa.m) s += 'm';
  if (isa.f) s += 'f';
  if (isa.c) s += 'c';
  if (!isa.zicsr) s += " without Zicsr";
  return s;
}

const char* missing_extension(const IsaSpec& isa, uint32_t word, const DecodedInsn& d) {
  // A compressed instruction needs C, then whatever its expansion (`d`) needs.
  if ((word & 3) != 3 && !isa.c) return "the C extension";
  const InsnClass cls = op_info(d.op).cls;
  if ((cls == InsnClass::Mul || cls == InsnClass::Div) && !isa.m) return "the M extension";
  switch (cls) {
    case InsnClass::FpAdd: case InsnClass::FpMul: case InsnClass::FpDiv: case InsnClass::FpSqrt:
    case InsnClass::FpCvt: case InsnClass::FpCmp: case InsnClass::FpMove: case InsnClass::FpFused:
    case InsnClass::FpLoad: case InsnClass::FpStore:
      if (!isa.f) return "the F extension";
      break;
    case InsnClass::Csr:
      if (!isa.zicsr) return "the Zicsr extension";
      break;
    default: break;
  }
  if (d.op == Op::FENCE_I && !isa.zifencei) return "the Zifencei extension";
  if (isa.rv32e && uses_high_register(d)) return "registers x16..x31 (the E base has x0..x15)";
  return nullptr;
}

}  // namespace fwsim
