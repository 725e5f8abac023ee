// Instantiates every function of every portable level, for the riscv32
// freestanding compile check (test/shims/freestanding_check.cmake).
#include "core/math/math_portable.hpp"

namespace {
template <class P>
void use_all(volatile float* f, volatile int* i) {
  f[0] = P::sqrt(f[0]);
  f[1] = P::floor(f[1]);
  f[2] = P::sin(f[2]);
  f[3] = P::cos(f[3]);
  f[4] = P::atan(f[4]);
  f[5] = P::from_int(i[0]);
  i[1] = P::to_int(f[6]);
}
}  // namespace

extern "C" void minrt_shims_use_all(volatile float* f, volatile int* i) {
  use_all<minrt::PortableFloatT<0>>(f, i);
  use_all<minrt::PortableFloatT<1>>(f, i);
  use_all<minrt::PortableFloatT<2>>(f, i);
}
