// Number tokens with the original runtime's semantics: read_int follows
// OCaml's int_of_string, read_float follows float_of_string (underscores
// ignored, then strtod, which rounds correctly). Integer-only so the same
// conversion runs bit for bit on the host and on a CPU without an FPU.
#pragma once

#include <stdint.h>

#include "core/base/bigint.hpp"
#include "core/base/bit_cast.hpp"

namespace minrt {

enum class NumberStatus {
  kOk,
  kInvalid,      // not a number of the expected kind
  kOutOfRange,   // integer outside OCaml's 63-bit int
  kNonFinite,    // inf, nan, or a float too large for the type
};

// IEEE binary formats the renderer can run in.
template <class R>
struct IeeeFormat;
template <>
struct IeeeFormat<double> {
  using Bits = uint64_t;
  static constexpr int kPrecision = 53;  // significand bits incl. the hidden one
  static constexpr int kBias = 1023;
  static constexpr int kMaxBiased = 2046;
};
template <>
struct IeeeFormat<float> {
  using Bits = uint32_t;
  static constexpr int kPrecision = 24;
  static constexpr int kBias = 127;
  static constexpr int kMaxBiased = 254;
};

namespace number_detail {

// Rounds m * 2^e (+ a nonzero remainder below m's last bit when `sticky`) to
// the nearest representable value, ties to even, subnormals and overflow
// included. Returns the bit pattern of the magnitude.
template <class R>
typename IeeeFormat<R>::Bits round_to_format(uint64_t m, int e, bool sticky) {
  using F = IeeeFormat<R>;
  using Bits = typename F::Bits;
  constexpr int P = F::kPrecision;
  constexpr int kEmin = 1 - F::kBias;
  constexpr Bits kInf = static_cast<Bits>(F::kMaxBiased + 1) << (P - 1);
  if (m == 0) return 0;
  const int top = e + (63 - __builtin_clzll(m));
  int lsb = (top < kEmin ? kEmin : top) - (P - 1);
  const int shift = lsb - e;
  uint64_t mant;
  if (shift <= 0) {
    mant = m << -shift;  // exact: m has at most P bits here
  } else if (shift > 64) {
    mant = 0;  // below half of the smallest subnormal
  } else {
    mant = shift == 64 ? 0 : m >> shift;
    const bool half = ((m >> (shift - 1)) & 1u) != 0;
    const uint64_t below = shift - 1 == 0 ? 0 : (m & ((uint64_t{1} << (shift - 1)) - 1));
    if (half && (sticky || below != 0 || (mant & 1u) != 0)) ++mant;
  }
  if (mant == (uint64_t{1} << P)) {
    mant >>= 1;
    ++lsb;
  }
  if (mant >= (uint64_t{1} << (P - 1))) {
    const int biased = lsb + (P - 1) + F::kBias;
    if (biased > F::kMaxBiased) return kInf;
    return (static_cast<Bits>(biased) << (P - 1)) |
           (static_cast<Bits>(mant) & ((Bits{1} << (P - 1)) - 1));
  }
  return static_cast<Bits>(mant);  // subnormal
}

inline int digit_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'z') return c - 'a' + 10;
  if (c >= 'A' && c <= 'Z') return c - 'A' + 10;
  return -1;
}

inline bool equals_nocase(const char* s, int n, const char* word) {
  int i = 0;
  for (; i < n && word[i] != 0; ++i) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != word[i]) return false;
  }
  return i == n && word[i] == 0;
}

// The signed decimal exponent after 'e' or 'p' (the whole rest of the
// token), added to `e`. Saturates far beyond any finite result.
inline bool parse_exponent(const char* s, int n, int& e) {
  int i = 0;
  bool neg = false;
  if (i < n && (s[i] == '+' || s[i] == '-')) neg = s[i++] == '-';
  if (i == n) return false;
  long x = 0;
  for (; i < n; ++i) {
    if (s[i] < '0' || s[i] > '9') return false;
    if (x < 1000000) x = x * 10 + (s[i] - '0');
  }
  e += static_cast<int>(neg ? -x : x);
  return true;
}

// Hexadecimal float ("0x1.8p3"), which OCaml's float_of_string accepts.
template <class R>
NumberStatus parse_hex_magnitude(const char* s, int n, typename IeeeFormat<R>::Bits& out) {
  uint64_t m = 0;
  int e = 0, i = 0, digits = 0;
  bool sticky = false, seen_point = false;
  for (; i < n; ++i) {
    if (s[i] == '.' && !seen_point) {
      seen_point = true;
      continue;
    }
    const int d = digit_value(s[i]);
    if (d < 0 || d >= 16) break;
    ++digits;
    if ((m >> 60) == 0) {
      m = (m << 4) | static_cast<unsigned>(d);
      if (seen_point) e -= 4;
    } else {
      sticky = sticky || d != 0;
      if (!seen_point) e += 4;
    }
  }
  if (digits == 0) return NumberStatus::kInvalid;
  if (i < n) {
    if ((s[i] != 'p' && s[i] != 'P') || !parse_exponent(s + i + 1, n - i - 1, e))
      return NumberStatus::kInvalid;
  }
  out = round_to_format<R>(m, e, sticky);
  return NumberStatus::kOk;
}

