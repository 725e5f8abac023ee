// Host-side accuracy measurement for the math policies: the named argument
// ranges, the reference (the host C library in double, which is what the
// original program computes, compared before rounding to float) and the
// error statistics.  Shared by test/shims and the shim-ulp-table tool so the
// tests assert on exactly what docs/shims.md reports.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace shim_ulp {

enum class Fn { sqrt, floor, sin, cos, atan };

inline const char* fn_name(Fn f) {
  switch (f) {
    case Fn::sqrt: return "sqrt";
    case Fn::floor: return "floor";
    case Fn::sin: return "sin";
    case Fn::cos: return "cos";
    case Fn::atan: return "atan";
  }
  return "?";
}

// The course's bound on the relative error of each function, as log2
// (add/sub 2^-23, mul 2^-22, div 2^-20 for reference); 0 means exact.
inline int course_rule_log2(Fn f) {
  switch (f) {
    case Fn::sqrt:
    case Fn::atan: return -20;
    case Fn::sin:
    case Fn::cos: return -18;
    case Fn::floor: return 0;
  }
  return 0;
}

inline double reference(Fn f, float x) {
  const double d = x;
  switch (f) {
    case Fn::sqrt: return std::sqrt(d);
    case Fn::floor: return std::floor(d);
    case Fn::sin: return std::sin(d);
    case Fn::cos: return std::cos(d);
    case Fn::atan: return std::atan(d);
  }
  return 0.0;
}

template <class P>
float evaluate(Fn f, float x) {
  switch (f) {
    case Fn::sqrt: return P::sqrt(x);
    case Fn::floor: return P::floor(x);
    case Fn::sin: return P::sin(x);
    case Fn::cos: return P::cos(x);
    case Fn::atan: return P::atan(x);
  }
  return 0.0f;
}

inline std::uint32_t bits_of(float x) { return std::bit_cast<std::uint32_t>(x); }
inline float float_of(std::uint32_t b) { return std::bit_cast<float>(b); }

// Floats in a monotone integer order: -0 and +0 are adjacent, and the
// difference of two keys counts the floats between them.
inline std::int64_t order_key(float x) {
  const std::uint32_t b = bits_of(x);
  const std::int64_t mag = b & 0x7fffffffu;
  return (b & 0x80000000u) != 0 ? -mag - 1 : mag;
}
inline float from_order_key(std::int64_t k) {
  return k < 0 ? float_of(std::uint32_t(-(k + 1)) | 0x80000000u)
               : float_of(std::uint32_t(k));
}

// Error of `got` against the exact value `ref`, in units of the float
// spacing at |ref| (the spacing of the binade, subnormal spacing below).
// Special results must match exactly (NaN for NaN, the same infinity),
// otherwise the error is infinite.
inline double ulp_error(float got, double ref) {
  if (std::isnan(ref)) return std::isnan(got) ? 0.0 : INFINITY;
  if (std::isnan(got)) return INFINITY;
  if (std::isinf(ref) || std::isinf(got)) {
    return double(got) == ref ? 0.0 : INFINITY;
  }
  const double mag = std::fabs(ref);
  int exp = mag == 0.0 ? -126 : std::ilogb(mag);
  if (exp < -126) exp = -126;
  return std::fabs(double(got) - ref) / std::ldexp(1.0, exp - 23);
}

struct Stats {
  std::uint64_t count = 0;
  std::uint64_t not_correctly_rounded = 0;
  double max_ulp = 0.0;
  double sum_ulp = 0.0;
  double max_rel = 0.0;
  float worst_arg = 0.0f;
  float worst_got = 0.0f;
  double worst_ref = 0.0;

  void add(float x, float got, double ref) {
    ++count;
    const float rounded = float(ref);
    const bool same = std::isnan(rounded) ? std::isnan(got)
                                          : bits_of(got) == bits_of(rounded);
    if (!same) ++not_correctly_rounded;
    const double e = ulp_error(got, ref);
    sum_ulp += e;
    if (e > max_ulp || count == 1) {
      max_ulp = e;
      worst_arg = x;
      worst_got = got;
      worst_ref = ref;
    }
    if (std::isfinite(ref) && ref != 0.0) {
      const double rel = std::isfinite(e) ? std::fabs((double(got) - ref) / ref)
                                          : INFINITY;
      if (rel > max_rel) max_rel = rel;
    }
  }
  double mean_ulp() const { return count == 0 ? 0.0 : sum_ulp / double(count); }
};

// An argument range: every `stride`-th float (by bit pattern) from lo to hi,
// both ends included.  stride 1 is exhaustive.
struct Range {
  std::string name;
  float lo, hi;
  std::int64_t stride;
};

template <class Visit>
void for_each_float(const Range& r, Visit&& visit) {
  const std::int64_t a = order_key(r.lo), b = order_key(r.hi);
  for (std::int64_t k = a; k <= b; k += r.stride) visit(from_order_key(k));
  if ((b - a) % r.stride != 0) visit(r.hi);
}

template <class P>
Stats measure(Fn f, const Range& r) {
  Stats s;
  for_each_float(r, [&](float x) { s.add(x, evaluate<P>(f, x), reference(f, x)); });
  return s;
}

inline constexpr float kMaxFloat = std::numeric_limits<float>::max();

// The named ranges.  `refine` divides the strides (the tests use 1, the tool
// a finer default; a huge value makes every stride 1, i.e. exhaustive).
// Strides are odd so that every low mantissa bit pattern is exercised.
inline std::vector<Range> ranges_for(Fn f, std::int64_t refine) {
  auto st = [&](std::int64_t s) {
    const std::int64_t v = s / refine;
    return v < 1 ? std::int64_t(1) : (v | 1);
  };
  switch (f) {
    case Fn::sin:
    case Fn::cos:
      return {{"renderer [-1e4, 1e4]", -1e4f, 1e4f, st(255)},
              {"large [1e4, 1e7]", 1e4f, 1e7f, st(255)},
              {"all finite", -kMaxFloat, kMaxFloat, st(255 * 17)}};
    case Fn::atan:
      return {{"renderer [0, 1e6]", 0.0f, 1e6f, st(255 * 3)},
              {"negatives [-1e6, 0]", -1e6f, -0.0f, st(255 * 7)},
              {"all", -INFINITY, INFINITY, st(255 * 17)}};
    case Fn::sqrt:
      return {{"renderer [0, 1e12]", 0.0f, 1e12f, st(255 * 3)},
              {"all non-negative", 0.0f, INFINITY, st(255 * 9)}};
    case Fn::floor:
      return {{"all", -INFINITY, INFINITY, st(255 * 3)}};
  }
  return {};
}

}  // namespace shim_ulp
