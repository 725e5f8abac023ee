// The firmware's one math policy, for every format: PortableFloat as the
// host's `--shims portable`; with MINRT_FW_HW_SQRT the square root is
// fsqrt.s (the same bits, core/math/math_rv32f.hpp) where the ISA has it.
// Without an FPU the square root is integer code (the same bits again,
// core/math/math_soft_float.hpp).
#pragma once

#include "core/math/math_portable.hpp"
#include "core/math/math_rv32f.hpp"
#include "core/math/math_soft_float.hpp"

namespace minrt::fw {

#if defined(__riscv) && !defined(__riscv_flen)
using Math = PortableFloatIntSqrt;
#elif MINRT_FW_HW_SQRT
using Math = PortableFloatHwSqrt;
#else
using Math = PortableFloat;
#endif

}  // namespace minrt::fw
