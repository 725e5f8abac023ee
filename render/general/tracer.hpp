// The general tracer's geometry: the nearest hit through the BVH and the
// plane list, shadow rays, and the surface at a hit (point, normal,
// material, where on the object). Templated on the math policy (like the
// min-rt tracer) and on the features the scene uses (features.hpp): code
// for an unused feature is not compiled into the path. The shading is a
// policy on top of it, one per format, chosen by the path (features.hpp):
// cs418_shading.hpp, phong_shading.hpp (miniRT), eastray_shading.hpp.
#pragma once

#include <stdint.h>

#include "formats/model/scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/csg_intersect.hpp"
#include "render/general/features.hpp"
#include "render/general/intersect.hpp"
#include "render/general/solid_intersect.hpp"
#include "render/general/simd_dispatch.hpp"
#include "render/general/sphere_lanes.hpp"
#include "render/general/wide_packet.hpp"
#include "render/general/wide_traversal.hpp"

namespace minrt::general {

// The colour a ray brings back; `hit` false when it meets nothing.
template <class R>
struct Sample {
  Vec3<R> color;
  bool hit;
};

// What shading needs of a hit.
template <class R>
struct SurfaceHit {
  Vec3<R> point;
  Vec3<R> normal;  // outward: sphere (p - c) / r, plane and triangle unit, solid unit
  uint32_t material;
  HitKind kind;
  uint32_t index;  // which object of its kind
  R b1, b2;        // triangle barycentrics (its texture coordinates come from them)
};

template <class M, uint32_t F>
class TracerCore {
  using R = typename M::real;

 public:
  // `light_dirs`: each sun's normalised direction, computed once at set-up.
  // `objects`: the hierarchy over the CSG tree's objects (kQuadrics).
  TracerCore(const model::Scene<R>& scene, const Bvh<R>& bvh, const Vec3<R>* light_dirs, R min_weight,
             const CsgObjects<R>* objects = nullptr)
      : s_(scene), bvh_(bvh), light_dirs_(light_dirs), min_weight_(min_weight), objects_(objects) {}

  // The nearest hit of rays[r] into h[r] for each bit r of `active` (h[r]
  // as nearest() leaves it), the rays walked through the wide tree as one
  // packet (wide_packet.hpp) where they share an octant. P: 4 or 8.
  template <int P>
  void nearest_packet(const Ray<R>* rays, uint32_t active, R eps, Hit<R>* h) const {
    if constexpr (kWideBvh) {
      if (bvh_.node_count != 0 && bvh_.wide.node_count != 0) {
        if constexpr ((F & kPlanes) != 0) {
          for (uint32_t b = active; b != 0; b &= b - 1) {
            const int r = __builtin_ctz(b);
            for (uint32_t i = 0; i < s_.plane_count; ++i) {
              const R t = hit_plane<M>(s_.planes[i], rays[r], eps);
              if (t > eps) h[r].offer(t, HitKind::kPlane, i, s_.planes[i].order);
            }
          }
        }
        if (active == 0) return;
#if MINRT_AVX2_DISPATCH
        if (bvh_.wide.avx2) return nearest_packet_avx2<P>(rays, active, eps, h);
#endif
        // 16-byte vectors: four rays at a time.
        for (int q = 0; q < P; q += 4)
          if ((active >> q & 15u) != 0) nearest_packet_wide<4, 16, 16, false>(rays + q, active >> q & 15u, eps, h + q);
        return;
      }
    }
    for (uint32_t b = active; b != 0; b &= b - 1) nearest(rays[__builtin_ctz(b)], eps, h[__builtin_ctz(b)]);
  }

