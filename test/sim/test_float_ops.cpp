// RV32F semantics through the interpreter (fast and soft paths): NaN rules,
// conversions, rounding modes (static and dynamic), exact fflags, fclass.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "sim_harness.hpp"

using namespace rv;
using fwsim::StopCause;

namespace {
constexpr uint32_t kQNaN = 0x7fc00000u, kSNaN = 0x7f800001u, kNegQNaNPayload = 0xffc12345u;
constexpr uint32_t kInf = 0x7f800000u, kNegInf = 0xff800000u, kNegZero = 0x80000000u;
constexpr uint32_t NX = 1, UF = 2, OF = 4, DZ = 8, NV = 16;

// Runs one FP instruction with f1/f2/f3 (or x1) set; returns (result, fflags).
struct One {
  uint32_t result, flags;
};
One run_fp(uint32_t insn, uint32_t a, uint32_t b = 0, uint32_t c = 0, bool int_result = false, uint32_t frm = 0) {
  Sim s({insn, csrrs(20, kFflags, 0)});
  s.f(1) = a;
  s.f(2) = b;
  s.f(3) = c;
  s.x(1) = a;
  s.m.hart().frm = static_cast<uint8_t>(frm);
  REQUIRE(s.run().cause == StopCause::Ebreak);
  return {int_result ? s.x(10) : s.f(10), s.x(20)};
}
}  // namespace

TEST_CASE("arithmetic NaN results are the canonical NaN", "[fp]") {
  auto r = run_fp(fadd(10, 1, 2, RNE), kInf, kNegInf);
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  r = run_fp(fmul(10, 1, 2), kNegQNaNPayload, bits_of(1.0f));
  CHECK(r.result == kQNaN);
  CHECK(r.flags == 0);
  r = run_fp(fmul(10, 1, 2), kSNaN, bits_of(1.0f));
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  r = run_fp(fsqrt(10, 1), bits_of(-1.0f));
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  r = run_fp(fsqrt(10, 1, RTZ), kNegZero);
  CHECK(r.result == kNegZero);
  r = run_fp(fdiv(10, 1, 2, RUP), 0, 0);  // soft path too
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
}

TEST_CASE("fflags are exact on the fast and the soft path", "[fp]") {
  for (uint32_t rm : {uint32_t{RNE}, uint32_t{RTZ}}) {
    CAPTURE(rm);
    CHECK(run_fp(fdiv(10, 1, 2, rm), bits_of(1.0f), bits_of(3.0f)).flags == NX);
    CHECK(run_fp(fdiv(10, 1, 2, rm), bits_of(1.0f), 0).flags == DZ);
    CHECK(run_fp(fmul(10, 1, 2, rm), bits_of(3e38f), bits_of(2.0f)).flags == (OF | NX));
    CHECK(run_fp(fmul(10, 1, 2, rm), bits_of(1e-30f), bits_of(1e-30f)).flags == (UF | NX));
    CHECK(run_fp(fadd(10, 1, 2, rm), bits_of(1.5f), bits_of(2.25f)).flags == 0);
    // Exact subnormal result: no underflow flag without inexact.
    CHECK(run_fp(fmul(10, 1, 2, rm), 0x00800000u, bits_of(0.5f)).flags == 0);
  }
  // Overflow result depends on the rounding mode.
  CHECK(run_fp(fmul(10, 1, 2, RNE), bits_of(3e38f), bits_of(2.0f)).result == kInf);
  CHECK(run_fp(fmul(10, 1, 2, RTZ), bits_of(3e38f), bits_of(2.0f)).result == 0x7f7fffffu);
  CHECK(run_fp(fmul(10, 1, 2, RDN), bits_of(3e38f), bits_of(-2.0f)).result == kNegInf);
  CHECK(run_fp(fmul(10, 1, 2, RUP), bits_of(3e38f), bits_of(-2.0f)).result == 0xff7fffffu);
}

