// The compiler's float library calls (the libgcc ABI: __addsf3, __mulsf3,
// the comparisons, ...) for a CPU without F, implemented by
// core/math/soft_float.hpp instead of libgcc's generic routines: the same
// bits for every operation, fewer instructions (docs/firmware.md,
// "Instruction counts and profile"). Linked ahead of libgcc.a, so its
// members for these symbols are never pulled. With M the mantissa products
// and quotients use mul/mulhu and divu/remu; without, quarter squares and
// shift-subtract division, so nothing here calls __mulsi3 or __udivsi3.
#include <stdint.h>

#include "core/math/soft_float.hpp"

namespace sf = minrt::soft_float;

namespace {

#if defined(__riscv_mul) || defined(__ARM_FEATURE_DSP)
using Mul = sf::Mul64Native;
#else
using Mul = sf::MulQuarterSquares;
#endif
#if defined(__riscv_div) || defined(__ARM_FEATURE_IDIV)
using Div = sf::DivNative;
#else
using Div = sf::DivShift;
#endif

uint32_t bits(float x) { return __builtin_bit_cast(uint32_t, x); }
float value(uint32_t b) { return __builtin_bit_cast(float, b); }

// The general paths (zeros, subnormals, infinities, NaN) as functions of
// the calls' own signature, entered by a tail jump: the normal-operand
// path then needs no stack frame.
[[gnu::noinline]] float add_general(float a, float b) { return value(sf::add_general(bits(a), bits(b))); }
[[gnu::noinline]] float mul_general(float a, float b) { return value(sf::mul_general<Mul>(bits(a), bits(b))); }

}  // namespace

#if defined(__clang__)
#define MINRT_TAIL [[clang::musttail]]
#else
#define MINRT_TAIL
#endif

extern "C" {

float __addsf3(float a, float b) {
  uint32_t x = bits(a), y = bits(b);
  sf::order_for_add(x, y);  // addition commutes, the general path too
  if (sf::add_ordered_needs_general(x, y)) {
    if (sf::add_ordered_gives_a(x, y)) return value(x);
    MINRT_TAIL return add_general(value(x), value(y));
  }
  return value(sf::add_ordered(x, y));
}
float __subsf3(float a, float b) {
  uint32_t x = bits(a), y = bits(b) ^ sf::kSignBit;
  sf::order_for_add(x, y);
  if (sf::add_ordered_needs_general(x, y)) {
    if (sf::add_ordered_gives_a(x, y)) return value(x);
    MINRT_TAIL return add_general(value(x), value(y));
  }
  return value(sf::add_ordered(x, y));
}
float __mulsf3(float a, float b) {
  const uint32_t x = bits(a), y = bits(b);
  if (sf::mul_needs_general(x, y)) {
    if (sf::mul_gives_zero(x, y)) return value((x ^ y) & sf::kSignBit);
    MINRT_TAIL return mul_general(a, b);
  }
  return value(sf::mul_normal<Mul>(x, y));
}
float __divsf3(float a, float b) { return value(sf::div<Div>(bits(a), bits(b))); }

// libgcc's contracts: eq/ne give 0 iff equal; lt/le give <= 0 iff a <= b
// and 1 when unordered; gt/ge give >= 0 iff a >= b and -1 when unordered.
int __eqsf2(float a, float b) { return sf::compare(bits(a), bits(b), 1); }
int __nesf2(float a, float b) { return sf::compare(bits(a), bits(b), 1); }
int __ltsf2(float a, float b) { return sf::compare(bits(a), bits(b), 1); }
int __lesf2(float a, float b) { return sf::compare(bits(a), bits(b), 1); }
int __gtsf2(float a, float b) { return sf::compare(bits(a), bits(b), -1); }
int __gesf2(float a, float b) { return sf::compare(bits(a), bits(b), -1); }
int __unordsf2(float a, float b) { return sf::unordered(bits(a), bits(b)) ? 1 : 0; }

float __floatsisf(int32_t i) { return value(sf::from_int(i)); }
float __floatunsisf(uint32_t i) { return value(sf::from_uint(i)); }
int32_t __fixsfsi(float a) { return sf::to_int(bits(a)); }
uint32_t __fixunssfsi(float a) { return sf::to_uint(bits(a)); }

}  // extern "C"
