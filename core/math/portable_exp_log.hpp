// exp and log in single precision from float add/sub/mul/div and bit
// operations only, for the general tracer's exposure (exp) and Gaussian
// samples (log) on an FPU without them. exp is within 1.01 ULP, log 1.9 ULP, over the
// float range (docs/shims.md has the measured table).
//
// Part of math_portable.hpp (included from it, after the helpers it uses);
// include that header, not this one.
#pragma once

namespace minrt::portable_detail {

// ln 2 split so that k * kLn2Hi is exact for |k| < 2^9.
inline constexpr float kLn2Hi = 0.693145751953125f;
inline constexpr float kLn2Lo = 1.42860682030941723212e-6f;
inline constexpr float kLog2E = 1.44269504088896341f;
inline constexpr float kExpOverflow = 88.7228317f;    // above: +inf
inline constexpr float kExpUnderflow = -103.972084f;  // below: 0

// e^x: x = k ln2 + r with |r| <= ln2/2, e^r by its Taylor series to r^7
// (truncation below 6e-9 relative), then scaled by 2^k in two exact steps.
constexpr float exp(float x) {
  const u32 b = bits_of(x);
  if (nan_bits(b)) return x + x;
  if (x > kExpOverflow) return float_of(kInfBits);
  if (x < kExpUnderflow) return 0.0f;
  const float kf = floor(x * kLog2E + 0.5f);
  const int k = to_int(kf);
  const float r = (x - kf * kLn2Hi) - kf * kLn2Lo;
  float p = 1.0f / 5040.0f;
  p = p * r + 1.0f / 720.0f;
  p = p * r + 1.0f / 120.0f;
  p = p * r + 1.0f / 24.0f;
  p = p * r + 1.0f / 6.0f;
  p = p * r + 0.5f;
  p = p * r * r + r;
  const float e = 1.0f + p;
  if (k > 127) return e * pow2(127) * pow2(k - 127);
  if (k < -126) return e * pow2(k + 64) * pow2(-64);
  return e * pow2(k);
}

// Natural log: x = m 2^e with m in [sqrt(1/2), sqrt(2)), log m = 2 atanh(s),
// s = (m - 1)/(m + 1), |s| <= 0.172, odd series to s^9.
constexpr float log(float x) {
  u32 b = bits_of(x);
  if (nan_bits(b) || (b & kSignBit) != 0) {
    if ((b & kAbsMask) == 0) return -float_of(kInfBits);  // log(-0) = -inf
    return float_of(kQuietNaN);
  }
  if (b == 0) return -float_of(kInfBits);
  if (b == kInfBits) return x;
  int e = 0;
  if (exponent_of(b) == -127) {  // subnormal: make it normal first
    b = bits_of(x * pow2(24));
    e = -24;
  }
  e += exponent_of(b);
  float m = float_of((b & kFracMask) | 0x3f800000u);
  if (m > 1.41421356f) {
    m = m * 0.5f;
    ++e;
  }
  const float s = (m - 1.0f) / (m + 1.0f);
  const float z = s * s;
  float p = 1.0f / 9.0f;
  p = p * z + 1.0f / 7.0f;
  p = p * z + 1.0f / 5.0f;
  p = p * z + 1.0f / 3.0f;
  const float lm = 2.0f * s + 2.0f * s * z * p;
  const float ef = from_int(e);
  return ef * kLn2Hi + (lm + ef * kLn2Lo);
}

// atan2 from the policy's atan: the smaller ratio keeps atan's argument in
// [0, 1], then the quadrant. atan2(+-0, +-0) is 0 (no direction).
template <int Level>
constexpr float atan2(float y, float x) {
  if (nan_bits(bits_of(x)) || nan_bits(bits_of(y))) return x + y;
  const float ax = x < 0.0f ? -x : x;
  const float ay = y < 0.0f ? -y : y;
  if (ax == 0.0f && ay == 0.0f) return 0.0f;
  constexpr float kHalfPi = 1.57079632679489662f;
  constexpr float kPi = 3.14159265358979324f;
  float a = ay <= ax ? atan<Level>(ay / ax) : kHalfPi - atan<Level>(ax / ay);
  if (x < 0.0f) a = kPi - a;
  return y < 0.0f ? -a : a;
}

}  // namespace minrt::portable_detail