TEST_CASE("all rounding modes, static and dynamic", "[fp][rounding]") {
  const uint32_t one = bits_of(1.0f), up = 0x3f800001u;  // 1 and 1 + 2^-23
  const uint32_t tie = 0x33800000u;                      // 2^-24: exactly half an ulp of 1
  const uint32_t above = 0x33c00000u;                    // 1.5 * 2^-24
  struct Case {
    uint32_t rm, tie_result, above_result;
  } cases[] = {{RNE, one, up}, {RTZ, one, one}, {RDN, one, one}, {RUP, up, up}, {RMM, up, up}};
  for (const Case& c : cases) {
    CAPTURE(c.rm);
    CHECK(run_fp(fadd(10, 1, 2, c.rm), one, tie).result == c.tie_result);
    CHECK(run_fp(fadd(10, 1, 2, c.rm), one, above).result == c.above_result);
    CHECK(run_fp(fadd(10, 1, 2, DYN), one, tie, 0, false, c.rm).result == c.tie_result);
    CHECK(run_fp(fadd(10, 1, 2, DYN), one, above, 0, false, c.rm).flags == NX);
  }
  // Negative ties: RDN rounds away from zero, RUP towards it.
  CHECK(run_fp(fsub(10, 1, 2, RDN), bits_of(-1.0f), tie).result == 0xbf800001u);
  CHECK(run_fp(fsub(10, 1, 2, RUP), bits_of(-1.0f), tie).result == bits_of(-1.0f));
  // Exact zero sum is -0 only when rounding down.
  CHECK(run_fp(fsub(10, 1, 2, RDN), one, one).result == kNegZero);
  CHECK(run_fp(fsub(10, 1, 2, RNE), one, one).result == 0u);
}

TEST_CASE("reserved rounding modes are illegal instructions", "[fp][rounding]") {
  Sim s({fadd(10, 1, 2, 5)});
  CHECK(s.run().cause == StopCause::IllegalInstruction);
  Sim d({fadd(10, 1, 2, DYN)});
  d.m.hart().frm = 6;
  CHECK(d.run().cause == StopCause::IllegalInstruction);
}

TEST_CASE("fcvt.w(u).s round per mode and saturate with NV", "[fp][convert]") {
  struct Case {
    float in;
    uint32_t rm;
    int32_t out;
  } cases[] = {{2.5f, RNE, 2},   {2.5f, RMM, 3},   {2.5f, RTZ, 2},   {2.5f, RDN, 2},   {2.5f, RUP, 3},
               {-2.5f, RNE, -2}, {-2.5f, RMM, -3}, {-2.5f, RTZ, -2}, {-2.5f, RDN, -3}, {-2.5f, RUP, -2},
               {3.5f, RNE, 4},   {-0.4f, RUP, 0}};
  for (const Case& c : cases) {
    CAPTURE(c.in, c.rm);
    auto r = run_fp(fcvt_w_s(10, 1, c.rm), bits_of(c.in), 0, 0, true);
    CHECK(static_cast<int32_t>(r.result) == c.out);
    CHECK(r.flags == NX);
  }
  auto sat = [](uint32_t insn, uint32_t in) { return run_fp(insn, in, 0, 0, true); };
  CHECK(sat(fcvt_w_s(10, 1, RTZ), bits_of(3e9f)).result == 0x7fffffffu);
  CHECK(sat(fcvt_w_s(10, 1, RTZ), bits_of(3e9f)).flags == NV);
  CHECK(sat(fcvt_w_s(10, 1, RTZ), bits_of(-3e9f)).result == 0x80000000u);
  CHECK(sat(fcvt_w_s(10, 1, RTZ), bits_of(-2147483648.0f)).flags == 0);
  CHECK(sat(fcvt_w_s(10, 1, RTZ), kQNaN).result == 0x7fffffffu);
  CHECK(sat(fcvt_w_s(10, 1, RTZ), 0xffc00000u).result == 0x7fffffffu);  // NaN sign ignored
  CHECK(sat(fcvt_w_s(10, 1, RTZ), kNegInf).result == 0x80000000u);
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), bits_of(-1.0f)).result == 0u);
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), bits_of(-1.0f)).flags == NV);
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), bits_of(-0.5f)).flags == NX);  // rounds to 0: in range
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), bits_of(5e9f)).result == 0xffffffffu);
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), kQNaN).result == 0xffffffffu);
  CHECK(sat(fcvt_wu_s(10, 1, RTZ), bits_of(4294967040.0f)).result == 4294967040u);
}

