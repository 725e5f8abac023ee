// Ray against sphere, plane and triangle, written as SPEC.md 1.3 states them
// (the CS418 reference images were matched with these exact formulas, so
// their order of operations is kept). `eps` is 0 for primary rays and the
// secondary-ray epsilon otherwise: roots at or below it are ignored.
#pragma once

#include "formats/model/scene.hpp"
#include "render/general/ray.hpp"

namespace minrt::general {

// The sphere's entry distance (its exit when the origin is inside or the
// entry is at or behind eps), or a negative value for a miss. Always
// inlined, for callers that test many spheres in a row (the sun grids);
// hit_sphere below is the same as one function.
template <class M>
[[gnu::always_inline]] inline typename M::real hit_sphere_inline(const model::Sphere<typename M::real>& s,
                                                                 const Ray<typename M::real>& ray,
                                                                 typename M::real eps) {
  using R = typename M::real;
  const Vec3<R> oc = s.center - ray.origin;
  const R r2 = s.radius * s.radius;
  const bool inside = dot(oc, oc) < r2;
  const R tc = dot(oc, ray.dir);
  if (!inside && tc < R(0)) return R(-1);
  const Vec3<R> closest = ray.origin + ray.dir * tc - s.center;
  const R d2 = dot(closest, closest);
  if (!inside && r2 < d2) return R(-1);
  const R under = r2 - d2;
  const R toff = M::sqrt(under > R(0) ? under : R(0));
  R t = inside ? tc + toff : tc - toff;
  if (t <= eps) t = tc + toff;  // a ray leaving the surface it starts on
  return t > eps ? t : R(-1);
}

template <class M>
typename M::real hit_sphere(const model::Sphere<typename M::real>& s, const Ray<typename M::real>& ray,
                            typename M::real eps) {
  return hit_sphere_inline<M>(s, ray, eps);
}

template <class M>
typename M::real hit_plane(const model::Plane<typename M::real>& p, const Ray<typename M::real>& ray,
                           typename M::real eps) {
  using R = typename M::real;
  const R denom = dot(ray.dir, p.normal);
  if (denom == R(0)) return R(-1);
  const R t = dot(p.point - ray.origin, p.normal) / denom;
  return t > eps ? t : R(-1);
}

// Inclusive edges (barycentrics >= -1e-9): strict tests leave holes on
// shared edges (SPEC.md 1.3).
template <class M>
typename M::real hit_triangle(const model::Triangle<typename M::real>& tri, const Ray<typename M::real>& ray,
                              typename M::real eps, typename M::real& b1, typename M::real& b2) {
  using R = typename M::real;
  const R denom = dot(ray.dir, tri.normal);
  if (denom == R(0)) return R(-1);
  const R t = dot(tri.p0 - ray.origin, tri.normal) / denom;
  if (!(t > eps)) return R(-1);
  const Vec3<R> rel = ray.origin + ray.dir * t - tri.p0;
  const R c1 = dot(tri.e1, rel);
  const R c2 = dot(tri.e2, rel);
  const R c0 = R(1) - c1 - c2;
  const R tol = R(-1e-9);
  if (!(c0 >= tol && c1 >= tol && c2 >= tol)) return R(-1);
  b1 = c1;
  b2 = c2;
  return t;
}

}  // namespace minrt::general
