// Random loop programs for comparing generated code with the interpreter
// (test_block_jit.cpp, test_timed_jit.cpp): a subroutine and a hot loop of
// random RV32IMF instructions with forward branches and calls, and the
// comparison of everything architectural after a run.
#pragma once
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

#include "sim_harness.hpp"

namespace jit_programs {

using namespace rv;
using fwsim::StopCause;
using fwsim::StopInfo;

constexpr uint32_t kDataOffset = 0x10000;  // data the programs load and store, in RAM
constexpr uint32_t kDataBytes = 512;
constexpr unsigned kDataReg = 2, kLoopReg = 31, kLinkReg = 1;

// FP operands that exercise NaN canonicalisation, signaling NaNs, zeros of
// both signs, infinities, subnormals and ordinary values.
constexpr uint32_t kFloatPool[] = {0x00000000, 0x80000000, 0x3fc00000, 0xc0100000, 0x7f800000, 0xff800000,
                                   0x7fc00000, 0x7f800001, 0xffc00123, 0x00000001, 0x807fffff, 0x7f7fffff,
                                   0x00800000, 0x4b000001, 0x3eaaaaab, 0xbf800000};

struct Program {
  std::vector<uint32_t> code;
  uint32_t x[32];
  uint32_t f[32];
  std::vector<uint8_t> data;
  uint32_t loop = 0;  // index of the loop's first instruction (after the subroutine)
};

// A subroutine, then a loop (run 40 times: hot enough to be translated)
// of random instructions with forward branches and calls; ebreak at the end.
inline Program random_program(uint32_t seed) {
  std::mt19937 rng(seed);
  auto pick = [&](uint32_t n) { return static_cast<uint32_t>(rng() % n); };
  auto dest = [&] {
    const uint32_t r = pick(30);
    return r < 2 ? 0u : r + 1;  // x0 or x3..x30 (x1, x2, x31 are the link, data and loop registers)
  };
  auto src = [&] { return pick(32); };
  auto freg = [&] { return pick(32); };
  auto rm = [&] {
    const uint32_t r[] = {DYN, RNE, DYN, RTZ, DYN, RUP};
    return r[pick(6)];
  };
  auto one = [&](bool allow_mem) -> uint32_t {
    switch (pick(allow_mem ? 40 : 32)) {
      case 0: return addi(dest(), src(), static_cast<int32_t>(pick(4096)) - 2048);
      case 1: return i_type(static_cast<int32_t>(pick(4096)) - 2048, src(), 2, dest(), 0x13);  // slti
      case 2: return i_type(static_cast<int32_t>(pick(4096)) - 2048, src(), 3, dest(), 0x13);  // sltiu
      case 3: return i_type(static_cast<int32_t>(pick(4096)) - 2048, src(), 4 + 2 * pick(2), dest(), 0x13);  // xori/ori
      case 4: return i_type(static_cast<int32_t>(pick(4096)) - 2048, src(), 7, dest(), 0x13);  // andi
      case 5: return slli(dest(), src(), pick(32));
      case 6: return pick(2) ? srli(dest(), src(), pick(32)) : srai(dest(), src(), pick(32));
      case 7: return r_type(pick(2) ? 0x20 : 0, src(), src(), 0, dest(), 0x33);  // add/sub
      case 8: return r_type(0, src(), src(), 1 + pick(7), dest(), 0x33);         // sll..and
      case 9: return r_type(0x20, src(), src(), 5, dest(), 0x33);                // sra
      case 10: return r_type(1, src(), src(), pick(8), dest(), 0x33);            // mul..remu
      case 11: return lui(dest(), pick(1u << 20));
      case 12: return auipc(dest(), pick(1u << 20));
      case 13: return fp(0x00 | pick(4) << 2, freg(), freg(), freg(), rm());  // fadd/fsub/fmul/fdiv
      case 14: return fsqrt(freg(), freg(), rm());
      case 15: return fp(0x10, freg(), freg(), freg(), pick(3));  // fsgnj/n/x
      case 16: return fp(0x14, freg(), freg(), freg(), pick(2));  // fmin/fmax
      case 17: return fp(0x50, dest(), freg(), freg(), pick(3));  // fle/flt/feq
      case 18: return fmv_x_w(dest(), freg());
      case 19: return fmv_w_x(freg(), src());
      case 20: return fcvt_s_w(freg(), src(), rm());
      case 21: return fcvt_w_s(dest(), freg(), rm());
      case 22: return fclass(dest(), freg());
      case 23: return fmadd(freg(), freg(), freg(), freg(), rm());
      case 24: return csrrs(dest(), kFflags, 0);
      case 25: return 0x0ff0000f;  // fence
      case 26: return fmul(freg(), freg(), freg(), DYN);
      case 27: return fadd(freg(), freg(), freg(), DYN);
      case 28: return fcvt_s_wu(freg(), src(), rm());
      case 29: return fp(0x50, dest(), freg(), freg(), 1);  // flt
      case 30: return add(dest(), src(), src());
      case 31: return addi(dest(), src(), static_cast<int32_t>(pick(64)) - 32);
      default: break;
    }
    // Loads and stores in the data area, aligned.
    const uint32_t kind = pick(10);
    const uint32_t lg = kind == 0 || kind == 3 || kind == 5 ? 0 : kind == 1 || kind == 4 || kind == 6 ? 1 : 2;
    const int32_t off = static_cast<int32_t>(pick(kDataBytes >> lg) << lg);
    switch (kind) {
      case 0: return lb(dest(), kDataReg, off);
      case 1: return lh(dest(), kDataReg, off);
      case 2: return lw(dest(), kDataReg, off);
      case 3: return lbu(dest(), kDataReg, off);
      case 4: return lhu(dest(), kDataReg, off);
      case 5: return sb(src(), kDataReg, off);
      case 6: return sh(src(), kDataReg, off);
      case 7: return sw(src(), kDataReg, off);
      case 8: return flw(freg(), kDataReg, off);
      default: return fsw(freg(), kDataReg, off);
    }
  };
  Program p;
  const uint32_t sub_len = 2 + pick(6);
  p.code.push_back(jal(0, static_cast<int32_t>(sub_len + 2) * 4));
  for (uint32_t i = 0; i < sub_len; ++i) p.code.push_back(one(true));
  p.code.push_back(jalr(0, kLinkReg, 0));
  const uint32_t loop = static_cast<uint32_t>(p.code.size());
  p.loop = loop;
  const uint32_t body = 8 + pick(40);
  for (uint32_t i = 0; i < body; ++i) {
    const uint32_t here = static_cast<uint32_t>(p.code.size());
    const uint32_t left = body - i;
    const uint32_t what = pick(12);
    if (what == 0 && left > 1) {
      // Forward branch over 0..3 instructions (at most to the loop's end).
      const uint32_t skip = pick(left < 4 ? left : 4);
      const uint32_t f3[] = {0, 1, 4, 5, 6, 7};
      p.code.push_back(b_type(static_cast<int32_t>(skip + 1) * 4, src(), src(), f3[pick(6)]));
    } else if (what == 1) {
      p.code.push_back(jal(kLinkReg, (1 - static_cast<int32_t>(here)) * 4));
    } else {
      p.code.push_back(one(true));
    }
  }
  p.code.push_back(addi(kLoopReg, kLoopReg, -1));
  p.code.push_back(bne(kLoopReg, 0, (static_cast<int32_t>(loop) - static_cast<int32_t>(p.code.size())) * 4));
  // Sim appends the final ebreak.
  for (uint32_t& r : p.x) r = rng();
  p.x[0] = 0;
  p.x[kDataReg] = fwsim::kRamBase + kDataOffset;
  p.x[kLoopReg] = 40;
  for (uint32_t& r : p.f) r = pick(3) ? kFloatPool[pick(16)] : rng();
  p.data.resize(kDataBytes);
  for (size_t i = 0; i < kDataBytes; i += 4) {
    const uint32_t w = pick(2) ? kFloatPool[pick(16)] : rng();
    std::memcpy(&p.data[i], &w, 4);
  }
  return p;
}

inline void load(Sim& s, const Program& p, bool jit, uint8_t frm) {
  s.m.set_jit(jit);
  for (unsigned i = 0; i < 32; ++i) {
    s.x(i) = p.x[i];
    s.f(i) = p.f[i];
  }
  s.m.hart().frm = frm;
  std::memcpy(s.m.bus().ram() + kDataOffset, p.data.data(), p.data.size());
}

// How many instructions the program runs to its end, interpreted: the
// range the limit tests pick their limits from.
inline uint64_t instructions_to_end(const Program& p) {
  Sim probe(p.code);
  load(probe, p, false, 0);
  probe.run();
  return probe.m.hart().instret;
}

// Everything architectural, and how the run stopped.
inline void require_same(Sim& a, Sim& b, const StopInfo& sa, const StopInfo& sb) {
  REQUIRE(sa.cause == sb.cause);
  REQUIRE(sa.pc == sb.pc);
  REQUIRE(sa.addr == sb.addr);
  REQUIRE(a.m.hart().pc == b.m.hart().pc);
  REQUIRE(a.m.hart().instret == b.m.hart().instret);
  REQUIRE(a.m.hart().cycles == b.m.hart().cycles);
  REQUIRE(a.m.hart().fflags == b.m.hart().fflags);
  for (unsigned i = 0; i < 32; ++i) {
    INFO("x" << i);
    REQUIRE(a.x(i) == b.x(i));
  }
  for (unsigned i = 0; i < 32; ++i) {
    INFO("f" << i);
    REQUIRE(a.f(i) == b.f(i));
  }
  REQUIRE(std::memcmp(a.m.bus().ram() + kDataOffset, b.m.bus().ram() + kDataOffset, kDataBytes) == 0);
}

}  // namespace jit_programs
