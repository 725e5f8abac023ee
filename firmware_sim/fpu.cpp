#include "fpu.hpp"

#include <cfenv>
#include <utility>

namespace fwsim::fpu {
namespace {

constexpr uint32_t kSign = 0x80000000u;
constexpr uint32_t kInf = 0x7f800000u;

bool is_inf(uint32_t a) { return (a & 0x7fffffffu) == kInf; }
bool is_zero(uint32_t a) { return (a & 0x7fffffffu) == 0; }
bool sign_of(uint32_t a) { return a >> 31; }

// Finite nonzero value = sig * 2^exp with bit 23 of sig set.
struct Unpacked {
  bool sign;
  int exp;
  uint32_t sig;
};

Unpacked unpack(uint32_t a) {
  Unpacked u{sign_of(a), 0, a & 0x7fffffu};
  int e = (a >> 23) & 0xff;
  if (e == 0) {
    int lz = __builtin_clz(u.sig) - 8;  // bring the leading one to bit 23
    u.sig <<= lz;
    u.exp = -149 - lz;
  } else {
    u.sig |= 0x800000u;
    u.exp = e - 150;
  }
  return u;
}

// Whether to add one unit at the kept LSB, given the discarded part `rem`
// compared against `half` (the weight of the first discarded bit).
bool round_up(unsigned rm, bool sign, uint64_t kept, uint64_t rem, uint64_t half) {
  if (rem == 0) return false;
  switch (rm) {
    case RNE: return rem > half || (rem == half && (kept & 1));
    case RTZ: return false;
    case RDN: return sign;
    case RUP: return !sign;
    default: return rem >= half;  // RMM
  }
}

// Split sig into sig >> n and the discarded bits; n may exceed 63, in which
// case the discarded part is reported as "less than half, nonzero".
void split(uint64_t sig, int n, uint64_t& kept, uint64_t& rem, uint64_t& half) {
  if (n == 0) { kept = sig; rem = 0; half = 1; return; }
  if (n < 64) {
    kept = sig >> n;
    rem = sig & ((uint64_t{1} << n) - 1);
    half = uint64_t{1} << (n - 1);
  } else {
    kept = 0;
    half = uint64_t{1} << 63;
    rem = n == 64 ? sig : (sig != 0);
  }
}

uint32_t overflow_result(bool sign, unsigned rm) {
  const uint32_t s = sign ? kSign : 0;
  const bool to_inf = rm == RNE || rm == RMM || (rm == RDN && sign) || (rm == RUP && !sign);
  return s | (to_inf ? kInf : 0x7f7fffffu);
}

// Round value = sig * 2^(e-63), bit 63 of sig set, to single precision.
uint32_t round_pack(bool sign, int e, uint64_t sig, unsigned rm, uint8_t& flags) {
  int biased = e + 127;
  const uint32_t s = sign ? kSign : 0;
  uint64_t kept, rem, half;
  if (biased < 1) {
    split(sig, 40 + 1 - biased, kept, rem, half);
    const bool inexact = rem != 0;
    kept += round_up(rm, sign, kept, rem, half);
    if (inexact) {
      // Tininess is detected after rounding (as RISC-V specifies): the value
      // is not tiny if rounding at normal precision reaches 2^-126.
      bool tiny = true;
      if (biased == 0) {
        uint64_t k2, r2, h2;
        split(sig, 40, k2, r2, h2);
        tiny = k2 + round_up(rm, sign, k2, r2, h2) < (uint64_t{1} << 24);
      }
      flags |= NX | (tiny ? UF : 0);
    }
    return s | static_cast<uint32_t>(kept);  // kept == 2^23 encodes the smallest normal
  }
  split(sig, 40, kept, rem, half);
  if (rem) flags |= NX;
  kept += round_up(rm, sign, kept, rem, half);
  if (kept == (uint64_t{1} << 24)) {
    kept >>= 1;
    ++biased;
  }
  if (biased >= 255) {
    flags |= OF | NX;
    return overflow_result(sign, rm);
  }
  return s | static_cast<uint32_t>(biased) << 23 | (static_cast<uint32_t>(kept) & 0x7fffffu);
}

// value = sig * 2^exp, sig != 0.
uint32_t normalize_round(bool sign, int exp, uint64_t sig, unsigned rm, uint8_t& flags) {
  int lz = __builtin_clzll(sig);
  return round_pack(sign, exp + 63 - lz, sig << lz, rm, flags);
}

uint32_t nan_result(uint32_t a, uint32_t b, uint8_t& flags) {
  if (is_snan(a) || is_snan(b)) flags |= NV;
  return kCanonicalNaN;
}

uint32_t zero_sum_sign(bool sa, bool sb, unsigned rm) {
  if (sa == sb) return sa ? kSign : 0;
  return rm == RDN ? kSign : 0;
}

unsigned clz128(unsigned __int128 v) {
  uint64_t hi = static_cast<uint64_t>(v >> 64);
  return hi ? __builtin_clzll(hi) : 64 + __builtin_clzll(static_cast<uint64_t>(v));
}

// Adds two finite values given as (sign, 128-bit magnitude, exponent of its
// LSB); exact except for bits shifted below the larger operand's LSB, which
// are kept as a sticky bit.
uint32_t add_wide(bool sx, unsigned __int128 x, int ex, bool sy, unsigned __int128 y, int ey,
                  unsigned rm, uint8_t& flags) {
  if (ex < ey) {
    std::swap(sx, sy);
    std::swap(x, y);
    std::swap(ex, ey);
  }
  // Bring x down to y's exponent if it has headroom, else jam y right.
  unsigned room = clz128(x) > 2 ? clz128(x) - 2 : 0;
  int d = ex - ey;
  int up = d < static_cast<int>(room) ? d : static_cast<int>(room);
  x <<= up;
  ex -= up;
  d -= up;
  if (d > 0) {
    if (d >= 127) y = y != 0;
    else y = (y >> d) | ((y & ((static_cast<unsigned __int128>(1) << d) - 1)) != 0);
  }
  bool sr = sx;
  unsigned __int128 r;
  if (sx == sy) {
    r = x + y;
  } else if (x >= y) {
    r = x - y;
  } else {
    r = y - x;
    sr = sy;
  }
  if (r == 0) return zero_sum_sign(sx, sy, rm);
  unsigned lz = clz128(r);
  r <<= lz;
  uint64_t hi = static_cast<uint64_t>(r >> 64) | (static_cast<uint64_t>(r) != 0);
  return round_pack(sr, ex + 127 - static_cast<int>(lz), hi, rm, flags);
}

uint64_t isqrt(uint64_t n, bool& exact) {
  uint64_t r = 0, bit = uint64_t{1} << 62;
  while (bit > n) bit >>= 2;
  while (bit) {
    if (n >= r + bit) {
      n -= r + bit;
      r = (r >> 1) + bit;
    } else {
      r >>= 1;
    }
    bit >>= 2;
  }
  exact = n == 0;
  return r;
}

uint32_t to_integer(uint32_t a, unsigned rm, uint8_t& flags, bool is_signed) {
  const uint32_t pos_max = is_signed ? 0x7fffffffu : 0xffffffffu;
  const uint32_t neg_max = is_signed ? 0x80000000u : 0u;
  if (is_nan(a)) {
    flags |= NV;
    return pos_max;
  }
  if (is_inf(a)) {
    flags |= NV;
    return sign_of(a) ? neg_max : pos_max;
  }
  if (is_zero(a)) return 0;
  Unpacked u = unpack(a);
  uint64_t mag;
  bool inexact = false;
  if (u.exp >= 0) {
    if (u.exp > 31) {
      flags |= NV;
      return u.sign ? neg_max : pos_max;
    }
    mag = static_cast<uint64_t>(u.sig) << u.exp;
  } else {
    uint64_t rem, half;
    split(u.sig, -u.exp, mag, rem, half);
    inexact = rem != 0;
    mag += round_up(rm, u.sign, mag, rem, half);
  }
  const uint64_t limit = u.sign ? (is_signed ? 0x80000000ull : 0ull) : pos_max;
  if (mag > limit) {
    flags |= NV;
    return u.sign ? neg_max : pos_max;
  }
  if (inexact) flags |= NX;
  return u.sign ? static_cast<uint32_t>(-static_cast<int64_t>(mag)) : static_cast<uint32_t>(mag);
}

}  // namespace

uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(a, b, flags);
  if (is_inf(a) || is_inf(b)) {
    if (is_inf(a) && is_inf(b) && sign_of(a) != sign_of(b)) {
      flags |= NV;
      return kCanonicalNaN;
    }
    return is_inf(a) ? a : b;
  }
  if (is_zero(a) && is_zero(b)) return zero_sum_sign(sign_of(a), sign_of(b), rm);
  if (is_zero(a)) return b;
  if (is_zero(b)) return a;
  Unpacked x = unpack(a), y = unpack(b);
  return add_wide(x.sign, x.sig, x.exp, y.sign, y.sig, y.exp, rm, flags);
}

uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) {
  return add(a, is_nan(b) ? b : b ^ kSign, rm, flags);
}

uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(a, b, flags);
  const uint32_t s = (a ^ b) & kSign;
  if (is_inf(a) || is_inf(b)) {
    if (is_zero(a) || is_zero(b)) {
      flags |= NV;
      return kCanonicalNaN;
    }
    return s | kInf;
  }
  if (is_zero(a) || is_zero(b)) return s;
  Unpacked x = unpack(a), y = unpack(b);
  return normalize_round(s != 0, x.exp + y.exp, uint64_t{x.sig} * y.sig, rm, flags);
}

uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) return nan_result(a, b, flags);
  const uint32_t s = (a ^ b) & kSign;
  if (is_inf(a)) {
    if (is_inf(b)) {
      flags |= NV;
      return kCanonicalNaN;
    }
    return s | kInf;
  }
  if (is_inf(b)) return s;
  if (is_zero(b)) {
    if (is_zero(a)) {
      flags |= NV;
      return kCanonicalNaN;
    }
    flags |= DZ;
    return s | kInf;
  }
  if (is_zero(a)) return s;
  Unpacked x = unpack(a), y = unpack(b);
  const uint64_t num = uint64_t{x.sig} << 40;
  uint64_t q = num / y.sig;
  q |= (num % y.sig) != 0;  // sticky: q has >= 40 bits, far below the rounding point
  return normalize_round(s != 0, x.exp - y.exp - 40, q, rm, flags);
}

