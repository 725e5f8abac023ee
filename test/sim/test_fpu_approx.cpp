// FPU models (fpu_approx.hpp) on known operands. Every expected value is
// worked out from the definition in docs/firmware_sim.md ("FPU models") by
// hand, step by step in exact arithmetic with round-to-nearest-even after
// each step; the derivations are in the comments.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include "fpu_approx.hpp"
#include "sim_harness.hpp"

using fwsim::FpuApprox;
using fwsim::FpuModelConfig;

namespace {
constexpr uint8_t NX = 1, UF = 2, OF = 4, DZ = 8, NV = 16;
constexpr uint32_t kQNaN = 0x7fc00000u, kSNaN = 0x7f800001u, kInf = 0x7f800000u, kNegInf = 0xff800000u;
constexpr uint32_t kOne = 0x3f800000u, kTwo = 0x40000000u, kThree = 0x40400000u;
constexpr uint32_t k1_3 = 0x3fa66666u;  // 1.3f = 10905190 * 2^-23
constexpr uint32_t kPi = 0x40490fdbu;

FpuModelConfig recip_model(unsigned t, unsigned e, unsigned n) {
  FpuModelConfig c;
  c.div = FpuModelConfig::Div::RecipMul;
  c.recip_table_bits = t;
  c.recip_entry_bits = e;
  c.recip_newton_steps = n;
  return c;
}
FpuModelConfig rsqrt_model(unsigned t, unsigned e, unsigned n) {
  FpuModelConfig c;
  c.sqrt = FpuModelConfig::Sqrt::TableNewton;
  c.rsqrt_table_bits = t;
  c.rsqrt_entry_bits = e;
  c.rsqrt_newton_steps = n;
  return c;
}

struct Out {
  uint32_t bits;
  uint8_t flags;
};
Out div_of(const FpuApprox& u, uint32_t a, uint32_t b) {
  uint8_t f = 0;
  const uint32_t r = u.div(a, b, 0, f);
  return {r, f};
}
Out sqrt_of(const FpuApprox& u, uint32_t a) {
  uint8_t f = 0;
  const uint32_t r = u.sqrt(a, 0, f);
  return {r, f};
}
}  // namespace

TEST_CASE("reciprocal table entries are 1/midpoint rounded to the entry width", "[fpu-approx]") {
  // T=0: one interval [1,2), midpoint 1.5, 1/1.5 = 2/3 rounded to 24 bits:
  // 2^25/3 = 11184810.67 -> 11184811 * 2^-24 = 0x3f2aaaab.
  CHECK(fwsim::recip_table_entry(0, 23, 0) == 0x3f2aaaabu);
  // T=1, E=2: [1,1.5) mid 1.25, 1/1.25 = 0.8 = 6.4/8 -> 6/8 = 0.75;
  //           [1.5,2) mid 1.75, 1/1.75 = 4.57/8 -> 5/8 = 0.625.
  CHECK(fwsim::recip_table_entry(1, 2, 0) == 0x3f400000u);
  CHECK(fwsim::recip_table_entry(1, 2, 1) == 0x3f200000u);
  // T=2, E=3: interval 1 is [1.25,1.5), mid 1.375 = 11/8, 8/11 = 11.64/16 -> 12/16 = 0.75.
  CHECK(fwsim::recip_table_entry(2, 3, 1) == 0x3f400000u);
  // T=4, E=1: mid 33/32, 32/33 = 3.88/4 rounds up to 4/4 = 1.0.
  CHECK(fwsim::recip_table_entry(4, 1, 0) == kOne);
  // Whole table, T=8: every entry within half an entry ulp of 1/midpoint.
  for (uint32_t i = 0; i < 256; ++i) {
    const double mid = 1.0 + (i + 0.5) / 256.0;
    float entry;
    const uint32_t bits = fwsim::recip_table_entry(8, 23, i);
    std::memcpy(&entry, &bits, 4);
    CHECK(std::fabs(entry - 1.0 / mid) <= 0x1p-25);
  }
}

