// IEEE 754 binary32 arithmetic in integer code, for CPUs without an FPU
// (rv32i, rv32im, rv32e, Cortex-M without FPU). Every operation is exact:
// round to nearest even, subnormals produced and consumed (no flush to
// zero), overflow to infinity, the same bits as a hardware FPU for every
// non-NaN result. A NaN result is the canonical quiet NaN 0x7fc00000, as
// RISC-V F computes it (and the rv32 libgcc this replaces).
//
// Each operation takes and returns the float's bits. The fast path (normal
// operands, normal result) stays short and branches out to a general path
// for zeros, subnormals, infinities, NaN, overflow and underflow.
//
// The wide products and quotients of the mantissas come from a template
// parameter, so the host tests check every variant:
//   Mul64Native / DivNative: the compiler's 32x32->64 multiply and 32-bit
//     divide (one mul + mulhu, divu/remu on a CPU with M);
//   MulQuarterSquares / DivShift: no multiply or divide instruction
//     (rv32i): a 24x24 product from a table of quarter squares
//     (a b = floor((a+b)^2/4) - floor((a-b)^2/4), exact for integers), and
//     restoring division one bit per step.
// Integer code only: no float type appears, so the operations cannot call
// themselves when they implement the compiler's float library calls.
#pragma once

#include <stdint.h>

#include "core/math/binary32_bits.hpp"

