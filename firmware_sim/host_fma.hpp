// Fused multiply-add on the host FPU, when the CPU has one: a single rounding
// in the current (round-to-nearest) mode with IEEE flags, i.e. exactly what
// fmadd.s with rm = RNE computes. Inline asm keeps it inside the hot loop
// without compiling the whole interpreter for FMA-capable CPUs only.
#pragma once

namespace fwsim {

extern const bool kHostHasFma;

// Only call when kHostHasFma.
inline float host_fma(float a, float b, float c) {
#if defined(__x86_64__)
  __asm__("vfmadd231ss %2, %1, %0" : "+x"(c) : "x"(a), "x"(b));
  return c;
#else
  return __builtin_fmaf(a, b, c);
#endif
}

}  // namespace fwsim
