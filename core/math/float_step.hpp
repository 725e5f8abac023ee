// A bound on the gap between a float and its neighbours, for moving a
// value rounded to float back to the side of the exact value it needs
// (box bounds rounded outward, a sphere's far side rounded up).
#pragma once

namespace minrt {

// |f| / 2^23 is at least one step of f at any exponent (float has 23
// fraction bits); the 1e-30 covers zero and subnormals. f is within half
// a step of the value it was rounded from, so f plus or minus this bound
// lies on the chosen side of it. For a float or a vector of floats.
template <class F>
[[gnu::always_inline]] constexpr F float_step_bound(F f) {
  return (f < 0.0f ? -f : f) * (1.0f / 8388608.0f) + 1e-30f;
}

}  // namespace minrt