TEST_CASE("fcvt.s.w(u) round large integers per mode", "[fp][convert]") {
  // 2^24 + 1 is not representable: ties to even gives 2^24, RUP 2^24 + 2.
  auto r = run_fp(fcvt_s_w(10, 1, RNE), 16777217u);
  CHECK(r.result == bits_of(16777216.0f));
  CHECK(r.flags == NX);
  CHECK(run_fp(fcvt_s_w(10, 1, RUP), 16777217u).result == bits_of(16777218.0f));
  CHECK(run_fp(fcvt_s_w(10, 1, RDN), static_cast<uint32_t>(-16777217)).result == bits_of(-16777218.0f));
  CHECK(run_fp(fcvt_s_wu(10, 1, RNE), 0xffffffffu).result == bits_of(4294967296.0f));
  CHECK(run_fp(fcvt_s_wu(10, 1, RTZ), 0xffffffffu).result == 0x4f7fffffu);
  CHECK(run_fp(fcvt_s_w(10, 1, RNE), 0x80000000u).flags == 0);
}

TEST_CASE("fmin/fmax NaN and signed-zero rules", "[fp][minmax]") {
  const uint32_t one = bits_of(1.0f);
  auto r = run_fp(fmin(10, 1, 2), kQNaN, one);
  CHECK(r.result == one);
  CHECK(r.flags == 0);
  r = run_fp(fmax(10, 1, 2), one, kSNaN);
  CHECK(r.result == one);
  CHECK(r.flags == NV);
  r = run_fp(fmin(10, 1, 2), kNegQNaNPayload, kSNaN);
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  CHECK(run_fp(fmin(10, 1, 2), 0, kNegZero).result == kNegZero);
  CHECK(run_fp(fmax(10, 1, 2), kNegZero, 0).result == 0u);
  CHECK(run_fp(fmin(10, 1, 2), bits_of(-3.0f), bits_of(2.0f)).result == bits_of(-3.0f));
}

TEST_CASE("comparisons: quiet feq, signalling flt/fle", "[fp][compare]") {
  CHECK(run_fp(feq(10, 1, 2), kQNaN, kQNaN, 0, true).flags == 0);
  CHECK(run_fp(feq(10, 1, 2), kSNaN, 0, 0, true).flags == NV);
  CHECK(run_fp(flt(10, 1, 2), kQNaN, 0, 0, true).flags == NV);
  CHECK(run_fp(fle(10, 1, 2), kQNaN, 0, 0, true).result == 0u);
  CHECK(run_fp(feq(10, 1, 2), kNegZero, 0, 0, true).result == 1u);
  CHECK(run_fp(flt(10, 1, 2), kNegZero, 0, 0, true).result == 0u);
  CHECK(run_fp(fle(10, 1, 2), bits_of(-1.0f), kNegZero, 0, true).result == 1u);
}

TEST_CASE("fclass reports each of the ten classes", "[fp][fclass]") {
  const std::pair<uint32_t, uint32_t> cases[] = {
      {kNegInf, 1u << 0}, {bits_of(-1.0f), 1u << 1}, {0x80000001u, 1u << 2}, {kNegZero, 1u << 3},
      {0u, 1u << 4},      {0x00000001u, 1u << 5},    {bits_of(1.0f), 1u << 6}, {kInf, 1u << 7},
      {kSNaN, 1u << 8},   {kQNaN, 1u << 9}};
  for (auto [in, cls] : cases) {
    CAPTURE(in);
    CHECK(run_fp(fclass(10, 1), in, 0, 0, true).result == cls);
  }
}