 protected:
  // ------------------------------------------------------------ visibility
  void nearest(const Ray<R>& ray, R eps, Hit<R>& h) const {
    if constexpr ((F & kPlanes) != 0) {
      for (uint32_t i = 0; i < s_.plane_count; ++i) {
        const R t = hit_plane<M>(s_.planes[i], ray, eps);
        if (t > eps) h.offer(t, HitKind::kPlane, i, s_.planes[i].order);
      }
    }
    if (bvh_.node_count == 0) return;
    if constexpr (kWideBvh) {
      if (bvh_.wide.node_count != 0) {
#if MINRT_AVX2_DISPATCH
        if (bvh_.wide.avx2) return nearest_wide_avx2(ray, eps, h);
#endif
        return nearest_wide<16, 16>(ray, eps, h);
      }
    }
    // Ordered traversal: both children's boxes are tested at the parent, the
    // nearer one is entered first and the farther one waits on the stack with
    // its entry distance, so it is dropped if a closer hit turns up first.
    // The order of visits never changes the result: hits are compared by
    // (distance, file order), whatever order they are found in.
    const Vec3<R> inv = inverse_dir(ray.dir);
    struct Entry {
      uint32_t node;
      R t;
    };
    Entry stack[kBvhStack];
    int top = 0;
    if (box_entry(bvh_.nodes[0].box, ray.origin, inv, h.limit()) < R(0)) return;
    uint32_t current = 0;
    for (;;) {
      const BvhNode<R>& node = bvh_.nodes[current];
      if (node.count == 0) {
        const R lim = h.limit();
        const R ta = box_entry(bvh_.nodes[node.index].box, ray.origin, inv, lim);
        const R tb = box_entry(bvh_.nodes[node.index + 1].box, ray.origin, inv, lim);
        if (ta >= R(0) && tb >= R(0)) {
          const bool a_first = ta <= tb;
          stack[top++] = Entry{a_first ? node.index + 1 : node.index, a_first ? tb : ta};
          current = a_first ? node.index : node.index + 1;
          continue;
        }
        if (ta >= R(0)) {
          current = node.index;
          continue;
        }
        if (tb >= R(0)) {
          current = node.index + 1;
          continue;
        }
      } else {
        leaf(node, ray, eps, h);
      }
      // Next waiting node that may still hold something closer.
      bool found = false;
      while (top > 0) {
        const Entry e = stack[--top];
        if (e.t <= h.limit()) {
          current = e.node;
          found = true;
          break;
        }
      }
      if (!found) return;
    }
  }

  void leaf(const BvhNode<R>& node, const Ray<R>& ray, R eps, Hit<R>& h) const {
    leaf_refs<true>(node.index, node.count, ray, eps, h);
  }

  // References first .. first+count-1: a leaf's tests (the binary walk's,
  // the board's), and for the wide walk its spheres too unless the caller
  // has tested them by vector group.
  template <bool kWithSpheres>
  [[gnu::always_inline]] inline void leaf_refs(uint32_t first, uint32_t count, const Ray<R>& ray, R eps,
                                               Hit<R>& h) const {
    for (uint32_t k = 0; k < count; ++k) {
      const uint32_t ref = bvh_.refs[first + k];
      if constexpr ((F & kSolids) != 0) {
        if ((ref & kSolidBit) != 0) {
          const uint32_t i = ref & ~kSolidBit;
          uint8_t part = 0;
          const R t = hit_solid<M>(s_.solids[i], ray, eps, part);
          if (t > eps && h.offer(t, HitKind::kSolid, i, s_.solids[i].order)) h.part = part;
          continue;
        }
      }
      if constexpr ((F & kTriangles) != 0) {
        if ((ref & kTriangleBit) != 0) {
          const uint32_t i = ref & ~kTriangleBit;
          R b1, b2;
          const R t = hit_triangle<M>(s_.triangles[i], ray, eps, b1, b2);
          if (t > eps && h.offer(t, HitKind::kTriangle, i, s_.triangles[i].order)) {
            h.b1 = b1;
            h.b2 = b2;
          }
          continue;
        }
      }
      if constexpr (kWithSpheres) {
        const R t = hit_sphere<M>(s_.spheres[ref], ray, eps);
        if (t > eps) h.offer(t, HitKind::kSphere, ref, s_.spheres[ref].order);
      }
    }
  }

