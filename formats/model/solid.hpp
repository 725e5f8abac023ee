// A finite cylinder or cone around an axis, closed by flat caps: miniRT's
// `cy` and `co` (SPEC.md 2.3). One shape covers both: the radius changes
// linearly along the axis, by `slope` per unit of height (0 for a cylinder).
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"

namespace minrt::model {

template <class R>
struct Solid {
  Vec3<R> base;    // centre of the disc at height 0
  Vec3<R> axis;    // unit length, from the base toward the other end
  R radius;        // at the base
  R slope;         // radius(m) = radius + slope * m
  R height;        // the solid spans 0 <= m <= height
  uint32_t material;
  uint32_t order;
};

}  // namespace minrt::model
