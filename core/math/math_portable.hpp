// Portable single-precision math policy: the runtime functions of min-rt
// (sqrt, floor, sin, cos, atan, float_of_int, int_of_float) built only from
// float add/sub/mul/div, comparisons and integer/bit operations, so that the
// renderer runs on a CPU whose FPU has nothing more (or on soft float).
//
// No libc, no <cmath>, no float<->int conversion instructions, no fma, no
// double.  Like the rest of core/, it includes no C++ library header (only
// the compiler's <stdint.h>), so it builds for a bare RISC-V target.
// Algorithms and measured errors are in docs/shims.md; the constants come
// from tools/shim_ulp/gen_coeffs.py.
//
//   PortableFloatT<2> (= PortableFloat, "float/portable"): sqrt correctly
//     rounded, sin/cos/atan below 1 ULP over the whole float range.
//   PortableFloatT<1> (= PortableFloatFast, "float/portable-fast"): shorter
//     polynomials, no extra-precision tail in the sin/cos reduction, one-step
//     atan reduction, sqrt from a Newton iteration without the exact
//     correction; up to 2.6 ULP.  Meets the course rules (relative error
//     2^-18 sin/cos, 2^-20 atan/sqrt).
//   PortableFloatT<0> (= PortableFloatMin, "float/portable-min"): the fewest
//     operations that still meet those rules: sqrt as the bare Newton
//     estimate, cos degree 6 without compensation, atan degree 9 after one
//     division, a shorter Cody-Waite pi/2; up to 3.4 ULP (2^-21.8).
//
// Everything assumes the build's -ffp-contract=off and IEEE binary32 with
// round-to-nearest-even; the compensated steps below rely on both.
#pragma once

#include <stdint.h>

#include "core/base/bit_cast.hpp"
#include "core/math/binary32_bits.hpp"
#include "core/math/math_policy.hpp"

