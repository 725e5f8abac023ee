// The miniMLRuntime math shims as a compile-time policy. The renderer is a
// template over one of these; each provides the floating type and the few
// functions the original program takes from its runtime. Everything else
// (add, sub, mul, div, compare, negate, abs) is plain arithmetic on `real`.
//
// The core includes no C++ library headers (only the compiler's own
// <stdint.h>/<stddef.h>), so it builds for a bare RISC-V target that has no
// C++ library at all; hence the home-made same_as below.
#pragma once

#include <stdint.h>

namespace minrt {

namespace policy_detail {
template <class A, class B>
inline constexpr bool kSame = false;
template <class A>
inline constexpr bool kSame<A, A> = true;
}  // namespace policy_detail

template <class A, class B>
concept SameAs = policy_detail::kSame<A, B>;

template <class M>
concept MathPolicy = requires(typename M::real x, int32_t i) {
  { M::sqrt(x) } -> SameAs<typename M::real>;
  { M::floor(x) } -> SameAs<typename M::real>;
  { M::sin(x) } -> SameAs<typename M::real>;
  { M::cos(x) } -> SameAs<typename M::real>;
  { M::atan(x) } -> SameAs<typename M::real>;
  // float_of_int: exact for the small integers the renderer converts.
  { M::from_int(i) } -> SameAs<typename M::real>;
  // int_of_float: truncation toward zero; only called with 0 <= x < 256.
  { M::to_int(x) } -> SameAs<int32_t>;
  { M::name } -> SameAs<const char* const&>;
};

// What the general tracer (CS418 and the later formats) needs on top:
// exposure (exp), Gaussian samples (log), sphere texture coordinates (atan2).
template <class M>
concept SceneMathPolicy = MathPolicy<M> && requires(typename M::real x) {
  { M::exp(x) } -> SameAs<typename M::real>;
  { M::log(x) } -> SameAs<typename M::real>;
  { M::atan2(x, x) } -> SameAs<typename M::real>;
};

}  // namespace minrt