uint32_t sqrt(uint32_t a, unsigned rm, uint8_t& flags) {
  if (is_nan(a)) return nan_result(a, a, flags);
  if (is_zero(a)) return a;
  if (sign_of(a)) {
    flags |= NV;
    return kCanonicalNaN;
  }
  if (is_inf(a)) return a;
  Unpacked x = unpack(a);
  uint64_t sig = x.sig;
  int e = x.exp;
  if (e & 1) {
    sig <<= 1;
    --e;
  }
  bool exact;
  uint64_t r = isqrt(sig << 38, exact);  // sqrt(sig * 2^38) = sqrt(sig) * 2^19
  r = (r << 1) | !exact;                 // one more bit so the sticky sits below it
  return normalize_round(false, e / 2 - 20, r, rm, flags);
}

uint32_t fma(uint32_t a, uint32_t b, uint32_t c, bool negate_product, bool negate_addend,
             unsigned rm, uint8_t& flags) {
  const bool ps = sign_of(a) ^ sign_of(b) ^ negate_product;
  const bool cs = sign_of(c) ^ negate_addend;
  // RISC-V: inf * 0 is invalid even when the addend is a quiet NaN.
  if ((is_inf(a) && is_zero(b)) || (is_zero(a) && is_inf(b))) {
    flags |= NV;
    return kCanonicalNaN;
  }
  if (is_nan(a) || is_nan(b) || is_nan(c)) {
    if (is_snan(a) || is_snan(b) || is_snan(c)) flags |= NV;
    return kCanonicalNaN;
  }
  if (is_inf(a) || is_inf(b)) {
    if (is_inf(c) && cs != ps) {
      flags |= NV;
      return kCanonicalNaN;
    }
    return (ps ? kSign : 0) | kInf;
  }
  if (is_inf(c)) return (cs ? kSign : 0) | kInf;
  const uint32_t c_signed = (c & 0x7fffffffu) | (cs ? kSign : 0);
  if (is_zero(a) || is_zero(b)) {
    if (is_zero(c)) return zero_sum_sign(ps, cs, rm);
    return c_signed;
  }
  Unpacked x = unpack(a), y = unpack(b);
  const uint64_t p = uint64_t{x.sig} * y.sig;
  if (is_zero(c)) return normalize_round(ps, x.exp + y.exp, p, rm, flags);
  Unpacked z = unpack(c_signed);
  return add_wide(ps, p, x.exp + y.exp, cs, z.sig, z.exp, rm, flags);
}

uint32_t to_int32(uint32_t a, unsigned rm, uint8_t& flags) { return to_integer(a, rm, flags, true); }
uint32_t to_uint32(uint32_t a, unsigned rm, uint8_t& flags) { return to_integer(a, rm, flags, false); }

uint32_t from_int32(int32_t v, unsigned rm, uint8_t& flags) {
  if (v == 0) return 0;
  const uint64_t mag = v < 0 ? -static_cast<int64_t>(v) : v;
  return normalize_round(v < 0, 0, mag, rm, flags);
}

uint32_t from_uint32(uint32_t v, unsigned rm, uint8_t& flags) {
  if (v == 0) return 0;
  return normalize_round(false, 0, v, rm, flags);
}

uint8_t take_host_flags() {
  const int fe = std::fetestexcept(FE_ALL_EXCEPT);
  uint8_t f = 0;
  if (fe & FE_INEXACT) f |= NX;
  if (fe & FE_UNDERFLOW) f |= UF;
  if (fe & FE_OVERFLOW) f |= OF;
  if (fe & FE_DIVBYZERO) f |= DZ;
  if (fe & FE_INVALID) f |= NV;
  if (fe) std::feclearexcept(FE_ALL_EXCEPT);
  return f;
}

void clear_host_flags() { std::feclearexcept(FE_ALL_EXCEPT); }

}  // namespace fwsim::fpu