  // The wide tree's walks (wide_traversal.hpp) with the boxes in vectors of
  // kBoxBytes and the spheres in vectors of kBytes; the AVX2 copies are the
  // same code compiled for AVX2 (simd_dispatch.hpp).
  template <int kBoxBytes, int kBytes>
  [[gnu::always_inline]] inline void nearest_wide(const Ray<R>& ray, R eps, Hit<R>& h) const {
    const SphereRay<R, kBytes> sray(ray);
    wide_nearest<kBoxBytes>(
        bvh_.wide, ray, [&]() __attribute__((always_inline)) { return h.limit(); },
        [&](uint32_t first, uint32_t count) __attribute__((always_inline)) {
          nearest_in_leaf<kBytes>(first, count, ray, sray, eps, h);
        });
  }

  // A wide leaf's references first .. first+count-1 for the nearest hit:
  // its spheres a vector group at a time, then any other primitives.
  template <int kBytes>
  [[gnu::always_inline]] inline void nearest_in_leaf(uint32_t first, uint32_t count, const Ray<R>& ray,
                                                     const SphereRay<R, kBytes>& sray, R eps, Hit<R>& h) const {
    const SphereLanes<R>& lanes = bvh_.wide.spheres;
    if (lanes.r2 == nullptr) return leaf_refs<true>(first, count, ray, eps, h);
    spheres_in_leaf<M, kBytes>(lanes, first, count, from_memory(sray), eps, [&](uint32_t pos, R t) __attribute__((always_inline)) {
      // The sphere's file order is read only for a tie: a farther hit
      // leaves its sphere's record untouched (not loaded).
      if (h.kind != HitKind::kNone && !(t <= h.t)) return;
      const uint32_t i = bvh_.refs[pos];
      h.offer(t, HitKind::kSphere, i, s_.spheres[i].order);
    });
    if constexpr ((F & (kTriangles | kSolids)) != 0)
      if (mixed_) leaf_refs<false>(first, count, ray, eps, h);
  }

  template <int kBoxBytes, int kBytes>
  [[gnu::always_inline]] inline bool occluded_wide(const Ray<R>& ray, R eps, R limit, uint32_t* cached) const {
    const SphereLanes<R>& lanes = bvh_.wide.spheres;
    const SphereRay<R, kBytes> sray(ray);
    return wide_any<kBoxBytes>(bvh_.wide, ray, limit, [&](uint32_t first, uint32_t count) __attribute__((always_inline)) {
      if (lanes.r2 != nullptr) {
        uint32_t blocker = kNoBlocker;
        spheres_in_leaf<M, kBytes>(lanes, first, count, sray, eps, [&](uint32_t pos, R t) __attribute__((always_inline)) {
          if (t < limit) blocker = pos;
        });
        if (blocker != kNoBlocker) {
          if (cached != nullptr) *cached = bvh_.refs[blocker];
          return true;
        }
        if constexpr ((F & (kTriangles | kSolids)) == 0) return false;
        if (!mixed_) return false;
      }
      for (uint32_t k = 0; k < count; ++k) {
        const uint32_t ref = bvh_.refs[first + k];
        if (lanes.r2 != nullptr && (ref & (kTriangleBit | kSolidBit)) == 0) continue;
        if (blocks(ref, ray, eps, limit)) {
          if (cached != nullptr) *cached = ref;
          return true;
        }
      }
      return false;
    });
  }