TEST_CASE("fused multiply-add rounds once and follows RISC-V NaN rules", "[fp][fma]") {
  // a*a = 1 + 2^-11 + 2^-24 rounds to 1 + 2^-11 when unfused; fused, the
  // 2^-24 survives the subtraction.
  const uint32_t a = 0x3f800800u, c = 0x3f801000u, neg_c = c | 0x80000000u;
  for (uint32_t rm : {uint32_t{RNE}, uint32_t{RTZ}, uint32_t{RMM}, uint32_t{RDN}}) {
    CAPTURE(rm);
    auto r = run_fp(fmadd(10, 1, 2, 3, rm), a, a, neg_c);
    CHECK(r.result == 0x33800000u);
    CHECK(r.flags == 0);
  }
  CHECK(run_fp(fmsub(10, 1, 2, 3, RNE), a, a, c).result == 0x33800000u);
  CHECK(run_fp(fnmsub(10, 1, 2, 3, RNE), a, a, c).result == 0xb3800000u);
  CHECK(run_fp(fnmadd(10, 1, 2, 3, RNE), a, a, neg_c).result == 0xb3800000u);
  const uint32_t m1 = bits_of(-1.0f);
  auto r = run_fp(fmadd(10, 1, 2, 3, RNE), kInf, 0, kQNaN);
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  r = run_fp(fmadd(10, 1, 2, 3, RNE), kInf, bits_of(1.0f), kNegInf);
  CHECK(r.result == kQNaN);
  CHECK(r.flags == NV);
  // Exact zero: -0 only when both addends are -0 (or rounding down).
  CHECK(run_fp(fmadd(10, 1, 2, 3, RNE), kNegZero, bits_of(1.0f), kNegZero).result == kNegZero);
  CHECK(run_fp(fmadd(10, 1, 2, 3, RDN), bits_of(1.0f), bits_of(1.0f), m1).result == kNegZero);
}

TEST_CASE("sign injection and moves are bit exact, NaN payloads included", "[fp]") {
  CHECK(run_fp(fsgnj(10, 1, 2), kSNaN, kNegZero).result == (kSNaN | 0x80000000u));
  CHECK(run_fp(fsgnjn(10, 1, 2), bits_of(2.0f), bits_of(3.0f)).result == bits_of(-2.0f));
  CHECK(run_fp(fsgnjx(10, 1, 2), bits_of(-2.0f), bits_of(-3.0f)).result == bits_of(2.0f));
  CHECK(run_fp(fmv_x_w(10, 1), kNegQNaNPayload, 0, 0, true).result == kNegQNaNPayload);
  CHECK(run_fp(fmv_w_x(10, 1), kSNaN).result == kSNaN);
}

TEST_CASE("fcsr, frm and fflags CSRs are views of one register", "[fp][csr]") {
  // frm = RUP via csrrwi, fflags accumulate across host and soft paths.
  Sim s({csrrwi(0, kFrm, RUP), fdiv(10, 1, 2, RNE), fsqrt(11, 3, DYN), csrrs(20, kFcsr, 0),
         csrrwi(21, kFflags, 0), csrrs(22, kFcsr, 0)});
  s.f(1) = bits_of(1.0f);
  s.f(2) = bits_of(3.0f);
  s.f(3) = bits_of(-4.0f);
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.x(20) == ((RUP << 5) | NX | NV));
  CHECK(s.x(21) == (NX | NV));
  CHECK(s.x(22) == (RUP << 5));
}

TEST_CASE("FP loads and stores move raw bits", "[fp]") {
  Sim s({fsw(1, 5, 0), flw(10, 5, 0), lw(11, 5, 0)});
  s.f(1) = kSNaN;
  s.x(5) = fwsim::kRamBase + 0x800;
  REQUIRE(s.run().cause == StopCause::Ebreak);
  CHECK(s.f(10) == kSNaN);
  CHECK(s.x(11) == kSNaN);
}
