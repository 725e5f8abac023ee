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

uint32_t min(uint32_t a, uint32_t b, uint8_t& flags);
uint32_t max(uint32_t a, uint32_t b, uint8_t& flags);
bool eq(uint32_t a, uint32_t b, uint8_t& flags);
bool lt(uint32_t a, uint32_t b, uint8_t& flags);
bool le(uint32_t a, uint32_t b, uint8_t& flags);
uint32_t classify(uint32_t a);

// Host FPU exception state <-> RISC-V fflags, for the fast path.
uint8_t take_host_flags();   // reads and clears the host's sticky flags
void clear_host_flags();

}  // namespace fwsim::fpu
