// Unsigned 64-bit division for RV32, which has no instruction for it: the
// compiler calls __udivdi3/__umoddi3 (normally from libgcc or compiler-rt,
// which the firmware does not link). Needed by the course protocol's exact
// float formatting (protocol/protocol_course.hpp). Shift and subtract,
// with a 32-bit fast path.
#include <stdint.h>

namespace {

uint64_t divide(uint64_t n, uint64_t d, uint64_t* remainder) {
  if ((n >> 32) == 0 && (d >> 32) == 0) {
    const uint32_t n32 = static_cast<uint32_t>(n);
    const uint32_t d32 = static_cast<uint32_t>(d);
    if (remainder != nullptr) *remainder = n32 % d32;
    return n32 / d32;
  }
  uint64_t q = 0;
  uint64_t r = 0;
  for (int i = 63; i >= 0; --i) {
    r = (r << 1) | ((n >> i) & 1u);
    if (r >= d) {
      r -= d;
      q |= uint64_t{1} << i;
    }
  }
  if (remainder != nullptr) *remainder = r;
  return q;
}

}  // namespace

extern "C" uint64_t __udivdi3(uint64_t n, uint64_t d) { return divide(n, d, nullptr); }

extern "C" uint64_t __umoddi3(uint64_t n, uint64_t d) {
  uint64_t r = 0;
  divide(n, d, &r);
  return r;
}