// d / 10^-exp10 (exp10 < 0) or d * 10^exp10, rounded: exact big-integer
// arithmetic for any digit count.
template <class R>
NumberStatus round_big_decimal(BigUint& d, int exp10, typename IeeeFormat<R>::Bits& out) {
  if (exp10 >= 0) {
    d.mul_pow10(exp10);
    const int b = d.bit_length();
    if (b <= 64) {
      out = round_to_format<R>(d.bits_from(0), 0, false);
    } else {
      out = round_to_format<R>(d.bits_from(b - 64), b - 64, d.any_below(b - 64));
    }
    return NumberStatus::kOk;
  }
  // value = d / 10^-exp10: a 64-bit quotient with a sticky remainder.
  BigUint den(1);
  den.mul_pow10(-exp10);
  const int k = 63 + den.bit_length() - d.bit_length();
  if (k >= 0) {
    d.shift_left(k);
  } else {
    den.shift_left(-k);
  }
  den.shift_left(63);
  uint64_t q = 0;
  for (int bit = 63; bit >= 0; --bit) {
    if (den.compare(d) <= 0) {
      d.subtract(den);
      q |= uint64_t{1} << bit;
    }
    den.shift_right_one();
  }
  out = round_to_format<R>(q, -k, !d.is_zero());
  return NumberStatus::kOk;
}

// At most 19 significant digits `dv` (nonzero) times 10^exp10, rounded,
// without a big integer where 64 bits (or the host's 128) hold the work.
// False when it does not apply.
template <class R>
bool round_small_decimal(uint64_t dv, int exp10, typename IeeeFormat<R>::Bits& out) {
  if (exp10 >= 0) {
    uint64_t v = dv;
    for (int e = 0; e < exp10; ++e) {
      if (v > UINT64_MAX / 10) return false;
      v *= 10;
    }
    out = round_to_format<R>(v, 0, false);
    return true;
  }
#if defined(__SIZEOF_INT128__)
  // Where the compiler has 128-bit integers (the host, not RV32): at most
  // 10^19 below the point divides in one step, the same quotient and
  // remainder as the long division.
  if (-exp10 <= 19) {
    uint64_t p = 1;
    for (int e = 0; e < -exp10; ++e) p *= 10;
    const int k = 63 + (64 - __builtin_clzll(p)) - (64 - __builtin_clzll(dv));
    const unsigned __int128 num = static_cast<unsigned __int128>(dv) << k;
    const uint64_t q = static_cast<uint64_t>(num / p);
    out = round_to_format<R>(q, -k, num % p != 0);
    return true;
  }
#endif
  return false;
}

template <class R>
NumberStatus parse_decimal_magnitude(const char* s, int n, typename IeeeFormat<R>::Bits& out) {
  // First pass: the digits' count and place, and the first 19 significant
  // ones in a word (they always fit); the big integer (4096 bits) is built
  // only for the numbers that need it.
  uint64_t small = 0;
  int i = 0, significant = 0, exp10 = 0, digits = 0;
  bool seen_point = false;
  for (; i < n; ++i) {
    if (s[i] == '.' && !seen_point) {
      seen_point = true;
      continue;
    }
    if (s[i] < '0' || s[i] > '9') break;
    ++digits;
    const unsigned v = static_cast<unsigned>(s[i] - '0');
    if (seen_point) --exp10;
    if (significant == 0 && v == 0) continue;
    if (++significant <= 19) small = small * 10 + v;
  }
  if (digits == 0) return NumberStatus::kInvalid;
  const int digits_end = i;
  if (i < n) {
    if ((s[i] != 'e' && s[i] != 'E') || !parse_exponent(s + i + 1, n - i - 1, exp10))
      return NumberStatus::kInvalid;
  }
  out = 0;
  if (significant == 0) return NumberStatus::kOk;
  // Decimal magnitude of the leading digit; outside these bounds the result
  // is certainly infinite (or zero) in both formats.
  const int magnitude = significant + exp10;
  if (magnitude > 330) {
    out = round_to_format<R>(1, 4096, false);
    return NumberStatus::kOk;
  }
  if (magnitude < -330) return NumberStatus::kOk;
  if (significant <= 19 && round_small_decimal<R>(small, exp10, out)) return NumberStatus::kOk;
  // Up to 19 digits the word holds the number; past that every digit is read again.
  BigUint d(significant <= 19 ? small : 0);
  if (significant > 19) {
    for (int k = 0; k < digits_end; ++k) {
      if (s[k] == '.') continue;
      const unsigned v = static_cast<unsigned>(s[k] - '0');
      if (d.is_zero() && v == 0) continue;
      if (!d.mul_add_small(10, v)) return NumberStatus::kInvalid;
    }
  }
  return round_big_decimal<R>(d, exp10, out);
}

}  // namespace number_detail