  // The packet's walk, the leaves tested ray by ray as nearest_wide does;
  // rays in several octants are walked one by one.
  template <int P, int kBoxBytes, int kBytes, bool kAvx>
  [[gnu::always_inline]] inline void nearest_packet_wide(const Ray<R>* rays, uint32_t active, R eps,
                                                         Hit<R>* h) const {
    PacketRay<P> packet;
    if (!make_packet_ray<P>(rays, active, packet)) {
      for (uint32_t b = active; b != 0; b &= b - 1) {
        const int r = __builtin_ctz(b);
#if MINRT_AVX2_DISPATCH
        if constexpr (kAvx) {
          nearest_wide_avx2(rays[r], eps, h[r]);
          continue;
        }
#endif
        nearest_wide<kBoxBytes, kBytes>(rays[r], eps, h[r]);
      }
      return;
    }
    SphereRay<R, kBytes> srays[P];
    for (uint32_t b = active; b != 0; b &= b - 1) srays[__builtin_ctz(b)] = SphereRay<R, kBytes>(rays[__builtin_ctz(b)]);
    wide_packet_nearest<P, kAvx>(
        bvh_.wide, packet, active,
        [&](int r) __attribute__((always_inline)) { return h[r].limit(); },
        [&](uint32_t first, uint32_t count, uint32_t which) __attribute__((always_inline)) {
          for (; which != 0; which &= which - 1) {
            const int r = __builtin_ctz(which);
            nearest_in_leaf<kBytes>(first, count, rays[r], srays[r], eps, h[r]);
          }
        });
  }

#if MINRT_AVX2_DISPATCH
  template <int P>
  MINRT_TARGET_AVX2 void nearest_packet_avx2(const Ray<R>* rays, uint32_t active, R eps, Hit<R>* h) const {
    nearest_packet_wide<P, kAvx2BoxBytes, kAvx2Bytes<R>, true>(rays, active, eps, h);
  }
  MINRT_TARGET_AVX2 void nearest_wide_avx2(const Ray<R>& ray, R eps, Hit<R>& h) const {
    nearest_wide<kAvx2BoxBytes, kAvx2Bytes<R>>(ray, eps, h);
  }
  MINRT_TARGET_AVX2 bool occluded_wide_avx2(const Ray<R>& ray, R eps, R limit, uint32_t* cached) const {
    return occluded_wide<kAvx2BoxBytes, kAvx2Bytes<R>>(ray, eps, limit, cached);
  }
#endif

  // Is anything between eps and `limit` along the ray? (Shadow rays.)
  // Does the primitive `ref` (a BVH reference) block the ray before `limit`?
  bool blocks(uint32_t ref, const Ray<R>& ray, R eps, R limit) const {
    R t;
    if constexpr ((F & kSolids) != 0) {
      if ((ref & kSolidBit) != 0) {
        uint8_t part = 0;
        t = hit_solid<M>(s_.solids[ref & ~kSolidBit], ray, eps, part);
        return t > eps && t < limit;
      }
    }
    if constexpr ((F & kTriangles) != 0) {
      if ((ref & kTriangleBit) != 0) {
        R b1, b2;
        t = hit_triangle<M>(s_.triangles[ref & ~kTriangleBit], ray, eps, b1, b2);
        return t > eps && t < limit;
      }
    }
    t = hit_sphere<M>(s_.spheres[ref], ray, eps);
    return t > eps && t < limit;
  }

  // Is anything between eps and `limit` along the ray? (Shadow rays toward
  // light `light`.) A sun grid answers the rays it covers; for the others
  // the object that last blocked this light is tried first: neighbouring
  // shadow rays are usually blocked by the same one. (Before a grid's cell
  // the cache costs more than it saves: it misses most rays there.) The
  // cache only saves time; the answer is the same with or without it.
  bool occluded(const Ray<R>& ray, R eps, R limit, uint32_t light) const {
    if constexpr ((F & kPlanes) != 0) {
      for (uint32_t i = 0; i < s_.plane_count; ++i) {
        const R t = hit_plane<M>(s_.planes[i], ray, eps);
        if (t > eps && t < limit) return true;
      }
    }
    if (bvh_.node_count == 0) return false;
    uint32_t* cached = light < kShadowCache ? &shadow_cache_[light] : nullptr;
    if constexpr (kWideBvh) {
      if (light < bvh_.wide.sun_grid_count && sun_grid_covers(bvh_.wide.sun_grids[light], ray)) {
        return sun_grid_any(bvh_.wide.sun_grids[light], ray.origin, [&](uint32_t i) __attribute__((always_inline)) {
          const R t = hit_sphere_inline<M>(s_.spheres[i], ray, eps);
          return t > eps && t < limit;
        });
      }
    }
    if (cached != nullptr && *cached != kNoBlocker && blocks(*cached, ray, eps, limit)) return true;
    if constexpr (kWideBvh) {
      if (bvh_.wide.node_count != 0) {
#if MINRT_AVX2_DISPATCH
        if (bvh_.wide.avx2) return occluded_wide_avx2(ray, eps, limit, cached);
#endif
        return occluded_wide<16, 16>(ray, eps, limit, cached);
      }
    }
    const Vec3<R> inv = inverse_dir(ray.dir);
    uint32_t stack[kBvhStack];
    int top = 0;
    if (box_entry(bvh_.nodes[0].box, ray.origin, inv, limit) < R(0)) return false;
    stack[top++] = 0;
    while (top > 0) {
      const BvhNode<R>& node = bvh_.nodes[stack[--top]];
      if (node.count == 0) {
        // Both children tested here: only boxes the ray enters are visited.
        if (box_entry(bvh_.nodes[node.index + 1].box, ray.origin, inv, limit) >= R(0)) stack[top++] = node.index + 1;
        if (box_entry(bvh_.nodes[node.index].box, ray.origin, inv, limit) >= R(0)) stack[top++] = node.index;
        continue;
      }
      for (uint32_t k = 0; k < node.count; ++k) {
        const uint32_t ref = bvh_.refs[node.index + k];
        if (blocks(ref, ray, eps, limit)) {
          if (cached != nullptr) *cached = ref;
          return true;
        }
      }
    }
    return false;
  }

