// IEEE 754 single precision as RISC-V F defines it: all five rounding modes,
// exact accrued flags, canonical NaN results, fmin/fmax NaN rules, saturating
// conversions. Values travel as raw bit patterns so no host FP unit (and no
// host exception flag) is touched here; the interpreter uses the host FPU
// only on its round-to-nearest fast path (see interpreter.cpp).
#pragma once
#include <cstdint>

namespace fwsim::fpu {

enum Flag : uint8_t { NX = 1, UF = 2, OF = 4, DZ = 8, NV = 16 };
enum Rounding : uint8_t { RNE = 0, RTZ = 1, RDN = 2, RUP = 3, RMM = 4, DYN = 7 };

inline constexpr uint32_t kCanonicalNaN = 0x7fc00000u;

inline bool is_nan(uint32_t a) { return (a & 0x7fffffffu) > 0x7f800000u; }
inline bool is_snan(uint32_t a) { return is_nan(a) && !(a & 0x00400000u); }

uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags);
uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags);
uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags);
uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags);
uint32_t sqrt(uint32_t a, unsigned rm, uint8_t& flags);
// a*b + c rounded once; the negated variants flip the signs of the product
// and/or the addend as fmsub/fnmsub/fnmadd require.
uint32_t fma(uint32_t a, uint32_t b, uint32_t c, bool negate_product, bool negate_addend,
             unsigned rm, uint8_t& flags);

uint32_t to_int32(uint32_t a, unsigned rm, uint8_t& flags);
uint32_t to_uint32(uint32_t a, unsigned rm, uint8_t& flags);
uint32_t from_int32(int32_t v, unsigned rm, uint8_t& flags);
uint32_t from_uint32(uint32_t v, unsigned rm, uint8_t& flags);

// Comparisons and min/max are integer-only and small: inline for the hot loop.
namespace detail {
// Orders non-NaN values; `zero_signed` makes -0 < +0 (fmin/fmax), otherwise
// the two zeros compare equal (feq/flt/fle).
inline int64_t order_key(uint32_t a, bool zero_signed) {
  int64_t mag = a & 0x7fffffffu;
  if (!(a >> 31)) return mag;
  return zero_signed ? -mag - 1 : -mag;
}

inline uint32_t min_max(uint32_t a, uint32_t b, uint8_t& flags, bool want_max) {
  if (is_snan(a) || is_snan(b)) flags |= NV;
  const bool na = is_nan(a), nb = is_nan(b);
  if (na && nb) return kCanonicalNaN;
  if (na) return b;
  if (nb) return a;
  const bool a_less = order_key(a, true) < order_key(b, true);
  return (a_less != want_max) ? a : b;
}

}  // namespace detail

inline uint32_t min(uint32_t a, uint32_t b, uint8_t& flags) { return detail::min_max(a, b, flags, false); }
inline uint32_t max(uint32_t a, uint32_t b, uint8_t& flags) { return detail::min_max(a, b, flags, true); }

inline bool eq(uint32_t a, uint32_t b, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    if (is_snan(a) || is_snan(b)) flags |= NV;
    return false;
  }
  return detail::order_key(a, false) == detail::order_key(b, false);
}

inline bool lt(uint32_t a, uint32_t b, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    flags |= NV;
    return false;
  }
  return detail::order_key(a, false) < detail::order_key(b, false);
}

inline bool le(uint32_t a, uint32_t b, uint8_t& flags) {
  if (is_nan(a) || is_nan(b)) {
    flags |= NV;
    return false;
  }
  return detail::order_key(a, false) <= detail::order_key(b, false);
}

inline uint32_t classify(uint32_t a) {
  const bool s = (a >> 31);
  const uint32_t e = (a >> 23) & 0xff, f = a & 0x7fffffu;
  if (e == 0xff) {
    if (f == 0) return s ? 1u << 0 : 1u << 7;
    return (f & 0x400000u) ? 1u << 9 : 1u << 8;
  }
  if (e == 0) {
    if (f == 0) return s ? 1u << 3 : 1u << 4;
    return s ? 1u << 2 : 1u << 5;
  }
  return s ? 1u << 1 : 1u << 6;
}


// Host FPU exception state <-> RISC-V fflags, for the fast path.
uint8_t take_host_flags();   // reads and clears the host's sticky flags
void clear_host_flags();

}  // namespace fwsim::fpu