// Parses a whole token as OCaml's float_of_string would, rounded directly to R.
template <class R>
NumberStatus parse_real(const char* s, int n, R& out) {
  using Bits = typename IeeeFormat<R>::Bits;
  constexpr int kSignShift = sizeof(Bits) * 8 - 1;
  // float_of_string drops every underscore before converting.
  char buf[260];
  int len = 0;
  for (int i = 0; i < n; ++i) {
    if (s[i] == '_') continue;
    if (len == static_cast<int>(sizeof buf)) return NumberStatus::kInvalid;
    buf[len++] = s[i];
  }
  int i = 0;
  while (i < len && (buf[i] == '\v' || buf[i] == '\f')) ++i;  // strtod skips these
  bool negative = false;
  if (i < len && (buf[i] == '+' || buf[i] == '-')) negative = buf[i++] == '-';
  const char* body = buf + i;
  const int blen = len - i;
  if (blen == 0) return NumberStatus::kInvalid;
  if (number_detail::equals_nocase(body, blen, "inf") ||
      number_detail::equals_nocase(body, blen, "infinity") ||
      number_detail::equals_nocase(body, blen, "nan"))
    return NumberStatus::kNonFinite;
  Bits bits = 0;
  NumberStatus st;
  if (blen > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X'))
    st = number_detail::parse_hex_magnitude<R>(body + 2, blen - 2, bits);
  else
    st = number_detail::parse_decimal_magnitude<R>(body, blen, bits);
  if (st != NumberStatus::kOk) return st;
  constexpr Bits kExpMask = static_cast<Bits>(IeeeFormat<R>::kMaxBiased + 1)
                            << (IeeeFormat<R>::kPrecision - 1);
  if ((bits & kExpMask) == kExpMask) return NumberStatus::kNonFinite;
  if (negative) bits |= Bits{1} << kSignShift;
  out = bit_cast<R>(bits);
  return NumberStatus::kOk;
}

// Parses a whole token as OCaml's int_of_string would on a 64-bit machine
// (63-bit ints; 0x/0o/0b prefixes are unsigned and wrap; underscores allowed
// after the first digit).
inline NumberStatus parse_int(const char* s, int n, int64_t& out) {
  int i = 0;
  bool negative = false;
  if (i < n && (s[i] == '-' || s[i] == '+')) negative = s[i++] == '-';
  int base = 10;
  bool is_signed = true;
  if (i + 1 < n && s[i] == '0') {
    switch (s[i + 1]) {
      case 'x': case 'X': base = 16; is_signed = false; i += 2; break;
      case 'o': case 'O': base = 8; is_signed = false; i += 2; break;
      case 'b': case 'B': base = 2; is_signed = false; i += 2; break;
      case 'u': case 'U': i += 2; is_signed = false; break;
      default: break;
    }
  }
  if (i == n) return NumberStatus::kInvalid;
  int d = number_detail::digit_value(s[i]);
  if (d < 0 || d >= base) return NumberStatus::kInvalid;
  constexpr uint64_t kLimit = uint64_t{1} << 63;  // 2^nbits for 63-bit ints
  uint64_t v = static_cast<unsigned>(d);
  for (++i; i < n; ++i) {
    if (s[i] == '_') continue;
    d = number_detail::digit_value(s[i]);
    if (d < 0 || d >= base) return NumberStatus::kInvalid;
    // Overflow check by multiplication: 64-bit division is a library call on
    // a 32-bit CPU.
    uint64_t scaled = 0;
    if (__builtin_mul_overflow(v, static_cast<uint64_t>(base), &scaled) ||
        scaled + static_cast<unsigned>(d) > kLimit)
      return NumberStatus::kOutOfRange;
    v = scaled + static_cast<unsigned>(d);
  }
  constexpr uint64_t kHalf = uint64_t{1} << 62;
  if (is_signed) {
    if (negative ? v > kHalf : v >= kHalf) return NumberStatus::kOutOfRange;
  } else if (v >= kLimit) {
    return NumberStatus::kOutOfRange;
  }
  // Unsigned forms wrap into the 63-bit range, as OCaml's ints do.
  if (is_signed) {
    out = negative ? -static_cast<int64_t>(v) : static_cast<int64_t>(v);
    return NumberStatus::kOk;
  }
  const int64_t r = v >= kHalf ? static_cast<int64_t>(v) - static_cast<int64_t>(kLimit - 1) - 1
                               : static_cast<int64_t>(v);
  out = negative ? -r : r;
  return NumberStatus::kOk;
}

}  // namespace minrt
