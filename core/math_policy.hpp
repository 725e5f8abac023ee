// The miniMLRuntime math shims as a compile-time policy. The renderer is a
// template over one of these; each provides the floating type and the few
// functions the original program takes from its runtime. Everything else
// (add, sub, mul, div, compare, negate, abs) is plain arithmetic on `real`.
#pragma once

#include <concepts>
#include <cstdint>

namespace minrt {

template <class M>
concept MathPolicy = requires(typename M::real x, std::int32_t i) {
  { M::sqrt(x) } -> std::same_as<typename M::real>;
  { M::floor(x) } -> std::same_as<typename M::real>;
  { M::sin(x) } -> std::same_as<typename M::real>;
  { M::cos(x) } -> std::same_as<typename M::real>;
  { M::atan(x) } -> std::same_as<typename M::real>;
  // float_of_int: exact for the small integers the renderer converts.
  { M::from_int(i) } -> std::same_as<typename M::real>;
  // int_of_float: truncation toward zero; only called with 0 <= x < 256.
  { M::to_int(x) } -> std::same_as<std::int32_t>;
  { M::name } -> std::convertible_to<const char*>;
};

}  // namespace minrt
