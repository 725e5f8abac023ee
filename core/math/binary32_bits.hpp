// The fields of an IEEE 754 binary32 word, for the integer code that takes
// floats apart: the portable shims and the soft float.
#pragma once

#include <stdint.h>

namespace minrt::binary32 {

inline constexpr uint32_t kSignBit = 0x80000000u;
inline constexpr uint32_t kAbsMask = 0x7fffffffu;
inline constexpr uint32_t kInfBits = 0x7f800000u;
inline constexpr uint32_t kFracMask = 0x007fffffu;
inline constexpr uint32_t kHiddenBit = 0x00800000u;
inline constexpr uint32_t kQuietNaN = 0x7fc00000u;  // the canonical NaN (RISC-V F)

}  // namespace minrt::binary32
