// PortableFloat with the square root done by the F extension's fsqrt.s when
// the target has it. The results are the same bits: the portable square root
// is correctly rounded for every float (checked exhaustively, see
// docs/shims.md), and so is fsqrt.s by the ISA. The course FPU's required
// operations include sqrt; sin, cos and atan stay in software.
#pragma once

#include "core/math/math_portable.hpp"

namespace minrt {

struct PortableFloatHwSqrt : PortableFloat {
  static constexpr const char* name = "float/portable+fsqrt";
  static real sqrt(real x) {
#if defined(__riscv_fsqrt)
    real r;
    __asm__("fsqrt.s %0, %1" : "=f"(r) : "f"(x));
    return r;
#else
    return PortableFloat::sqrt(x);
#endif
  }
};
static_assert(MathPolicy<PortableFloatHwSqrt>);

}  // namespace minrt