TEST_CASE("inverse square root table entries cover 1 to 2 then 2 to 4", "[fpu-approx]") {
  // T=1, E=23: index 0 is [1,2), mid 1.5: 1/sqrt(1.5) = 0.81649658 -> 0x3f5105ec;
  //            index 1 is [2,4), mid 3:   1/sqrt(3)   = 0.57735027 -> 0x3f13cd3a.
  CHECK(fwsim::rsqrt_table_entry(1, 23, 0) == 0x3f5105ecu);
  CHECK(fwsim::rsqrt_table_entry(1, 23, 1) == 0x3f13cd3au);
  // T=2, E=3: the upper index bit picks [1,2) or [2,4), one fraction bit
  // halves it: index 0 is [1,1.5) mid 1.25 -> 1/sqrt(1.25) = 0.894 = 14.31/16 -> 14/16;
  // index 1 is [1.5,2) mid 1.75 -> 0.756 = 12.09/16 -> 12/16;
  // index 2 is [2,3) mid 2.5 -> 0.632 = 10.12/16 -> 10/16;
  // index 3 is [3,4) mid 3.5 -> 0.535 = 8.55/16 -> 9/16.
  CHECK(fwsim::rsqrt_table_entry(2, 3, 0) == 0x3f600000u);
  CHECK(fwsim::rsqrt_table_entry(2, 3, 1) == 0x3f400000u);
  CHECK(fwsim::rsqrt_table_entry(2, 3, 2) == 0x3f200000u);
  CHECK(fwsim::rsqrt_table_entry(2, 3, 3) == 0x3f100000u);
}

TEST_CASE("reciprocal Newton steps in single precision", "[fpu-approx]") {
  // T=0, N=1, m=1: r0 = 11184811*2^-24; t = m r0 = r0; 2 - t = 22369621*2^-24
  // is a tie at 2^-23 spacing -> even 11184810*2^-23 = 0x3faaaaaa;
  // r1 = r0 * that = 0.88888884 -> 0x3f638e38 (error 1/9: e0 = 1/3 squared).
  CHECK(FpuApprox(recip_model(0, 23, 1)).recip_significand(kOne) == 0x3f638e38u);
  // T=2, E=3, N=1, m = 1.3f: index (frac >> 21) = 1 -> r0 = 0.75;
  // t = 1.3f * 0.75 = 16357785*2^-24 (exact) = 0x3f799999;
  // 2 - t = 17196647*2^-24, a tie -> 8598324*2^-23 = 0x3f833334;
  // r1 = 0.75 * that = 12897486*2^-24 (exact) = 0x3f44ccce.
  const FpuApprox coarse(recip_model(2, 3, 1));
  CHECK(coarse.recip_significand(k1_3) == 0x3f44ccceu);
  // 3 / 1.3f: significands 1.5 and 1.3f, exponents 1 and 0.
  // q = 1.5 * r1 = 19346229*2^-24, a tie -> 9673114*2^-23; times 2^1 = 0x4013999a.
  CHECK(div_of(coarse, kThree, k1_3).bits == 0x4013999au);
  CHECK(div_of(coarse, kThree | 0x80000000u, k1_3).bits == 0xc013999au);
  CHECK(div_of(coarse, kThree, k1_3 | 0x80000000u).bits == 0xc013999au);
  CHECK(div_of(coarse, kThree, k1_3).flags == NX);
  // Exponents move the result only: 3*2^10 / (1.3f*2^-5) = 0x4013999a * 2^15.
  CHECK(div_of(coarse, kThree + (10u << 23), k1_3 - (5u << 23)).bits == 0x4013999au + (15u << 23));
  // N=0: the table entry itself: 1 / 1.3f = 1 * 0.75.
  CHECK(div_of(FpuApprox(recip_model(2, 3, 0)), kOne, k1_3).bits == 0x3f400000u);
}

TEST_CASE("inverse square root Newton steps and the square root", "[fpu-approx]") {
  // T=2, E=3, N=1. sqrt(1): m=1, even exponent, index 0 -> r0 = 14/16.
  // r0^2 = 196/256, (m/2) r0^2 = 98/256, 1.5 - that = 286/256,
  // r1 = 14/16 * 286/256 = 4004/4096 = 0.9775390625 (all exact);
  // s = m r1 = 0x3f7a4000.
  const FpuApprox u(rsqrt_model(2, 3, 1));
  CHECK(u.rsqrt_significand(kOne) == 0x3f7a4000u);
  CHECK(sqrt_of(u, kOne).bits == 0x3f7a4000u);
  // sqrt(2): exponent 1 is odd -> m = 2, e = 0; index 2 ([2,3)) -> r0 = 10/16.
  // r0^2 = 100/256, (m/2) r0^2 = 100/256, 1.5 - that = 284/256,
  // r1 = 10/16 * 284/256 = 2840/4096; s = 2 r1 = 1.38671875 = 0x3fb18000.
  CHECK(sqrt_of(u, kTwo).bits == 0x3fb18000u);
  // sqrt(8) = sqrt(2 * 2^2) = s * 2; sqrt(0.5) = sqrt(2 * 2^-2) = s / 2.
  CHECK(sqrt_of(u, 0x41000000u).bits == 0x40318000u);
  CHECK(sqrt_of(u, 0x3f000000u).bits == 0x3f318000u);
  CHECK(sqrt_of(u, kTwo).flags == NX);
  // N=0: sqrt(1) = 1 * r0 = 0.875.
  CHECK(sqrt_of(FpuApprox(rsqrt_model(2, 3, 0)), kOne).bits == 0x3f600000u);
}