namespace minrt {
namespace portable_detail {

using u32 = uint32_t;
using i32 = int32_t;
using u64 = uint64_t;

using binary32::kAbsMask;
using binary32::kFracMask;
using binary32::kHiddenBit;
using binary32::kInfBits;
using binary32::kQuietNaN;
using binary32::kSignBit;

constexpr u32 bits_of(float x) { return bit_cast<u32>(x); }
constexpr float float_of(u32 b) { return bit_cast<float>(b); }
constexpr bool nan_bits(u32 b) { return (b & kAbsMask) > kInfBits; }
// Unbiased exponent field (subnormals and zero give -127, inf/NaN 128).
constexpr int exponent_of(u32 b) { return int((b >> 23) & 0xffu) - 127; }
// 2^e for -126 <= e <= 127, exact.
constexpr float pow2(int e) { return float_of(u32(e + 127) << 23); }

// Leading zeros by binary search: __builtin_clz may become a libcall
// (__clzsi2) on cores without a count instruction.
constexpr int clz32(u32 v) {
  if (v == 0) return 32;
  int n = 0;
  if ((v & 0xffff0000u) == 0) { n += 16; v <<= 16; }
  if ((v & 0xff000000u) == 0) { n += 8; v <<= 8; }
  if ((v & 0xf0000000u) == 0) { n += 4; v <<= 4; }
  if ((v & 0xc0000000u) == 0) { n += 2; v <<= 2; }
  if ((v & 0x80000000u) == 0) { n += 1; }
  return n;
}
constexpr int clz64(u64 v) {
  const u32 hi = u32(v >> 32);
  return hi != 0 ? clz32(hi) : 32 + clz32(u32(v));
}

// ---------------------------------------------------------------- integers

// int32 -> float, round to nearest even.  The leading one is placed at bit 23
// and added (not or-ed) onto the exponent field, so a mantissa that rounds up
// to 2^24 carries into the exponent by itself.
constexpr float from_int(i32 i) {
  const u32 sign = i < 0 ? kSignBit : 0u;
  const u32 mag = i < 0 ? 0u - u32(i) : u32(i);
  if (mag == 0) return 0.0f;
  const int top = 31 - clz32(mag);
  u32 m;
  if (top <= 23) {
    m = mag << (23 - top);
  } else {
    const int drop = top - 23;
    const u32 rest = mag & ((1u << drop) - 1u);
    const u32 half = 1u << (drop - 1);
    m = mag >> drop;
    if (rest > half || (rest == half && (m & 1u) != 0)) ++m;
  }
  return float_of(sign | ((u32(top + 126) << 23) + m));
}

// float -> int32, truncation toward zero.  Exact for |x| < 2^31 and for
// -2^31; larger magnitudes saturate, NaN gives 0.
constexpr i32 to_int(float x) {
  const u32 b = bits_of(x);
  if (nan_bits(b)) return 0;
  const int e = exponent_of(b);
  if (e < 0) return 0;
  const bool neg = (b & kSignBit) != 0;
  if (e >= 31) {
    return neg ? INT32_MIN : INT32_MAX;
  }
  const u32 m = (b & kFracMask) | kHiddenBit;
  const u32 mag = e >= 23 ? m << (e - 23) : m >> (23 - e);
  return neg ? i32(0u - mag) : i32(mag);
}

// ------------------------------------------------------------------- floor

constexpr float floor(float x) {
  u32 b = bits_of(x);
  const int e = exponent_of(b);
  if (e == 128) return x + x;  // inf stays, NaN is quieted
  if (e >= 23) return x;       // already integral
  if (e < 0) {
    if ((b & kAbsMask) == 0) return x;  // keeps -0
    return (b & kSignBit) != 0 ? -1.0f : 0.0f;
  }
  const u32 frac = kFracMask >> e;
  if ((b & frac) == 0) return x;
  // Negative: add one unit to the magnitude (a carry out of the mantissa
  // lands in the exponent, giving the next power of two), then chop.
  if ((b & kSignBit) != 0) b += frac + 1u;
  return float_of(b & ~frac);
}

// -------------------------------------------------------------------- sqrt

// Level 2: correctly rounded; level 1: one Heron-style correction; level 0:
// the Newton estimate x r as it is.
template <int Level>
constexpr float sqrt(float x) {
  u32 b = bits_of(x);
  if (nan_bits(b)) return x + x;
  if ((b & kAbsMask) == 0) return x;  // +0, -0
  if ((b & kSignBit) != 0) return float_of(kQuietNaN);
  if (b == kInfBits) return x;
  int half_scale = 0;
  if (b < kHiddenBit) {  // subnormal: scale by 2^24 (exact), result by 2^-12
    x = x * pow2(24);
    b = bits_of(x);
    half_scale = 12;
  }
  // Reciprocal square root: bit-level first guess (about 3.5 % off), then
  // three Newton steps r <- r (3/2 - x/2 r^2), each roughly squaring the error.
  const float half_x = 0.5f * x;
  float r = float_of(0x5f3759dfu - (b >> 1));
  for (int i = 0; i < 3; ++i) r = r * (1.5f - half_x * r * r);
  float y = x * r;
  if constexpr (Level == 0) {
    // Three Newton steps leave r within a few float roundings of
    // 1/sqrt(x); x r is then a few ULPs off, well inside 2^-20.
    return float_of(bits_of(y) - (u32(half_scale) << 23));
  } else if constexpr (Level == 1) {
    // One Heron-style correction: y + (x - y^2) / (2y), with 1/y ~ r.
    y = y + (x - y * y) * (0.5f * r);
    return float_of(bits_of(y) - (u32(half_scale) << 23));
  } else {
    // Exact integer correction.  x = mx 2^(E-23); with F = floor(E/2),
    // N = mx 2^(23+E-2F) is in [2^46, 2^48) and sqrt(x) = sqrt(N) 2^(F-23).
    const int e = exponent_of(b);
    const int f = e >> 1;  // floor, also for negative e
    const u64 n = u64((b & kFracMask) | kHiddenBit) << (23 + e - 2 * f);
    const u32 yb = bits_of(y);
    const int ey = exponent_of(yb);
    u64 q;  // candidate sqrt(N), from the estimate's mantissa
    if (ey > f) {
      q = 0xffffffu;
    } else if (ey < f) {
      q = kHiddenBit;
    } else {
      q = (yb & kFracMask) | kHiddenBit;
    }
    // Make q = floor(sqrt(N)); the estimate is a few units off at most.
    while (q * q > n) --q;
    while ((q + 1) * (q + 1) <= n) ++q;
    // Nearest: round up iff N > (q + 1/2)^2 = q^2 + q + 1/4, i.e. N - q^2 > q
    // (N is an integer, so there are no ties).
    if (n - q * q > q) ++q;
    return float_of((u32(f - half_scale + 126) << 23) + u32(q));
  }
}

// ------------------------------------------------------- error-free sums

struct Pair {
  float hi, lo;
};
// hi + lo == a + b exactly (Knuth), any magnitudes.
constexpr Pair two_sum(float a, float b) {
  const float s = a + b;
  const float bb = s - a;
  const float err = (a - (s - bb)) + (b - bb);
  return {s, err};
}
// Same, when |a| >= |b| or a == 0 (Dekker).
constexpr Pair fast_two_sum(float a, float b) {
  const float s = a + b;
  return {s, b - (s - a)};
}

template <int N>
constexpr float horner(const float (&c)[N], float z) {
  float acc = c[N - 1];
  for (int i = N - 2; i >= 0; --i) acc = acc * z + c[i];
  return acc;
}

// ------------------------------------------------------- sin/cos reduction

// |x| = k pi/2 + (hi + lo), |hi + lo| <= about pi/4; quadrant = k mod 4.
struct Reduced {
  float hi, lo;
  u32 quadrant;
};

inline constexpr float kTwoOverPi = 0x1.45f306p-1f;
inline constexpr float kRoundMagic = 0x1.8p23f;  // adding it rounds to integer
inline constexpr u32 kPiOver4Bits = 0x3f490fdbu;  // float(pi/4)
inline constexpr u32 kCodyWaiteLimitBits = 0x46000000u;  // 2^13

// pi/2 in pieces: the first five have 11 significant bits, so k * piece is
// exact for k < 2^13; the sixth is the float nearest to the rest.
inline constexpr float kPio2Pieces[6] = {
    0x1.92p+0f, 0x1.fb4p-12f, 0x1.444p-24f, 0x1.68cp-39f, 0x1.1a4p-54f,
    0x1.13198ap-65f};
// Fast level: the first four pieces, then the float nearest to the rest.
inline constexpr float kPio2FastTail = 0x1.1a6264p-54f;
// Minimum level: the first three pieces, then the float nearest to the rest.
inline constexpr float kPio2MinTail = 0x1.68c234p-39f;

// Cody-Waite for pi/4 < ax < 2^13.  ax - k*p0 is exact (Sterbenz for k <= 2,
// otherwise the difference fits in 24 bits), and so is the step with p1; the
// later steps are exact whenever the remainder is small, and otherwise round
// at a relative 2^-24 of a remainder that is not small.  With Tail, the
// later roundings are also captured (two_sum) in lo.
// The nearest multiple k of pi/2 below 2^13, as an integer and a float.
struct NearestQuadrant {
  u32 k;
  float kf;
};
constexpr NearestQuadrant nearest_quadrant(float ax) {
  const float t = ax * kTwoOverPi + kRoundMagic;
  return {bits_of(t) - bits_of(kRoundMagic), t - kRoundMagic};
}

template <bool Tail>
constexpr Reduced reduce_cody_waite(float ax) {
  const auto [k, kf] = nearest_quadrant(ax);
  float r = ax - kf * kPio2Pieces[0];
  r = r - kf * kPio2Pieces[1];
  if constexpr (!Tail) {
    r = r - kf * kPio2Pieces[2];
    r = r - kf * kPio2Pieces[3];
    r = r - kf * kPio2FastTail;
    return {r, 0.0f, k};
  } else {
    float lo = 0.0f;
    for (int i = 2; i < 6; ++i) {
      const Pair s = two_sum(r, -(kf * kPio2Pieces[i]));
      r = s.hi;
      lo = lo + s.lo;
    }
    const Pair out = fast_two_sum(r, lo);
    return {out.hi, out.lo, k};
  }
}

// Bits of 2/pi after the binary point, most significant first (word 0 holds
// the bits of weight 2^-1 .. 2^-32).
inline constexpr u32 kTwoOverPiWords[10] = {
    0xa2f9836eu, 0x4e441529u, 0xfc2757d1u, 0xf534ddc0u, 0xdb629599u,
    0x3c439041u, 0xfe5163abu, 0xdebbc561u, 0xb7246e3au, 0x424dd2e0u};
// round(pi/2 * 2^62)
inline constexpr u64 kPio2Fixed62 = 0x6487ed5110b4611aull;

// High 64 bits of the 128-bit product a*b, from 32x32->64 multiplies.
constexpr u64 mul_hi64(u64 a, u64 b) {
  const u64 a0 = u32(a), a1 = a >> 32, b0 = u32(b), b1 = b >> 32;
  const u64 p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const u64 mid = (p00 >> 32) + u32(p01) + u32(p10);
  return p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

// 64 bits of the little-endian limb array p starting at bit pos.
constexpr u64 bits64_at(const u32 (&p)[6], int pos) {
  const int w = pos >> 5, sh = pos & 31;
  if (sh == 0) return (u64(p[w + 1]) << 32) | p[w];
  const u32 lo = (p[w] >> sh) | (p[w + 1] << (32 - sh));
  const u32 hi = (p[w + 1] >> sh) | (p[w + 2] << (32 - sh));
  return (u64(hi) << 32) | lo;
}

// Payne-Hanek in integer arithmetic for finite ax >= 2^13 (a test checks it
// against Cody-Waite from 2 up).  ax = m 2^s, m a 24-bit integer.  Bits of
// 2/pi whose weight makes m * bit * 2^s a multiple of 4 cannot change the
// quadrant or the fraction, so only a 96-bit window of 2/pi is multiplied:
// the product then holds the quadrant and at least 94 fraction bits (error
// below 2^-70 of a quarter turn).  The top 64 fraction bits, centred to
// [-1/2, 1/2], are multiplied by pi/2 in fixed point and split into two
// floats.
constexpr Reduced reduce_payne_hanek(u32 ab) {
  const u32 m = (ab & kFracMask) | kHiddenBit;
  const int s = exponent_of(ab) - 23;
  const int first = s >= 2 ? s - 1 : 1;  // weight 2^-first: first bit used
  const int w = (first - 1) >> 5, sh = (first - 1) & 31;
  u32 win[3] = {};
  for (int i = 0; i < 3; ++i) {
    win[i] = kTwoOverPiWords[w + i] << sh;
    if (sh != 0) win[i] |= kTwoOverPiWords[w + i + 1] >> (32 - sh);
  }
  // prod = m * win (120 bits); ax * 2/pi = prod * 2^-fbits (mod 4).
  u32 prod[6] = {};
  u64 acc = u64(m) * win[2];
  prod[0] = u32(acc);
  acc = (acc >> 32) + u64(m) * win[1];
  prod[1] = u32(acc);
  acc = (acc >> 32) + u64(m) * win[0];
  prod[2] = u32(acc);
  prod[3] = u32(acc >> 32);
  const int fbits = first + 95 - s;
  u32 quadrant = u32(bits64_at(prod, fbits)) & 3u;
  u64 frac = bits64_at(prod, fbits - 64);  // quarter turns * 2^64
  const bool neg = (frac >> 63) != 0;
  if (neg) {
    quadrant += 1u;
    frac = 0u - frac;
  }
  const u64 h = mul_hi64(frac, kPio2Fixed62);  // |r| = h * 2^-62
  if (h == 0) return {0.0f, 0.0f, quadrant};
  const int lz = clz64(h);
  const u64 norm = h << lz;  // |r| = norm * 2^(-62-lz)
  const u32 top24 = u32(norm >> 40);
  const u32 next24 = u32(norm >> 16) & 0xffffffu;
  float hi = float_of((u32(1 - lz + 126) << 23) + top24);
  float lo = from_int(i32(next24)) * pow2(-46 - lz);
  if (neg) {
    hi = -hi;
    lo = -lo;
  }
  const Pair out = fast_two_sum(hi, lo);
  return {out.hi, out.lo, quadrant};
}

// Level 0: three 11-bit pieces and the float tail of the rest of pi/2 (one
// step fewer than level 1; docs/shims.md measures it against 2^-18).
constexpr Reduced reduce_cody_waite_min(float ax) {
  const auto [k, kf] = nearest_quadrant(ax);
  float r = ax - kf * kPio2Pieces[0];
  r = r - kf * kPio2Pieces[1];
  r = r - kf * kPio2Pieces[2];
  r = r - kf * kPio2MinTail;
  return {r, 0.0f, k};
}

template <int Level>
constexpr Reduced reduce_quadrant(u32 ab) {
  const float ax = float_of(ab);
  if (ab <= kPiOver4Bits) return {ax, 0.0f, 0u};
  if constexpr (Level == 0) {
    if (ab < kCodyWaiteLimitBits) return reduce_cody_waite_min(ax);
    return reduce_payne_hanek(ab);  // its lo is ignored by the level-0 kernels
  }
  if (ab < kCodyWaiteLimitBits) return reduce_cody_waite<(Level >= 2)>(ax);
  return reduce_payne_hanek(ab);
}

// ---------------------------------------------------------- sin/cos kernels

// sin r = r + r^3 S(r^2), cos r = 1 - r^2/2 + r^4 C(r^2) on |r| <= pi/4
// (fitted to 1.002 pi/4); see tools/shim_ulp/gen_coeffs.py.
inline constexpr float kSin9[4] = {-0x1.555556p-3f, 0x1.11110ep-7f,
                                   -0x1.a0139ap-13f, 0x1.6db9d4p-19f};
inline constexpr float kSin7[3] = {-0x1.555552p-3f, 0x1.110c1ep-7f,
                                   -0x1.9ac446p-13f};
inline constexpr float kCos8[3] = {0x1.555554p-5f, -0x1.6c12cap-10f,
                                   0x1.9bd444p-16f};
// Level 0: cos r = 1 + r^2 C(r^2), degree 6 (the whole of cos, -1/2 fitted too).
inline constexpr float kCosMin6[3] = {-0x1.fffff4p-2f, 0x1.554a38p-5f,
                                      -0x1.661878p-10f};

// sin(hi + lo), |lo| <= ulp(hi): sin(hi) + lo cos(hi), cos(hi) ~ 1 - z/2.
template <int Level>
constexpr float sin_kernel(float hi, float lo) {
  const float z = hi * hi;
  if constexpr (Level >= 2) {
    const float tail = z * (hi * horner(kSin9, z) - 0.5f * lo) + lo;
    return hi + tail;
  } else {
    return hi + hi * z * horner(kSin7, z);
  }
}

// cos(hi + lo): cos(hi) - lo sin(hi).  1 - z/2 is formed with its rounding
// error recovered ((1 - w) - z/2 is exact), then the small terms are added.
constexpr float cos_kernel(float hi, float lo) {
  const float z = hi * hi;
  const float hz = 0.5f * z;
  const float w = 1.0f - hz;
  return w + (((1.0f - w) - hz) + (z * z * horner(kCos8, z) - hi * lo));
}

// Level 0: cos(hi), lo ignored (it is at most half an ULP of hi).
constexpr float cos_kernel_min(float hi) {
  const float z = hi * hi;
  return 1.0f + z * horner(kCosMin6, z);
}

template <int Level>
constexpr float sin_from(const Reduced& red, u32 quadrant) {
  float v;
  if constexpr (Level == 0) {
    v = (quadrant & 1u) != 0 ? cos_kernel_min(red.hi) : sin_kernel<0>(red.hi, red.lo);
  } else {
    v = (quadrant & 1u) != 0 ? cos_kernel(red.hi, red.lo)
                             : sin_kernel<Level>(red.hi, red.lo);
  }
  return (quadrant & 2u) != 0 ? -v : v;
}

inline constexpr u32 kTinyTrigBits = 0x39800000u;  // 2^-12

template <int Level>
constexpr float sin(float x) {
  const u32 b = bits_of(x), ab = b & kAbsMask;
  if (ab >= kInfBits) return x - x;  // inf -> NaN, NaN stays NaN
  if (ab < kTinyTrigBits) return x;  // x^3/6 is below half an ULP
  const Reduced red = reduce_quadrant<Level>(ab);
  const float v = sin_from<Level>(red, red.quadrant);
  return (b & kSignBit) != 0 ? -v : v;
}

template <int Level>
constexpr float cos(float x) {
  const u32 ab = bits_of(x) & kAbsMask;
  if (ab >= kInfBits) return x - x;
  if (ab < kTinyTrigBits) return 1.0f;
  const Reduced red = reduce_quadrant<Level>(ab);
  return sin_from<Level>(red, red.quadrant + 1u);  // cos x = sin(x + pi/2)
}

// -------------------------------------------------------------------- atan

// atan t = t + t^3 A(t^2).
inline constexpr float kAtan13[6] = {-0x1.555556p-2f, 0x1.99997cp-3f,
                                     -0x1.248a16p-3f, 0x1.c57b76p-4f,
                                     -0x1.6142a6p-4f, 0x1.9d82b4p-5f};  // |t| <= tan(pi/8)
inline constexpr float kAtan13b[6] = {-0x1.555556p-2f, 0x1.999968p-3f,
                                      -0x1.248626p-3f, 0x1.c4f1ecp-4f,
                                      -0x1.5d79d8p-4f, 0x1.8b0b06p-5f};  // |t| <= 7/16
inline constexpr float kAtan11[5] = {-0x1.555554p-2f, 0x1.999730p-3f,
                                     -0x1.242026p-3f, 0x1.b80edep-4f,
                                     -0x1.0840fap-4f};  // |t| <= tan(pi/8)
inline constexpr float kAtan9[4] = {-0x1.555536p-2f, 0x1.996ba2p-3f,
                                    -0x1.1f366ap-3f, 0x1.5cfb58p-4f};  // |t| <= tan(pi/8)

// atan(c) as hi + lo for the reduction centres.
inline constexpr float kAtanHalfHi = 0x1.dac670p-2f, kAtanHalfLo = 0x1.586ed4p-28f;
inline constexpr float kPiOver4Hi = 0x1.921fb6p-1f, kPiOver4Lo = -0x1.777a5cp-26f;
inline constexpr float kAtan3HalfHi = 0x1.f730bep-1f, kAtan3HalfLo = -0x1.afc12cp-26f;
inline constexpr float kPiOver2Hi = 0x1.921fb6p+0f, kPiOver2Lo = -0x1.777a5cp-25f;
inline constexpr float kTanPiOver8 = 0x1.a8279ap-2f;
inline constexpr float kTan3PiOver8 = 0x1.3504f4p+1f;
inline constexpr u32 kTinyAtanBits = 0x39800000u;  // 2^-12: atan x rounds to x

// Level 2: five intervals, t = (a - c) / (1 + c a) with atan(c) in two
// parts, so |t| <= 7/16 and the polynomial needs degree 13.
constexpr float atan_accurate(float a) {
  float t, base_hi, base_lo;
  if (a < 0.4375f) {
    t = a;
    base_hi = 0.0f;
    base_lo = 0.0f;
  } else if (a < 0.6875f) {
    t = (2.0f * a - 1.0f) / (2.0f + a);  // (a - 1/2) / (1 + a/2), exact scalings
    base_hi = kAtanHalfHi;
    base_lo = kAtanHalfLo;
  } else if (a < 1.1875f) {
    t = (a - 1.0f) / (a + 1.0f);
    base_hi = kPiOver4Hi;
    base_lo = kPiOver4Lo;
  } else if (a < 2.4375f) {
    t = (a - 1.5f) / (1.0f + 1.5f * a);
    base_hi = kAtan3HalfHi;
    base_lo = kAtan3HalfLo;
  } else {
    t = -1.0f / a;  // atan a = pi/2 - atan(1/a); also right for a = inf
    base_hi = kPiOver2Hi;
    base_lo = kPiOver2Lo;
  }
  const float z = t * t;
  return base_hi + (t + (base_lo + t * z * horner(kAtan13b, z)));
}

// Level 1: a > 1 -> pi/2 - atan(1/a), then a > tan(pi/8) -> pi/4 + atan(t)
// with t = (a - 1) / (a + 1); degree-11 polynomial on |t| <= tan(pi/8).
constexpr float atan_fast(float a) {
  const bool inverted = a > 1.0f;
  if (inverted) a = 1.0f / a;
  float v;
  if (a > kTanPiOver8) {
    const float t = (a - 1.0f) / (a + 1.0f);
    const float z = t * t;
    v = kPiOver4Hi + (t + t * z * horner(kAtan11, z));
  } else {
    const float z = a * a;
    v = a + a * z * horner(kAtan11, z);
  }
  return inverted ? kPiOver2Hi - v : v;
}

// Level 0: one reduction step with at most one division: a > tan(3pi/8) ->
// pi/2 + atan(-1/a), a > tan(pi/8) -> pi/4 + atan((a - 1) / (a + 1));
// degree-9 polynomial on |t| <= tan(pi/8).
constexpr float atan_min(float a) {
  if (a <= kTanPiOver8) {
    const float z = a * a;
    return a + a * z * horner(kAtan9, z);
  }
  float t, base;
  if (a < kTan3PiOver8) {
    t = (a - 1.0f) / (a + 1.0f);
    base = kPiOver4Hi;
  } else {
    t = -1.0f / a;  // also right for a = inf
    base = kPiOver2Hi;
  }
  const float z = t * t;
  return base + (t + t * z * horner(kAtan9, z));
}

template <int Level>
constexpr float atan(float x) {
  const u32 b = bits_of(x), ab = b & kAbsMask;
  if (nan_bits(b)) return x + x;
  if (ab < kTinyAtanBits) return x;  // also keeps -0 and subnormals
  const float a = float_of(ab);
  const float v = Level >= 2 ? atan_accurate(a) : Level == 1 ? atan_fast(a) : atan_min(a);
  return (b & kSignBit) != 0 ? -v : v;
}

}  // namespace portable_detail
}  // namespace minrt

// exp, log, atan2: the general tracer's extra shims, built on the above.
#include "core/math/portable_exp_log.hpp"

namespace minrt {

template <int Level>
struct PortableFloatT {
  static_assert(Level >= 0 && Level <= 2,
                "levels: 0 = minimum for the course rules, 1 = fast, 2 = accurate");
  using real = float;
  static constexpr const char* name = Level == 2   ? "float/portable"
                                      : Level == 1 ? "float/portable-fast"
                                                   : "float/portable-min";
  static constexpr int level = Level;
  static constexpr real sqrt(real x) {
    return portable_detail::sqrt<Level>(x);
  }
  static constexpr real floor(real x) { return portable_detail::floor(x); }
  static constexpr real sin(real x) { return portable_detail::sin<Level>(x); }
  static constexpr real cos(real x) { return portable_detail::cos<Level>(x); }
  static constexpr real atan(real x) { return portable_detail::atan<Level>(x); }
  // Used by the general tracer only (portable_exp_log.hpp); min-rt needs none.
  static constexpr real exp(real x) { return portable_detail::exp(x); }
  static constexpr real log(real x) { return portable_detail::log(x); }
  static constexpr real atan2(real y, real x) { return portable_detail::atan2<Level>(y, x); }
  static constexpr real from_int(int32_t i) {
    return portable_detail::from_int(i);
  }
  static constexpr int32_t to_int(real x) {
    return portable_detail::to_int(x);
  }
};

using PortableFloat = PortableFloatT<2>;
using PortableFloatFast = PortableFloatT<1>;
using PortableFloatMin = PortableFloatT<0>;

static_assert(MathPolicy<PortableFloatT<0>>);
static_assert(MathPolicy<PortableFloatT<1>>);
static_assert(MathPolicy<PortableFloatT<2>>);
static_assert(SceneMathPolicy<PortableFloatT<2>>);

}  // namespace minrt
