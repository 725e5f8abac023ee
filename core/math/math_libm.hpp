// Math policies backed by the C library: the exact reference mode (double,
// what the original OCaml program calls) and float with the C library's
// single-precision functions. Host only: these are the one place the core
// touches libm, and the symbols they pull in are the documented externals.
#pragma once

#include <stdint.h>

extern "C" {
double sqrt(double);
double floor(double);
double sin(double);
double cos(double);
double atan(double);
double atan2(double, double);
double exp(double);
double log(double);
float sqrtf(float);
float floorf(float);
float sinf(float);
float cosf(float);
float atanf(float);
float atan2f(float, float);
float expf(float);
float logf(float);
}

namespace minrt {

struct LibmDouble {
  using real = double;
  static constexpr const char* name = "double/libm";
  static real sqrt(real x) { return ::sqrt(x); }
  static real floor(real x) { return ::floor(x); }
  static real sin(real x) { return ::sin(x); }
  static real cos(real x) { return ::cos(x); }
  static real atan(real x) { return ::atan(x); }
  static real atan2(real y, real x) { return ::atan2(y, x); }
  static real exp(real x) { return ::exp(x); }
  static real log(real x) { return ::log(x); }
  static real from_int(int32_t i) { return static_cast<real>(i); }
  static int32_t to_int(real x) { return static_cast<int32_t>(x); }
};

struct LibmFloat {
  using real = float;
  static constexpr const char* name = "float/libm";
  static real sqrt(real x) { return ::sqrtf(x); }
  static real floor(real x) { return ::floorf(x); }
  static real sin(real x) { return ::sinf(x); }
  static real cos(real x) { return ::cosf(x); }
  static real atan(real x) { return ::atanf(x); }
  static real atan2(real y, real x) { return ::atan2f(y, x); }
  static real exp(real x) { return ::expf(x); }
  static real log(real x) { return ::logf(x); }
  static real from_int(int32_t i) { return static_cast<real>(i); }
  static int32_t to_int(real x) { return static_cast<int32_t>(x); }
};

}  // namespace minrt