TEST_CASE("zeros infinities and NaNs keep their IEEE results", "[fpu-approx]") {
  FpuModelConfig c = recip_model(10, 23, 1);
  c.sqrt = FpuModelConfig::Sqrt::TableNewton;
  const FpuApprox u(c);
  auto same = [](Out o, uint32_t bits, uint8_t flags) {
    CHECK(o.bits == bits);
    CHECK(o.flags == flags);
  };
  same(div_of(u, 0, 0), kQNaN, NV);
  same(div_of(u, kInf, kNegInf), kQNaN, NV);
  same(div_of(u, kOne, 0), kInf, DZ);
  same(div_of(u, kOne, 0x80000000u), kNegInf, DZ);
  same(div_of(u, kInf, kTwo), kInf, 0);
  same(div_of(u, kTwo, kNegInf), 0x80000000u, 0);
  same(div_of(u, 0x80000000u, kThree), 0x80000000u, 0);
  same(div_of(u, 0xffc12345u, kOne), kQNaN, 0);
  same(div_of(u, kOne, kSNaN), kQNaN, NV);
  same(sqrt_of(u, 0xbf800000u), kQNaN, NV);
  same(sqrt_of(u, kNegInf), kQNaN, NV);
  same(sqrt_of(u, 0x80000000u), 0x80000000u, 0);
  same(sqrt_of(u, 0), 0, 0);
  same(sqrt_of(u, kInf), kInf, 0);
  same(sqrt_of(u, kSNaN), kQNaN, NV);
  // A quotient beyond the float range is infinite: 2^127 / 0.25.
  same(div_of(u, 0x7f000000u, 0x3e800000u), kInf, OF | NX);
}

TEST_CASE("subnormals are rounded when kept and zero when flushed", "[fpu-approx]") {
  // T=0, E=1, N=0: 1/1.5 = 2.67/4 -> 3/4, so every reciprocal significand is 0.75.
  FpuModelConfig keep = recip_model(0, 1, 0);
  FpuModelConfig flush = keep;
  flush.flush_subnormals = true;
  const FpuApprox k(keep), f(flush);
  // 2^-126 / 2 = 0.75 * 2^-127 = 1.5 * 2^-128 = 3145728 * 2^-149 (exact).
  CHECK(div_of(k, 0x00800000u, kTwo).bits == 0x00300000u);
  CHECK(div_of(k, 0x00800000u, kTwo).flags == (UF | NX));
  CHECK(div_of(f, 0x00800000u, kTwo).bits == 0);
  CHECK(div_of(f, 0x00800000u, kTwo).flags == (UF | NX));
  // 2^-126 / 2^22 = 0.75 * 2^-148 = 1.5 * 2^-149: a tie, to even 2 * 2^-149.
  CHECK(div_of(k, 0x00800000u, 0x4a800000u).bits == 0x00000002u);
  // A subnormal divisor is normalised when kept, zero when flushed.
  // 1 / 2^-149: significand 1, exponent -149 -> 0.75 * 2^149 overflows.
  CHECK(div_of(k, kOne, 0x00000001u).bits == kInf);
  CHECK(div_of(f, kOne, 0x00000001u).bits == kInf);
  CHECK(div_of(f, kOne, 0x00000001u).flags == DZ);
  // 2^-130 / 2^-3 = 0.75 * 2^-127 ... via a subnormal dividend: 2^-130 is
  // 0x00080000; significand 1, exponent -130; kept it gives 0.75 * 2^-127.
  CHECK(div_of(k, 0x00080000u, 0x3e000000u).bits == 0x00300000u);
  CHECK(div_of(f, 0x00080000u, 0x3e000000u).bits == 0);
  // Exact ops with subnormals flushed: inputs and results.
  FpuModelConfig ftz;
  ftz.flush_subnormals = true;
  const FpuApprox z(ftz), ieee{FpuModelConfig{}};
  uint8_t fl = 0;
  CHECK(z.mul(0x0d800000u, 0x30800000u, 0, fl) == 0);  // 2^-100 * 2^-30 = 2^-130
  CHECK(fl == (UF | NX));
  fl = 0;
  CHECK(ieee.mul(0x0d800000u, 0x30800000u, 0, fl) == 0x00080000u);
  CHECK(fl == 0);
  fl = 0;
  CHECK(z.add(0x00000001u, 0, 0, fl) == 0);
  CHECK(z.add(0x80000001u, kOne, 0, fl) == kOne);
  CHECK(fl == 0);
  CHECK(z.sqrt(0x00400000u, 0, fl) == 0);
  CHECK(ieee.add(0x00000001u, 0, 0, fl) == 0x00000001u);
}

