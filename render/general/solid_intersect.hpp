// Ray against a finite cylinder or cone with its caps (model/solid.hpp).
// The side is solved in the plane perpendicular to the axis (the parts of
// origin and direction along the axis are removed first), which keeps the
// quadratic well conditioned far from the world origin (cylinders.rt has
// coordinates near 8,000). `part` tells the shading which surface was hit.
#pragma once

#include <stdint.h>

#include "formats/model/solid.hpp"
#include "render/general/ray.hpp"

namespace minrt::general {

inline constexpr uint8_t kSolidSide = 0;
inline constexpr uint8_t kSolidBaseCap = 1;
inline constexpr uint8_t kSolidTopCap = 2;

// The nearest distance beyond eps at which the ray meets the solid, or a
// negative value for a miss.
template <class M>
typename M::real hit_solid(const model::Solid<typename M::real>& s, const Ray<typename M::real>& ray,
                           typename M::real eps, uint8_t& part) {
  using R = typename M::real;
  const Vec3<R> x = ray.origin - s.base;
  const R xv = dot(x, s.axis);
  const R dv = dot(ray.dir, s.axis);
  const Vec3<R> xp = x - s.axis * xv;        // origin, across the axis
  const Vec3<R> dp = ray.dir - s.axis * dv;  // direction, across the axis
  const R k = s.slope;
  const R rx = s.radius + k * xv;  // radius at the origin's height
  R best = R(-1);
  auto offer = [&](R t, uint8_t which) {
    if (t > eps && (best < R(0) || t < best)) {
      best = t;
      part = which;
    }
  };
  // Side: |xp + t dp|^2 = (rx + k dv t)^2, within 0 <= m <= height.
  const R a = dot(dp, dp) - k * k * dv * dv;
  const R b = R(2) * (dot(xp, dp) - k * dv * rx);
  const R c = dot(xp, xp) - rx * rx;
  if (a != R(0)) {
    const R disc = b * b - R(4) * a * c;
    if (disc >= R(0)) {
      const R sq = M::sqrt(disc);
      const R roots[2] = {(-b - sq) / (R(2) * a), (-b + sq) / (R(2) * a)};
      for (const R t : roots) {
        const R m = xv + dv * t;
        if (m >= R(0) && m <= s.height) offer(t, kSolidSide);
      }
    }
  }
  // Caps: discs at m = 0 and m = height where the radius there is positive.
  if (dv != R(0)) {
    auto cap = [&](R m, R radius, uint8_t which) {
      if (!(radius > R(0))) return;
      const R t = (m - xv) / dv;
      const Vec3<R> q = xp + dp * t;
      if (dot(q, q) <= radius * radius) offer(t, which);
    };
    cap(R(0), s.radius, kSolidBaseCap);
    cap(s.height, s.radius + k * s.height, kSolidTopCap);
  }
  return best;
}

// The outward normal at point p of the solid's `part` (not yet turned
// toward the viewer).
template <class M>
Vec3<typename M::real> solid_normal(const model::Solid<typename M::real>& s, const Vec3<typename M::real>& p,
                                    uint8_t part) {
  using R = typename M::real;
  if (part == kSolidBaseCap) return -s.axis;
  if (part == kSolidTopCap) return s.axis;
  const Vec3<R> rel = p - s.base;
  const R m = dot(rel, s.axis);
  // Gradient of |across|^2 - radius(m)^2: across - slope * radius(m) * axis.
  const Vec3<R> g = (rel - s.axis * m) - s.axis * (s.slope * (s.radius + s.slope * m));
  const R g2 = dot(g, g);
  return g2 > R(0) ? g / M::sqrt(g2) : s.axis;  // the cone's tip: any normal will do
}

}  // namespace minrt::general
