// PortableFloat with the square root done in integer arithmetic
// (soft_float::sqrt), for CPUs without an FPU. The results are the same
// bits: the portable square root is correctly rounded for every float
// (docs/shims.md), and so is soft_float::sqrt (checked against the host's
// sqrtf for all 2^32 inputs, test/soft_float). On soft float it replaces
// the portable one's Newton steps, each a chain of library calls, by one
// digit-by-digit loop.
#pragma once

#include "core/base/bit_cast.hpp"
#include "core/math/math_portable.hpp"
#include "core/math/soft_float.hpp"

namespace minrt {

struct PortableFloatIntSqrt : PortableFloat {
  static constexpr const char* name = "float/portable+intsqrt";
  static real sqrt(real x) { return bit_cast<real>(soft_float::sqrt(bit_cast<uint32_t>(x))); }
};
static_assert(MathPolicy<PortableFloatIntSqrt>);
static_assert(SceneMathPolicy<PortableFloatIntSqrt>);

}  // namespace minrt