TEST_CASE("truncating multiply and add round toward zero and overflow to infinity", "[fpu-approx]") {
  FpuModelConfig c;
  c.mul = FpuModelConfig::Rounding::Truncate;
  c.add = FpuModelConfig::Rounding::Truncate;
  const FpuApprox t(c), ieee{FpuModelConfig{}};
  uint8_t f = 0;
  // pi^2 = 9.8696041...: nearest is 0x411de9e7, below it 0x411de9e6.
  CHECK(ieee.mul(kPi, kPi, 0, f) == 0x411de9e7u);
  CHECK(t.mul(kPi, kPi, 0, f) == 0x411de9e6u);
  CHECK(t.mul(kPi | 0x80000000u, kPi, 0, f) == 0xc11de9e6u);
  // 1 + 1.5 * 2^-24: nearest 1 + 2^-23, truncated 1.
  CHECK(ieee.add(kOne, 0x33c00000u, 0, f) == 0x3f800001u);
  CHECK(t.add(kOne, 0x33c00000u, 0, f) == kOne);
  CHECK(t.sub(kOne, 0xb3c00000u, 0, f) == kOne);
  // The rounding-mode operand does not change a truncating unit.
  CHECK(t.add(kOne, 0x33c00000u, 3 /* RUP */, f) == kOne);
  // 2^127 * 2 overflows to infinity (round toward zero would give the largest float).
  f = 0;
  CHECK(t.mul(0x7f000000u, kTwo, 0, f) == kInf);
  CHECK(f == (OF | NX));
  f = 0;
  CHECK(t.add(0x7f7fffffu, 0x7f7fffffu, 0, f) == kInf);
  CHECK(f == (OF | NX));
  // The divider's Newton steps use the unit's own (truncating) multiplier
  // and subtracter. T=2, E=3, N=1, m = 1.3f as above: t = 0x3f799999 (exact);
  // 2 - t = 17196647*2^-24 truncates to 8598323*2^-23 = 0x3f833333 (the
  // nearest-even result was 0x3f833334); r1 = 0.75 * that = 12897484.5*2^-24
  // truncates to 12897484*2^-24 = 0x3f44cccc.
  FpuModelConfig tr = recip_model(2, 3, 1);
  tr.mul = FpuModelConfig::Rounding::Truncate;
  tr.add = FpuModelConfig::Rounding::Truncate;
  CHECK(FpuApprox(tr).recip_significand(k1_3) == 0x3f44ccccu);
}

TEST_CASE("the interpreter runs modelled ops only where the model differs", "[fpu-approx]") {
  using namespace rv;
  const FpuApprox coarse(recip_model(2, 3, 1));
  Sim s({fdiv(10, 1, 2), fmul(11, 3, 3), fdiv(12, 1, 2, RNE), csrrwi(0, kFrm, RTZ), fdiv(13, 1, 2),
         fmul(14, 3, 3), csrrs(20, kFflags, 0)});
  s.m.set_fpu_model(&coarse);
  s.f(1) = kThree;
  s.f(2) = k1_3;
  s.f(3) = kPi;
  REQUIRE(s.run().cause == fwsim::StopCause::Ebreak);
  CHECK(s.f(10) == 0x4013999au);  // modelled, dynamic rounding mode
  CHECK(s.f(12) == 0x4013999au);  // modelled, static RNE
  CHECK(s.f(13) == 0x4013999au);  // modelled after frm changed: the model has one behaviour
  CHECK(s.f(11) == 0x411de9e7u);  // fmul stays IEEE (nearest)
  CHECK(s.f(14) == 0x411de9e6u);  // IEEE round toward zero from frm
  CHECK((s.x(20) & NX) != 0);
}

TEST_CASE("modelled ops keep reserved rounding modes illegal and honour the mode when exact", "[fpu-approx]") {
  using namespace rv;
  const FpuApprox coarse(recip_model(2, 3, 1));
  Sim bad({fdiv(10, 1, 2, 5)});
  bad.m.set_fpu_model(&coarse);
  CHECK(bad.run().cause == fwsim::StopCause::IllegalInstruction);

  FpuModelConfig ftz;
  ftz.flush_subnormals = true;
  const FpuApprox z(ftz);
  Sim s({fadd(10, 1, 2, RUP), fadd(11, 1, 2, RTZ), fmul(12, 3, 4)});
  s.m.set_fpu_model(&z);
  s.f(1) = kOne;
  s.f(2) = 0x33c00000u;  // 1.5 * 2^-24
  s.f(3) = 0x0d800000u;  // 2^-100
  s.f(4) = 0x30800000u;  // 2^-30
  REQUIRE(s.run().cause == fwsim::StopCause::Ebreak);
  CHECK(s.f(10) == 0x3f800001u);
  CHECK(s.f(11) == kOne);
  CHECK(s.f(12) == 0);  // 2^-130 flushed
}