namespace minrt::soft_float {

using u32 = uint32_t;
using i32 = int32_t;
using u64 = uint64_t;

using binary32::kAbsMask;
using binary32::kFracMask;
using binary32::kHiddenBit;
using binary32::kInfBits;
using binary32::kQuietNaN;
using binary32::kSignBit;


#if defined(__GNUC__)
#define MINRT_SOFT_NOINLINE __attribute__((noinline))
#define MINRT_SOFT_INLINE inline __attribute__((always_inline))
#else
#define MINRT_SOFT_NOINLINE
#define MINRT_SOFT_INLINE inline
#endif

// Leading zeros by binary search (a count instruction is not in RV32I/M).
MINRT_SOFT_INLINE constexpr int clz(u32 v) {
  if (v == 0) return 32;
  int n = 0;
  if ((v & 0xffff0000u) == 0) { n += 16; v <<= 16; }
  if ((v & 0xff000000u) == 0) { n += 8; v <<= 8; }
  if ((v & 0xf0000000u) == 0) { n += 4; v <<= 4; }
  if ((v & 0xc0000000u) == 0) { n += 2; v <<= 2; }
  if ((v & 0x80000000u) == 0) { n += 1; }
  return n;
}

// v >> s with every bit shifted out or-ed into bit 0 (the sticky bit),
// for any s >= 0.
MINRT_SOFT_INLINE constexpr u32 shift_right_sticky(u32 v, u32 s) {
  if (s >= 31) return v != 0 ? 1u : 0u;
  const u32 kept = v >> s;
  return kept | ((kept << s) != v ? 1u : 0u);
}

// ------------------------------------------------------------ wide products

// The high and low words of a 32x32 product of x = X << 8 and y = Y << 8,
// X and Y 24-bit mantissas with the hidden bit set.
struct Wide {
  u32 hi, lo;
};

struct Mul64Native {
  static constexpr Wide mul(u32 x, u32 y) {
    const u64 p = u64(x) * u64(y);
    return {u32(p >> 32), u32(p)};
  }
};

// floor(n^2 / 4) for -2^12 < n < 2^13: the sums and differences of two
// 12-bit halves, differences indexed directly (no absolute value).
inline constexpr int kQuarterSquaresLow = 4095;
struct QuarterSquares {
  u32 v[kQuarterSquaresLow + 8192];
  constexpr QuarterSquares() : v{} {
    // n^2/4 by additions only: floor(n^2/4) - floor((n-1)^2/4) = floor(n/2).
    u32 q = 0;
    for (u32 n = 0; n < 8192; ++n) {
      if (n != 0) q += n >> 1;
      v[kQuarterSquaresLow + n] = q;
      if (n != 0 && n <= u32(kQuarterSquaresLow)) v[kQuarterSquaresLow - n] = q;
    }
  }
};
inline constexpr QuarterSquares kQuarterSquares{};

struct MulQuarterSquares {
  static constexpr Wide mul(u32 x, u32 y) {
    // The 12-bit halves of the 24-bit mantissas x >> 8 and y >> 8.
    const u32 a1 = x >> 20, a0 = (x << 12) >> 20;
    const i32 b1 = i32(y >> 20), b0 = i32((y << 12) >> 20);
    // a_i b_j = t[a_i + b_j] - t[a_i - b_j]: one row pointer per half of a,
    // each half of b scaled once for the four lookups that use it.
    const u32* t1 = kQuarterSquares.v + kQuarterSquaresLow + a1;
    const u32* t0 = kQuarterSquares.v + kQuarterSquaresLow + a0;
    const u32 p11 = t1[b1] - t1[-b1], p00 = t0[b0] - t0[-b0];
    const u32 mid = (t1[b0] - t1[-b0]) + (t0[b1] - t0[-b1]);  // < 2^25
    // P = p11 2^24 + mid 2^12 + p00 (48 bits); x y = P 2^16, so the high
    // word is P >> 16 and the low word P's low 16 bits, shifted up.
    const u32 hi = (p11 << 8) + ((mid + (p00 >> 12)) >> 4);
    const u32 lo = ((mid << 12) + p00) << 16;
    return {hi, lo};
  }
};

// --------------------------------------------------------------- quotients

// floor(n 2^30 / d) for 2^23 <= d < 2^24 and d <= n < 2 d, in [2^30, 2^31),
// with bit 0 set when the division leaves a remainder.
struct DivNative {
  static constexpr u32 quotient(u32 n, u32 d) {
    // Long division by 7, 8, 8 and 7 bits: each partial numerator stays
    // below 2^32 because the remainder is below 2^24.
    u32 q = (n << 7) / d, r = (n << 7) % d;
    q = (q << 8) | ((r << 8) / d), r = (r << 8) % d;
    q = (q << 8) | ((r << 8) / d), r = (r << 8) % d;
    q = (q << 7) | ((r << 7) / d), r = (r << 7) % d;
    return q | (r != 0 ? 1u : 0u);
  }
};

// 26 quotient bits (the 24 of the mantissa, a rounding bit and one more),
// placed like DivNative's 31 with the sticky bit at 0: rounding sees the
// same result.
struct DivShift {
  static constexpr u32 quotient(u32 n, u32 d) {
    u32 q = 0, r = n;
    for (int i = 0; i < 26; ++i) {
      q <<= 1;
      if (r >= d) {
        r -= d;
        q |= 1u;
      }
      r <<= 1;
    }
    return (q << 5) | (r != 0 ? 1u : 0u);
  }
};

// ------------------------------------------------------------------ rounding

// The float sign | m 2^(e - 157): m has its leading one at bit 30 (or is
// smaller when e <= 1, a subnormal result), bits 6..0 are the guard bits and
// bit 0 also holds the sticky or of everything below. Rounds to nearest
// even; overflow gives infinity, e < 1 a subnormal (or zero).
MINRT_SOFT_INLINE constexpr u32 round_pack_general(u32 sign, i32 e, u32 m) {
  if (e >= 255) return sign | kInfBits;
  if (e < 1) {
    m = shift_right_sticky(m, u32(1 - e));
    e = 1;
  }
  const u32 r = (m + 0x3fu + ((m >> 7) & 1u)) >> 7;
  // The mantissa's hidden bit adds one to the exponent field, so a mantissa
  // rounded up to 2^24 carries into the exponent by itself, and a subnormal
  // rounded up to 2^23 becomes the least normal.
  return sign | ((u32(e - 1) << 23) + r);
}

MINRT_SOFT_INLINE constexpr u32 round_pack(u32 sign, i32 e, u32 m) {
  if (u32(e - 1) >= 254u) return round_pack_general(sign, e, m);
  return sign | ((u32(e - 1) << 23) + ((m + 0x3fu + ((m >> 7) & 1u)) >> 7));
}

// A finite non-zero magnitude as m 2^(e - 150), m in [2^23, 2^24)
// (subnormals normalized, their e below 1).
struct Unpacked {
  i32 e;
  u32 m;
};
constexpr Unpacked unpack(u32 ax) {
  const i32 e = i32(ax >> 23);
  if (e != 0) return {e, (ax & kFracMask) | kHiddenBit};
  const int s = clz(ax) - 8;
  return {1 - s, ax << s};
}

// ------------------------------------------------------------- add, subtract

constexpr u32 add_general(u32 a, u32 b) {
  u32 ax = a & kAbsMask, bx = b & kAbsMask;
  if (ax < bx) {
    const u32 t = a; a = b; b = t;
    const u32 tx = ax; ax = bx; bx = tx;
  }
  if (ax >= kInfBits) {
    if (ax > kInfBits) return kQuietNaN;
    if (bx == kInfBits && ((a ^ b) & kSignBit) != 0) return kQuietNaN;  // inf - inf
    return a;
  }
  if (bx == 0) return ax == 0 ? (a & b) : a;  // -0 + -0 = -0, else +0
  const i32 ea = i32(ax >> 23), eb = i32(bx >> 23);
  // Subnormals: no hidden bit, exponent field 0 weighs like 1.
  u32 ma = ((ax & kFracMask) | (ea != 0 ? kHiddenBit : 0u)) << 7;
  u32 mb = ((bx & kFracMask) | (eb != 0 ? kHiddenBit : 0u)) << 7;
  i32 e = ea != 0 ? ea : 1;
  mb = shift_right_sticky(mb, u32(e - (eb != 0 ? eb : 1)));
  const u32 sign = a & kSignBit;
  u32 m;
  if (((a ^ b) & kSignBit) == 0) {
    m = ma + mb;
    if ((m & kSignBit) != 0) {
      m = (m >> 1) | (m & 1u);
      ++e;
    }
  } else {
    m = ma - mb;
    if (m == 0) return 0;  // x - x = +0
    const int s = clz(m) - 1;
    m <<= s;
    e -= s;
  }
  return round_pack_general(sign, e, m);
}

// For |a| >= |b|: zeros, subnormals, infinities and NaN go to add_general
// (the larger decides infinity and NaN, the smaller zero and subnormal).
MINRT_SOFT_INLINE constexpr bool add_ordered_needs_general(u32 a, u32 b) {
  return (a << 1) >= (kInfBits << 1) || (b << 1) < (kHiddenBit << 1);
}

// a + b for normal finite a and b with |a| >= |b|.
MINRT_SOFT_INLINE constexpr u32 add_ordered(u32 a, u32 b) {
  const u32 ea = a << 1 >> 24, d = ea - (b << 1 >> 24);
  const u32 ma = ((a << 8) | kSignBit) >> 1;  // hidden bit at 30, 7 guard bits
  const u32 mb = shift_right_sticky(((b << 8) | kSignBit) >> 1, d);
  const u32 top = a >> 23;                 // sign and exponent field
  u32 m;
  if (((a ^ b) & kSignBit) == 0) {
    m = ma + mb;
    if ((m & kSignBit) != 0) {  // carry: one more exponent
      m = (m >> 1) | (m & 1u);
      if (ea == 254) return (a & kSignBit) | kInfBits;
      return (top << 23) + ((m + 0x3fu + ((m >> 7) & 1u)) >> 7);
    }
  } else {
    m = ma - mb;
    if (m < 0x40000000u) {  // cancellation: exact when it is more than one bit
      if (m == 0) return 0;
      const int s = clz(m) - 1;
      return round_pack_general(a & kSignBit, i32(ea) - s, m << s);
    }
  }
  return ((top - 1) << 23) + ((m + 0x3fu + ((m >> 7) & 1u)) >> 7);
}

// Puts the operand of larger magnitude first.
MINRT_SOFT_INLINE constexpr void order_for_add(u32& a, u32& b) {
  if ((a << 1) < (b << 1)) {
    const u32 t = a;
    a = b;
    b = t;
  }
}

// For |a| >= |b|, the general case the renderer meets most (x + 0): b is
// a zero and a neither zero nor NaN, so a + b = a.
MINRT_SOFT_INLINE constexpr bool add_ordered_gives_a(u32 a, u32 b) {
  return (b << 1) == 0 && (a << 1) - 1u < (kInfBits << 1);
}

MINRT_SOFT_INLINE constexpr u32 add(u32 a, u32 b) {
  order_for_add(a, b);
  if (add_ordered_needs_general(a, b)) return add_ordered_gives_a(a, b) ? a : add_general(a, b);
  return add_ordered(a, b);
}

MINRT_SOFT_INLINE constexpr u32 sub(u32 a, u32 b) { return add(a, b ^ kSignBit); }

// ------------------------------------------------------------------ multiply

template <class Mul>
constexpr u32 mul_general(u32 a, u32 b) {
  const u32 sign = (a ^ b) & kSignBit;
  const u32 ax = a & kAbsMask, bx = b & kAbsMask;
  if ((ax == 0 || bx == 0) && ax < kInfBits && bx < kInfBits) return sign;  // the common case here
  if (ax > kInfBits || bx > kInfBits) return kQuietNaN;
  if (ax == kInfBits || bx == kInfBits) return (ax == 0 || bx == 0) ? kQuietNaN : (sign | kInfBits);
  const Unpacked ua = unpack(ax), ub = unpack(bx);
  const Wide p = Mul::mul(ua.m << 8, ub.m << 8);
  i32 e = ua.e + ub.e - 126;
  u32 m = p.hi;  // leading one at 31 or 30
  const u32 sticky = p.lo != 0 ? 1u : 0u;
  if ((m & kSignBit) != 0) {
    m = (m >> 1) | (m & 1u) | sticky;
  } else {
    m |= sticky;
    --e;
  }
  return round_pack(sign, e, m);
}

// Written with the exponent fields mul_normal uses, so that the compiler
// extracts them once.
MINRT_SOFT_INLINE constexpr bool mul_needs_general(u32 a, u32 b) {
  return ((a >> 23) & 0xffu) - 1u >= 254u || ((b >> 23) & 0xffu) - 1u >= 254u;
}

// a b for normal finite a and b.
template <class Mul>
MINRT_SOFT_INLINE constexpr u32 mul_normal(u32 a, u32 b) {
  const Wide p = Mul::mul((a << 8) | kSignBit, (b << 8) | kSignBit);
  i32 e = i32(((a >> 23) & 0xffu) + ((b >> 23) & 0xffu)) - 126;
  u32 m = p.hi;
  const u32 sticky = p.lo != 0 ? 1u : 0u;
  if ((m & kSignBit) != 0) {
    m = (m >> 1) | (m & 1u) | sticky;
  } else {
    m |= sticky;
    --e;
  }
  return round_pack((a ^ b) & kSignBit, e, m);
}

// The general case the renderer meets most: a zero times a finite number.
MINRT_SOFT_INLINE constexpr bool mul_gives_zero(u32 a, u32 b) {
  const u32 ax = a << 1, bx = b << 1;
  return (ax == 0 && bx < (kInfBits << 1)) || (bx == 0 && ax < (kInfBits << 1));
}

template <class Mul>
MINRT_SOFT_INLINE constexpr u32 mul(u32 a, u32 b) {
  if (mul_needs_general(a, b)) return mul_gives_zero(a, b) ? (a ^ b) & kSignBit : mul_general<Mul>(a, b);
  return mul_normal<Mul>(a, b);
}

// -------------------------------------------------------------------- divide

template <class Div>
MINRT_SOFT_INLINE constexpr u32 div(u32 a, u32 b) {
  const u32 sign = (a ^ b) & kSignBit;
  const u32 ax = a & kAbsMask, bx = b & kAbsMask;
  const u32 ea = ax >> 23, eb = bx >> 23;
  Unpacked ua, ub;
  if (ea - 1u < 254u && eb - 1u < 254u) {
    ua = {i32(ea), (ax & kFracMask) | kHiddenBit};
    ub = {i32(eb), (bx & kFracMask) | kHiddenBit};
  } else {
    if (ax > kInfBits || bx > kInfBits) return kQuietNaN;
    if (ax == kInfBits) return bx == kInfBits ? kQuietNaN : (sign | kInfBits);
    if (bx == kInfBits) return sign;
    if (bx == 0) return ax == 0 ? kQuietNaN : (sign | kInfBits);
    if (ax == 0) return sign;
    ua = unpack(ax);
    ub = unpack(bx);
  }
  i32 e = ua.e - ub.e + 126;
  u32 n = ua.m;
  if (n < ub.m) {
    n <<= 1;
    --e;
  }
  // quotient in [2^30, 2^31): the value is (q / 2^30) 2^(e + 1 - 127).
  const u32 q = Div::quotient(n, ub.m);
  return round_pack(sign, e + 1, q);
}

// --------------------------------------------------------------- square root

// Correctly rounded (there are no ties: a square root of a float is never
// halfway between two floats). Digit by digit, two radicand bits a step.
constexpr u32 sqrt(u32 a) {
  const u32 ax = a & kAbsMask;
  if (ax > kInfBits) return kQuietNaN;
  if (ax == 0) return a;  // +0, -0
  if ((a & kSignBit) != 0) return kQuietNaN;
  if (ax == kInfBits) return a;
  Unpacked u = unpack(ax);
  // value = m 2^(e - 150); make e - 150 even, so sqrt = sqrt(m') 2^((e-150)/2).
  i32 e = u.e - 150;
  u32 m = u.m;
  if ((e & 1) != 0) {
    m <<= 1;
    --e;
  }
  // m in [2^23, 2^25): r = floor(sqrt(m 2^26)) in [2^24, 2^26) holds the
  // 24 mantissa bits and at least one guard bit. The radicand's two-bit
  // digits enter from the top of x (m's 13 digit pairs, then zeros); the
  // remainder stays below 2^27, so everything fits in 32 bits.
  u32 x = m << 6, root = 0, rem = 0;
  for (int i = 0; i < 26; ++i) {
    rem = (rem << 2) | (x >> 30);
    x <<= 2;
    root <<= 1;
    const u32 t = (root << 1) | 1u;
    if (rem >= t) {
      rem -= t;
      root |= 1u;
    }
  }
  const u32 rem_nonzero = rem != 0 ? 1u : 0u;
  const u32 res = root;
  // sqrt(value) = r 2^((e - 26)/2); r in [2^24, 2^26). Place its leading
  // one at bit 30 with sticky = remainder.
  u32 r = u32(res);
  i32 ee = (e - 26) / 2;  // value = r 2^ee
  int s = clz(r) - 1;
  r <<= s;  // r 2^ee = (r << s) 2^(ee - s)
  r |= rem_nonzero;
  // (r<<s) with leading one at 30: float exponent field = ee - s + 30 + 127.
  return round_pack(0, ee - s + 157, r);
}

// ---------------------------------------------------------------- comparisons

constexpr bool is_nan(u32 a) { return (a & kAbsMask) > kInfBits; }
constexpr bool unordered(u32 a, u32 b) { return is_nan(a) || is_nan(b); }

// -1, 0, 1 for a < b, a == b, a > b; `unord` when either is NaN.
MINRT_SOFT_INLINE constexpr int compare(u32 a, u32 b, int unord) {
  const u32 ax = a << 1, bx = b << 1;  // magnitudes, shifted
  if (ax > (kInfBits << 1) || bx > (kInfBits << 1)) return unord;
  if ((ax | bx) == 0) return 0;  // +0 == -0
  // Sign and magnitude order as two's complement integers, reversed when
  // both are negative.
  const i32 sa = i32(a), sb = i32(b);
  if ((sa & sb) < 0) return int(sb > sa) - int(sb < sa);
  return int(sa > sb) - int(sa < sb);
}

// ---------------------------------------------------------------- conversions

// int32 -> float, round to nearest even.
constexpr u32 from_int(i32 i) {
  const u32 sign = i < 0 ? kSignBit : 0u;
  const u32 mag = i < 0 ? 0u - u32(i) : u32(i);
  if (mag == 0) return 0;
  const int s = clz(mag);
  // leading one to bit 31, then to bit 30 with sticky
  const u32 m = shift_right_sticky(mag << s, 1);
  return round_pack(sign, 158 - s, m);
}

constexpr u32 from_uint(u32 mag) {
  if (mag == 0) return 0;
  const int s = clz(mag);
  const u32 m = shift_right_sticky(mag << s, 1);
  return round_pack(0, 158 - s, m);
}

// float -> int32, truncation toward zero; out of range and NaN: saturated
// (NaN to INT32_MAX), as RISC-V fcvt.w.s.
constexpr i32 to_int(u32 a) {
  const u32 ax = a & kAbsMask;
  if (ax > kInfBits) return INT32_MAX;
  const i32 e = i32(ax >> 23) - 127;
  if (e < 0) return 0;
  const bool neg = (a & kSignBit) != 0;
  if (e >= 31) return neg ? INT32_MIN : INT32_MAX;
  const u32 m = (ax & kFracMask) | kHiddenBit;
  const u32 mag = e >= 23 ? m << (e - 23) : m >> (23 - e);
  return neg ? i32(0u - mag) : i32(mag);
}

// float -> uint32, truncation; negative gives 0, too large and NaN give
// UINT32_MAX (fcvt.wu.s).
constexpr u32 to_uint(u32 a) {
  const u32 ax = a & kAbsMask;
  if (ax > kInfBits) return UINT32_MAX;
  const i32 e = i32(ax >> 23) - 127;
  if (e < 0) return 0;
  if ((a & kSignBit) != 0) return 0;
  if (e >= 32) return UINT32_MAX;
  const u32 m = (ax & kFracMask) | kHiddenBit;
  return e >= 23 ? m << (e - 23) : m >> (23 - e);
}

}  // namespace minrt::soft_float
