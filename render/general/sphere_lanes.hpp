// Ray against a leaf's spheres a vector group at a time (wide_traversal.hpp's
// lanes). The vector part is hit_sphere's arithmetic up to the
// square root, operation for operation (plain + - * and compares, exact in
// every lane), and rejects the spheres the ray misses; each remaining one is
// finished in scalar code with the policy's square root, so a hit has the
// bits hit_sphere gives it.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/model/scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/wide_node.hpp"
#include "render/general/wide_traversal.hpp"

namespace minrt::general {

// Fills tree.wide.spheres from the scene and the reference array; false
// (left unbuilt) when the arena is too small.
template <class R>
bool build_sphere_lanes(const model::Scene<R>& scene, Arena& arena, Bvh<R>& tree) {
  tree.wide.spheres = SphereLanes<R>{};
  if (tree.node_count == 0 || scene.sphere_count == 0) return true;
  uint32_t n = 0;  // references: the leaves' ranges cover 0 .. n-1
  for (uint32_t i = 0; i < tree.node_count; ++i)
    if (tree.nodes[i].count != 0 && tree.nodes[i].index + tree.nodes[i].count > n)
      n = tree.nodes[i].index + tree.nodes[i].count;
  const size_t size = static_cast<size_t>(n) + kSphereLanePad;
  R* x = arena.alloc_zeroed<R>(size);
  R* y = arena.alloc_zeroed<R>(size);
  R* z = arena.alloc_zeroed<R>(size);
  R* r2 = arena.alloc_zeroed<R>(size);
  if (x == nullptr || y == nullptr || z == nullptr || r2 == nullptr) return false;
  for (size_t p = 0; p < size; ++p) {
    const uint32_t ref = p < n ? tree.refs[p] : kTriangleBit;
    if ((ref & (kTriangleBit | kSolidBit)) != 0) {
      r2[p] = R(-1);
      continue;
    }
    const model::Sphere<R>& s = scene.spheres[ref];
    x[p] = s.center.x;
    y[p] = s.center.y;
    z[p] = s.center.z;
    r2[p] = s.radius * s.radius;
  }
  tree.wide.spheres = SphereLanes<R>{x, y, z, r2};
  return true;
}

// A ray's origin and direction in every lane: made once a ray, not once a
// leaf.
template <class R, int kBytes>
struct SphereRay {
  using V = Lanes<R, kBytes>;
  V ox, oy, oz, dx, dy, dz;
  SphereRay() = default;  // an array of a packet's rays, set one by one
  [[gnu::always_inline]] explicit SphereRay(const Ray<R>& ray) {
    splat(ox, ray.origin.x);
    splat(oy, ray.origin.y);
    splat(oz, ray.origin.z);
    splat(dx, ray.dir.x);
    splat(dy, ray.dir.y);
    splat(dz, ray.dir.z);
  }
};

// Calls `found(position, t)` for each sphere among positions first ..
// first+count-1 that the ray meets beyond eps, with hit_sphere's distance,
// in order of position.
template <class M, int kBytes, class Found>
[[gnu::always_inline]] inline void spheres_in_leaf(const SphereLanes<typename M::real>& s, uint32_t first,
                                                   uint32_t count, const SphereRay<typename M::real, kBytes>& ray,
                                                   typename M::real eps, Found found) {
  using R = typename M::real;
  using V = Lanes<R, kBytes>;
  constexpr int kL = kLanes<R, kBytes>;
  const V zero{};
  const V ox = ray.ox, oy = ray.oy, oz = ray.oz, dx = ray.dx, dy = ray.dy, dz = ray.dz;
  const uint32_t end = first + count;
  for (uint32_t p = first; p < end; p += kL) {
    V cx, cy, cz, r2;
    __builtin_memcpy(&cx, s.x + p, sizeof cx);
    __builtin_memcpy(&cy, s.y + p, sizeof cy);
    __builtin_memcpy(&cz, s.z + p, sizeof cz);
    __builtin_memcpy(&r2, s.r2 + p, sizeof r2);
    const V ocx = cx - ox, ocy = cy - oy, ocz = cz - oz;
    const auto inside = ocx * ocx + ocy * ocy + ocz * ocz < r2;
    const V tc = ocx * dx + ocy * dy + ocz * dz;
    const V clx = ox + dx * tc - cx, cly = oy + dy * tc - cy, clz = oz + dz * tc - cz;
    const V d2 = clx * clx + cly * cly + clz * clz;
    const auto met = inside | (~(tc < zero) & ~(r2 < d2));
    // The lanes met, less those past the leaf's end (without a branch: how
    // many lanes the last group keeps varies from leaf to leaf).
    const uint32_t left = end - p;
    const uint32_t keep = left < static_cast<uint32_t>(kL) ? left : static_cast<uint32_t>(kL);
    uint32_t bits = true_lanes<R, kBytes>(met) & ((1u << keep) - 1u);
    while (bits != 0) {
      const int k = __builtin_ctz(bits);
      bits &= bits - 1;
      // A triangle's or the padding's lane (r2 = -1) is met only by a ray
      // with a NaN in it; its position names no sphere.
      if (r2[k] < R(0)) continue;
      const R under = r2[k] - d2[k];
      const R toff = M::sqrt(under > R(0) ? under : R(0));
      R t = inside[k] != 0 ? tc[k] + toff : tc[k] - toff;
      if (t <= eps) t = tc[k] + toff;  // a ray leaving the surface it starts on
      if (t > eps) found(p + static_cast<uint32_t>(k), t);
    }
  }
}

}  // namespace minrt::general
