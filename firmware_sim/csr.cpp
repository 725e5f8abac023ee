#include "csr.hpp"

#include "fpu.hpp"

namespace fwsim {
namespace {
enum : unsigned {
  kFflags = 0x001, kFrm = 0x002, kFcsr = 0x003,
  kCycle = 0xc00, kTime = 0xc01, kInstret = 0xc02,
  kCycleH = 0xc80, kTimeH = 0xc81, kInstretH = 0xc82,
  kMcycle = 0xb00, kMinstret = 0xb02, kMcycleH = 0xb80, kMinstretH = 0xb82,
  kMstatus = 0x300, kMisa = 0x301, kMie = 0x304, kMtvec = 0x305, kMscratch = 0x340,
  kMepc = 0x341, kMcause = 0x342, kMtval = 0x343, kMip = 0x344,
  kMvendorid = 0xf11, kMarchid = 0xf12, kMimpid = 0xf13, kMhartid = 0xf14,
};
// RV32 + I, M, F
constexpr uint32_t kMisaValue = (1u << 30) | (1u << 8) | (1u << 12) | (1u << 5);
}  // namespace

bool CsrFile::read(HartState& h, unsigned csr, uint32_t& v) const {
  const uint64_t time = static_cast<uint64_t>(
      static_cast<unsigned __int128>(h.cycles) * kTimebaseHz / clock_hz_);
  switch (csr) {
    case kFflags: h.fflags |= fpu::take_host_flags(); v = h.fflags; return true;
    case kFrm: v = h.frm; return true;
    case kFcsr: h.fflags |= fpu::take_host_flags(); v = (uint32_t{h.frm} << 5) | h.fflags; return true;
    case kCycle: case kMcycle: v = static_cast<uint32_t>(h.cycles); return true;
    case kCycleH: case kMcycleH: v = static_cast<uint32_t>(h.cycles >> 32); return true;
    case kInstret: case kMinstret: v = static_cast<uint32_t>(h.instret); return true;
    case kInstretH: case kMinstretH: v = static_cast<uint32_t>(h.instret >> 32); return true;
    case kTime: v = static_cast<uint32_t>(time); return true;
    case kTimeH: v = static_cast<uint32_t>(time >> 32); return true;
    case kMstatus: v = mstatus_; return true;
    case kMisa: v = kMisaValue; return true;
    case kMie: v = mie_; return true;
    case kMtvec: v = mtvec_; return true;
    case kMscratch: v = mscratch_; return true;
    case kMepc: v = mepc_; return true;
    case kMcause: v = mcause_; return true;
    case kMtval: v = mtval_; return true;
    case kMip: case kMvendorid: case kMarchid: case kMimpid: case kMhartid: v = 0; return true;
  }
  return false;
}

bool CsrFile::access(HartState& h, unsigned csr, CsrOp op, uint32_t operand, bool write,
                     uint32_t& old) {
  if (!read(h, csr, old)) return false;
  if (!write) return true;
  uint32_t v = op == CsrOp::Write ? operand : op == CsrOp::Set ? (old | operand) : (old & ~operand);
  switch (csr) {
    case kFflags: h.fflags = v & 0x1f; fpu::clear_host_flags(); return true;
    case kFrm: h.frm = v & 7; return true;
    case kFcsr: h.fflags = v & 0x1f; h.frm = (v >> 5) & 7; fpu::clear_host_flags(); return true;
    case kMstatus: mstatus_ = v; return true;
    case kMie: mie_ = v; return true;
    case kMtvec: mtvec_ = v; return true;
    case kMscratch: mscratch_ = v; return true;
    case kMepc: mepc_ = v; return true;
    case kMcause: mcause_ = v; return true;
    case kMtval: mtval_ = v; return true;
    case kMisa: case kMip: return true;  // WARL: writes ignored
    default: return false;               // counters and ids are read-only here
  }
}

}  // namespace fwsim
