#include "lockstep.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "decoder.hpp"
#include "disassembler.hpp"

namespace fwsim {
namespace {

bool writes_x(Format f) {
  switch (f) {
    case Format::R: case Format::I: case Format::Shift: case Format::Load: case Format::U:
    case Format::J: case Format::Jalr: case Format::Csr: case Format::CsrI: case Format::FCmp:
    case Format::FCvtXF: case Format::FMvXF:
      return true;
    default:
      return false;
  }
}

bool writes_f(Format f) {
  switch (f) {
    case Format::FR: case Format::FR4: case Format::FUnary: case Format::FSgn: case Format::FCvtFX:
    case Format::FMvFX: case Format::FLoad:
      return true;
    default:
      return false;
  }
}

unsigned access_size(Op op) {
  switch (op) {
    case Op::LB: case Op::LBU: case Op::SB: return 1;
    case Op::LH: case Op::LHU: case Op::SH: return 2;
    default: return 4;
  }
}

std::string hex(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%08x", v);
  return b;
}

float as_float(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// Within `bound` of the exact result `exp`: the same bits, both NaN, or a
// finite relative error below the bound (a result the exact unit rounds to
// a subnormal may come back flushed to zero).
bool fp_within(uint32_t got, uint32_t exp, double bound) {
  if (got == exp) return true;
  const float g = as_float(got), e = as_float(exp);
  if (std::isnan(g) && std::isnan(e)) return true;
  if (bound == 0 || std::isnan(g) || std::isnan(e) || std::isinf(g) || std::isinf(e)) return false;
  if (e == 0) return g == 0;
  if (std::fabs(e) < 0x1p-126f && std::fabs(g) < 0x1p-126f) return true;
  return std::fabs(static_cast<double>(g) - e) / std::fabs(static_cast<double>(e)) < bound;
}

double parse_bound(const std::string& v, const std::string& item) {
  char* end = nullptr;
  double d;
  if (v.rfind("2^-", 0) == 0) {
    const long n = std::strtol(v.c_str() + 3, &end, 10);
    if (end == v.c_str() + 3 || *end || n < 0 || n > 200) throw std::runtime_error("bad FPU bound '" + item + "'");
    d = std::ldexp(1.0, static_cast<int>(-n));
  } else {
    d = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !(d >= 0) || d >= 1) throw std::runtime_error("bad FPU bound '" + item + "'");
  }
  return d;
}

}  // namespace

FpuSpec parse_fpu_spec(const std::string& text) {
  FpuSpec s;
  size_t at = 0;
  while (at <= text.size()) {
    size_t comma = text.find(',', at);
    if (comma == std::string::npos) comma = text.size();
    const std::string item = text.substr(at, comma - at);
    const size_t eq = item.find('=');
    if (eq == std::string::npos) throw std::runtime_error("bad FPU bound '" + item + "': expected OP=BOUND");
    const std::string op = item.substr(0, eq), v = item.substr(eq + 1);
    double* slot = op == "add" ? &s.add : op == "mul" ? &s.mul : op == "div" ? &s.div : op == "sqrt" ? &s.sqrt : nullptr;
    if (!slot) throw std::runtime_error("bad FPU bound '" + item + "': the operations are add, mul, div, sqrt");
    *slot = parse_bound(v, item);
    at = comma + 1;
  }
  return s;
}

Retirement step_one(Machine& m, StopInfo& stop) {
  HartState& h = m.hart();
  Retirement r;
  r.pc = h.pc;
  if (m.bus().in_code(h.pc, 4) && !(h.pc & 3)) std::memcpy(&r.insn, m.bus().code_at(h.pc), 4);
  const DecodedInsn d = decode(r.insn);
  const Format f = op_info(d.op).format;
  const uint32_t rs1v = h.x[d.rs1];
  const uint32_t rs2v = f == Format::FStore ? h.f[d.rs2] : h.x[d.rs2];

  // As a debugger's single step: stop at every possible successor. A jump
  // to itself is stopped by the instruction limit, checked at taken jumps.
  std::vector<uint32_t> next{h.pc + 4};
  if (f == Format::Branch) next.push_back(h.pc + static_cast<uint32_t>(d.imm));
  else if (f == Format::J) next = {h.pc + static_cast<uint32_t>(d.imm)};
  else if (f == Format::Jalr) next = {(rs1v + static_cast<uint32_t>(d.imm)) & ~1u};
  bool self_loop = false;
  std::vector<uint32_t> set;
  for (uint32_t a : next) {
    if (a == h.pc) self_loop = true;
    else if (m.set_breakpoint(a)) set.push_back(a);
  }
  stop = m.run(self_loop ? h.instret : std::numeric_limits<uint64_t>::max());
  if (stop.cause == StopCause::InstructionLimit && self_loop) stop.cause = StopCause::Breakpoint;
  for (uint32_t a : set) m.clear_breakpoint(a);

  const uint8_t rd = (r.insn >> 7) & 31;
  if (writes_x(f) && rd != 0) {
    r.rd = rd;
    r.rd_value = h.x[rd];
  } else if (writes_f(f)) {
    r.rd = rd;
    r.rd_value = h.f[rd];
  }
  if (f == Format::Load || f == Format::FLoad || f == Format::Store || f == Format::FStore) {
    const uint32_t addr = rs1v + static_cast<uint32_t>(d.imm);
    const unsigned size = access_size(d.op);
    const unsigned lane = addr & 3;
    const uint8_t mask = static_cast<uint8_t>(((1u << size) - 1) << lane);
    r.mem_addr = addr & ~3u;
    if (f == Format::Store || f == Format::FStore) {
      r.mem_wmask = mask;
      const uint32_t v = size == 4 ? rs2v : rs2v & ((1u << (8 * size)) - 1);
      r.mem_wdata = v << (8 * lane);
    } else {
      r.mem_rmask = mask;
      if (const uint8_t* p = m.bus().host_at(r.mem_addr, 4)) std::memcpy(&r.mem_rdata, p, 4);
    }
  }
  return r;
}

std::string Lockstep::where(uint32_t pc) const {
  if (!symbols_) return hex(pc);
  return hex(pc) + " in " + symbols_->describe(pc);
}

std::string Lockstep::line(const Retirement& r) const {
  char b[64];
  std::snprintf(b, sizeof b, "%08x: %08x  ", r.pc, r.insn);
  std::string s = b + disassemble(r.insn, r.pc);
  const Format f = op_info(decode(r.insn).op).format;
  if (r.rd != 0 || writes_f(f)) s += std::string("  ") + (writes_f(f) ? f_reg_name(r.rd) : x_reg_name(r.rd)) + "=" + hex(r.rd_value);
  if (r.mem_wmask) s += "  mem[" + hex(r.mem_addr) + "]=" + hex(r.mem_wdata) + " mask " + std::to_string(r.mem_wmask);
  if (r.mem_rmask) s += "  load " + hex(r.mem_addr) + " mask " + std::to_string(r.mem_rmask);
  return s;
}

void Lockstep::diverge(const Retirement& dut, const Retirement& exp, uint64_t cycle, const std::string& what,
                       const std::string& expected, const std::string& actual) {
  std::string s = "lockstep: divergence at cycle " + std::to_string(cycle) + ", instruction " +
                  std::to_string(checked_ + 1) + ": " + what + "\n";
  s += "  at " + where(exp.pc) + "\n";
  s += "  expected: " + expected + "\n";
  s += "  actual:   " + actual + "\n";
  s += "  reference: " + line(exp) + "\n";
  s += "  CPU:       " + line(dut) + "\n";
  if (!past_.empty()) {
    s += "  last " + std::to_string(past_.size()) + " retired instructions (cycle: pc: insn):\n";
    for (size_t i = 0; i < past_.size(); ++i) {
      const Past& p = past_[(next_ + i) % past_.size()];
      s += "    " + std::to_string(p.cycle) + ": " + line(p.r) + "\n";
    }
  }
  report_ = s;
}

bool Lockstep::check(const Retirement& dut, uint64_t cycle) {
  if (ref_stopped_) {
    report_ = "lockstep: the CPU retired " + where(dut.pc) + " at cycle " + std::to_string(cycle) +
              " after the reference stopped\n";
    return false;
  }
  // Where the CPU's instruction is not the reference's, stop before
  // stepping: the reference has not run it.
  const uint32_t ref_pc = ref_.hart().pc;
  if (dut.pc != ref_pc) {
    Retirement exp;
    exp.pc = ref_pc;
    if (ref_.bus().in_code(ref_pc, 4)) std::memcpy(&exp.insn, ref_.bus().code_at(ref_pc), 4);
    std::string what = "pc";
    if (!past_.empty()) {
      const Past& prev = past_[(next_ + past_.size() - 1) % past_.size()];
      what += " after " + line(prev.r);
    }
    diverge(dut, exp, cycle, what, hex(ref_pc), hex(dut.pc));
    return false;
  }
  StopInfo stop;
  Retirement exp = step_one(ref_, stop);
  if (stop.cause != StopCause::None && stop.cause != StopCause::Breakpoint) ref_stopped_ = true;
  auto fail = [&](const std::string& what, const std::string& e, const std::string& a) {
    diverge(dut, exp, cycle, what, e, a);
    return false;
  };
  if (dut.insn != exp.insn) return fail("instruction word", hex(exp.insn), hex(dut.insn));

  const DecodedInsn d = decode(exp.insn);
  const OpInfo& info = op_info(d.op);
  const bool fp_dest = writes_f(info.format);
  // Loads outside RAM and ROM read devices: the CPU's value stands.
  const bool device_load = exp.mem_rmask && !ref_.bus().host_at(exp.mem_addr, 4);
  if (device_load && exp.rd != 0) {
    if (fp_dest) ref_.hart().f[exp.rd] = dut.rd_value;
    else ref_.hart().x[exp.rd] = dut.rd_value;
    exp.rd_value = dut.rd_value;
    exp.mem_rdata = dut.mem_rdata;
  }
  auto reg = [&](uint8_t r, uint32_t v) {
    return std::string(fp_dest ? f_reg_name(r) : x_reg_name(r)) + " = " + hex(v);
  };
  if (dut.rd != exp.rd) return fail("destination register", reg(exp.rd, exp.rd_value), reg(dut.rd, dut.rd_value));
  if (dut.rd_value != exp.rd_value) {
    double bound = 0;
    switch (info.cls) {
      case InsnClass::FpAdd: bound = spec_.add; break;
      case InsnClass::FpMul: bound = spec_.mul; break;
      case InsnClass::FpDiv: bound = spec_.div; break;
      case InsnClass::FpSqrt: bound = spec_.sqrt; break;
      default: break;
    }
    if (fp_dest && bound > 0 && fp_within(dut.rd_value, exp.rd_value, bound)) {
      ref_.hart().f[exp.rd] = dut.rd_value;  // adopted: the reference goes on from the CPU's value
      ++fp_adopted_;
    } else {
      char rel[96] = "";
      if (fp_dest) {
        const double e = as_float(exp.rd_value), g = as_float(dut.rd_value);
        std::snprintf(rel, sizeof rel, " (%.9g vs %.9g, relative error %.3g, bound %.3g)", g, e,
                      e != 0 ? std::fabs(g - e) / std::fabs(e) : 0.0, bound);
      }
      return fail(fp_dest && bound > 0 ? "float result outside the FPU specification" : "register value",
                  reg(exp.rd, exp.rd_value), reg(dut.rd, dut.rd_value) + rel);
    }
  }
  if (exp.mem_wmask || dut.mem_wmask) {
    if (dut.mem_wmask != exp.mem_wmask || dut.mem_addr != exp.mem_addr)
      return fail("store address", hex(exp.mem_addr) + " mask " + std::to_string(exp.mem_wmask),
                  hex(dut.mem_addr) + " mask " + std::to_string(dut.mem_wmask));
    uint32_t lanes = 0;
    for (int i = 0; i < 4; ++i)
      if (exp.mem_wmask & (1 << i)) lanes |= 0xffu << (8 * i);
    if ((dut.mem_wdata & lanes) != (exp.mem_wdata & lanes))
      return fail("store data", hex(exp.mem_wdata & lanes), hex(dut.mem_wdata & lanes));
  }
  if (exp.mem_rmask && (dut.mem_rmask != exp.mem_rmask || dut.mem_addr != exp.mem_addr))
    return fail("load address", hex(exp.mem_addr) + " mask " + std::to_string(exp.mem_rmask),
                hex(dut.mem_addr) + " mask " + std::to_string(dut.mem_rmask));

  ++checked_;
  if (history_) {
    if (past_.size() < history_) past_.push_back({cycle, dut});
    else {
      past_[next_] = {cycle, dut};
      next_ = (next_ + 1) % history_;
    }
  }
  return true;
}

}  // namespace fwsim