  // ---------------------------------------------------------------- surface
  // The surface at hit `h` of `ray`. `kUnitPlanes`: the plane normals are
  // unit as stored (miniRT's reader normalises them); otherwise they are
  // normalised here, in the tracer's precision.
  template <bool kUnitPlanes>
  [[gnu::always_inline]] inline SurfaceHit<R> surface(const Ray<R>& ray, const Hit<R>& h) const {
    SurfaceHit<R> sh;
    sh.point = ray.origin + ray.dir * h.t;
    sh.kind = h.kind;
    sh.index = h.index;
    sh.b1 = h.b1;
    sh.b2 = h.b2;
    switch (h.kind) {
      case HitKind::kSphere: {
        const model::Sphere<R>& sp = s_.spheres[h.index];
        sh.normal = (sh.point - sp.center) / sp.radius;
        sh.material = sp.material;
        break;
      }
      case HitKind::kPlane:
        if constexpr (kUnitPlanes) {
          sh.normal = s_.planes[h.index].normal;
        } else {
          sh.normal = normalize<M>(s_.planes[h.index].normal);
        }
        sh.material = s_.planes[h.index].material;
        break;
      case HitKind::kSolid:
        if constexpr ((F & kSolids) != 0) {
          sh.normal = solid_normal<M>(s_.solids[h.index], sh.point, h.part);
          sh.material = s_.solids[h.index].material;
          break;
        }
        [[fallthrough]];
      default:
        sh.normal = normalize<M>(s_.triangles[h.index].normal);
        sh.material = s_.triangles[h.index].material;
        break;
    }
    return sh;
  }

  static R max_abs(const Vec3<R>& v) {
    const R x = v.x < R(0) ? -v.x : v.x, y = v.y < R(0) ? -v.y : v.y, z = v.z < R(0) ? -v.z : v.z;
    return x > y ? (x > z ? x : z) : (y > z ? y : z);
  }

  static constexpr uint32_t kShadowCache = 16;  // lights with a last-blocker cache
  static constexpr uint32_t kNoBlocker = 0xffffffffu;

  const model::Scene<R>& s_;
  const Bvh<R>& bvh_;
  const Vec3<R>* light_dirs_;
  R min_weight_;
  const CsgObjects<R>* objects_;
  // Whether the hierarchy holds anything besides spheres: a sphere-only
  // scene on a path with triangles skips the leaves' second pass.
  const bool mixed_ = s_.triangle_count + s_.solid_count != 0;
  // One tracer per row (per thread): the cache is never shared.
  mutable uint32_t shadow_cache_[kShadowCache] = {kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker};
};

}  // namespace minrt::general
