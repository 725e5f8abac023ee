// Part of the min-rt tracer (render/sld/tracer.hpp).
// The surface normal and the texture colour at the hit point.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::get_nvector(const Object& m, const R* dir) -> void {
  if (m.form == kFormBox) {
    const int side = intsec_rectside_ - 1;
    zero3(nvector_);
    nvector_[side] = -sgn(dir[side]);
  } else if (m.form == kFormPlane) {
    nvector_[0] = -m.abc[0];
    nvector_[1] = -m.abc[1];
    nvector_[2] = -m.abc[2];
  } else {
    const R p0 = intersection_point_[0] - m.center[0];
    const R p1 = intersection_point_[1] - m.center[1];
    const R p2 = intersection_point_[2] - m.center[2];
    const R d0 = p0 * m.abc[0];
    const R d1 = p1 * m.abc[1];
    const R d2 = p2 * m.abc[2];
    if (m.rotated == 0) {
      nvector_[0] = d0;
      nvector_[1] = d1;
      nvector_[2] = d2;
    } else {
      nvector_[0] = d0 + (p1 * m.rot[2] + p2 * m.rot[1]) * R(0.5);
      nvector_[1] = d1 + (p0 * m.rot[2] + p2 * m.rot[0]) * R(0.5);
      nvector_[2] = d2 + (p0 * m.rot[1] + p1 * m.rot[0]) * R(0.5);
    }
    normalize(nvector_, m.inverted);
  }
}

template <MathPolicy M>
inline auto Tracer<M>::utexture(const Object& m, const R* p) -> void {
  copy3(texture_color_, m.color);
  switch (m.texture) {
    case kTextureChecker: {
      const R w1 = p[0] - m.center[0];
      const bool flag1 = w1 - M::floor(w1 * R(0.05)) * R(20.0) < R(10.0);
      const R w3 = p[2] - m.center[2];
      const bool flag2 = w3 - M::floor(w3 * R(0.05)) * R(20.0) < R(10.0);
      texture_color_[1] = flag1 == flag2 ? R(255.0) : R(0.0);
      break;
    }
    case kTextureStripes: {
      const R w2 = sqr(M::sin(p[1] * R(0.25)));
      texture_color_[0] = R(255.0) * w2;
      texture_color_[1] = R(255.0) * (R(1.0) - w2);
      break;
    }
    case kTextureRings: {
      const R w1 = p[0] - m.center[0];
      const R w3 = p[2] - m.center[2];
      const R w2 = M::sqrt(sqr(w1) + sqr(w3)) / R(10.0);
      const R w4 = (w2 - M::floor(w2)) * R(3.1415927);
      const R cws = sqr(M::cos(w4));
      texture_color_[1] = cws * R(255.0);
      texture_color_[2] = (R(1.0) - cws) * R(255.0);
      break;
    }
    case kTextureSpots: {
      const R w1 = (p[0] - m.center[0]) * M::sqrt(m.abc[0]);
      const R w3 = (p[2] - m.center[2]) * M::sqrt(m.abc[2]);
      const R w4 = sqr(w1) + sqr(w3);
      const R w7 = fabs(w1) < R(1.0e-4) ? R(15.0)
                                         : M::atan(fabs(w3 / w1)) * R(30.0) / R(3.1415927);
      const R w9 = w7 - M::floor(w7);
      const R w2 = (p[1] - m.center[1]) * M::sqrt(m.abc[1]);
      const R w8 = fabs(w4) < R(1.0e-4) ? R(15.0)
                                         : M::atan(fabs(w2 / w4)) * R(30.0) / R(3.1415927);
      const R w10 = w8 - M::floor(w8);
      const R w11 = R(0.15) - sqr(R(0.5) - w9) - sqr(R(0.5) - w10);
      const R w12 = w11 < R(0) ? R(0.0) : w11;
      texture_color_[2] = R(255.0) * w12 / R(0.3);
      break;
    }
    default:
      break;
  }
}

}  // namespace minrt
