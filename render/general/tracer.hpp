// The general tracer: nearest hit through the BVH and the plane list, direct
// light with shadows, reflection, refraction, roughness and global
// illumination, as SPEC.md 1.3 gives them for CS418. Templated on the math
// policy (like the min-rt tracer) and on the features the scene uses
// (features.hpp): code for an unused feature is not compiled into the path.
// EASTRAY's finish (quadric solids in CSG trees, meshes, its shading) is a
// path of its own: eastray_shading.hpp.
#pragma once

#include <stdint.h>

#include "core/base/counter_rng.hpp"
#include "core/image/srgb.hpp"
#include "formats/model/scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/csg_intersect.hpp"
#include "render/general/features.hpp"
#include "render/general/intersect.hpp"
#include "render/general/sampling.hpp"
#include "render/general/solid_intersect.hpp"
#include "render/general/simd_dispatch.hpp"
#include "render/general/sphere_lanes.hpp"
#include "render/general/wide_traversal.hpp"

namespace minrt::general {

// Secondary rays ignore hits at or below this distance (SPEC.md 1.3: any
// value from 1e-10 to 1e-3 gives the reference images).
inline constexpr double kSecondaryEpsilon = 1e-4;

// Each secondary ray draws from its own stream, forked by the kind of
// branch, so skipping a branch (the weight cut-off) changes no other
// random number.
inline constexpr uint32_t kBranchReflect = 1;
inline constexpr uint32_t kBranchRefract = 2;
inline constexpr uint32_t kBranchGi = 3;

template <class R>
struct Sample {
  Vec3<R> color;
  bool hit;
};

template <class M, uint32_t F>
class Tracer {
  using R = typename M::real;

 public:
  // `light_dirs`: each sun's normalised direction, computed once at set-up.
  // `objects`: the hierarchy over the CSG tree's objects (kQuadrics).
  Tracer(const model::Scene<R>& scene, const Bvh<R>& bvh, const Vec3<R>* light_dirs, R min_weight,
         const CsgObjects<R>* objects = nullptr)
      : s_(scene), bvh_(bvh), light_dirs_(light_dirs), min_weight_(min_weight), objects_(objects) {}

  // Colour along a ray; `hit` false when it meets nothing.
  // `weight` bounds how much this ray can still change the pixel: children
  // whose weight falls below the renderer's cut-off are not traced.
  Sample<R> trace(const Ray<R>& ray, int depth, int gi_level, R weight, R eps, CounterRng& rng) const {
    Hit<R> h{};
    nearest(ray, eps, h);
    if (h.kind == HitKind::kNone) return {{}, false};
    return {shade(ray, h, depth, gi_level, weight, rng), true};
  }

  // Finish::kEastray (eastray_shading.hpp): the colour a ray from `o` along
  // unit `d` brings back; `medium_half` is the absorption half distance of
  // the body it travels in (0: air, where the mist is).
  Vec3<R> eastray_radiance(const Vec3<R>& o, const Vec3<R>& d, int depth, R weight, R medium_half) const;

 private:
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
        return nearest_wide<16>(ray, eps, h);
      }
    }
    // Ordered traversal: both children's boxes are tested at the parent, the
    // nearer one is entered first and the farther one waits on the stack with
    // its entry distance, so it is dropped if a closer hit turns up first.
    // The order of visits never changes the result: hits are compared by
    // (distance, file order), whatever order they are found in.
    const Vec3<R> inv = inverse_dir(ray.dir);
    auto limit = [&] { return h.kind == HitKind::kNone ? R(3.0e38f) : h.t; };
    struct Entry {
      uint32_t node;
      R t;
    };
    Entry stack[kBvhStack];
    int top = 0;
    if (box_entry(bvh_.nodes[0].box, ray.origin, inv, limit()) < R(0)) return;
    uint32_t current = 0;
    for (;;) {
      const BvhNode<R>& node = bvh_.nodes[current];
      if (node.count == 0) {
        const R lim = limit();
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
        if (e.t <= limit()) {
          current = e.node;
          found = true;
          break;
        }
      }
      if (!found) return;
    }
  }

  void leaf(const BvhNode<R>& node, const Ray<R>& ray, R eps, Hit<R>& h) const {
    for (uint32_t k = 0; k < node.count; ++k) {
      const uint32_t ref = bvh_.refs[node.index + k];
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
      const R t = hit_sphere<M>(s_.spheres[ref], ray, eps);
      if (t > eps) h.offer(t, HitKind::kSphere, ref, s_.spheres[ref].order);
    }
  }

  // References first .. first+count-1 for the wide walk: leaf()'s tests,
  // and its spheres too unless the caller has tested them by vector group.
  // (leaf() stays as it is: it is the board's code, whose counts are measured.)
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

  // The wide tree's walks (wide_traversal.hpp) with vectors of kBytes; the
  // AVX2 copies are the same code compiled for AVX2 (simd_dispatch.hpp).
  template <int kBytes>
  [[gnu::always_inline]] inline void nearest_wide(const Ray<R>& ray, R eps, Hit<R>& h) const {
    const SphereLanes<R>& lanes = bvh_.wide.spheres;
    wide_nearest<kBytes>(
        bvh_.wide, ray, [&]() __attribute__((always_inline)) { return h.kind == HitKind::kNone ? R(3.0e38f) : h.t; },
        [&](uint32_t first, uint32_t count) __attribute__((always_inline)) {
          if (lanes.r2 == nullptr) return leaf_refs<true>(first, count, ray, eps, h);
          spheres_in_leaf<M, kBytes>(lanes, first, count, ray, eps, [&](uint32_t pos, R t) __attribute__((always_inline)) {
            const uint32_t i = bvh_.refs[pos];
            h.offer(t, HitKind::kSphere, i, s_.spheres[i].order);
          });
          if constexpr ((F & (kTriangles | kSolids)) != 0) leaf_refs<false>(first, count, ray, eps, h);
        });
  }

  template <int kBytes>
  [[gnu::always_inline]] inline bool occluded_wide(const Ray<R>& ray, R eps, R limit, uint32_t* cached) const {
    const SphereLanes<R>& lanes = bvh_.wide.spheres;
    return wide_any<kBytes>(bvh_.wide, ray, limit, [&](uint32_t first, uint32_t count) __attribute__((always_inline)) {
      if (lanes.r2 != nullptr) {
        uint32_t blocker = kNoBlocker;
        spheres_in_leaf<M, kBytes>(lanes, first, count, ray, eps, [&](uint32_t pos, R t) __attribute__((always_inline)) {
          if (t < limit) blocker = pos;
        });
        if (blocker != kNoBlocker) {
          if (cached != nullptr) *cached = bvh_.refs[blocker];
          return true;
        }
        if constexpr ((F & (kTriangles | kSolids)) == 0) return false;
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

#if MINRT_AVX2_DISPATCH
  MINRT_TARGET_AVX2 void nearest_wide_avx2(const Ray<R>& ray, R eps, Hit<R>& h) const {
    nearest_wide<kAvx2Bytes<R>>(ray, eps, h);
  }
  MINRT_TARGET_AVX2 bool occluded_wide_avx2(const Ray<R>& ray, R eps, R limit, uint32_t* cached) const {
    return occluded_wide<kAvx2Bytes<R>>(ray, eps, limit, cached);
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
  // light `light`.) The object that last blocked this light is tried first:
  // neighbouring shadow rays are usually blocked by the same one. The cache
  // only saves time; the answer is the same with or without it.
  bool occluded(const Ray<R>& ray, R eps, R limit, uint32_t light) const {
    if constexpr ((F & kPlanes) != 0) {
      for (uint32_t i = 0; i < s_.plane_count; ++i) {
        const R t = hit_plane<M>(s_.planes[i], ray, eps);
        if (t > eps && t < limit) return true;
      }
    }
    if (bvh_.node_count == 0) return false;
    uint32_t* cached = light < kShadowCache ? &shadow_cache_[light] : nullptr;
    if (cached != nullptr && *cached != kNoBlocker && blocks(*cached, ray, eps, limit)) return true;
    if constexpr (kWideBvh) {
      if (bvh_.wide.node_count != 0) {
#if MINRT_AVX2_DISPATCH
        if (bvh_.wide.avx2) return occluded_wide_avx2(ray, eps, limit, cached);
#endif
        return occluded_wide<16>(ray, eps, limit, cached);
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

  // --------------------------------------------------------------- shading
  static R max_abs(const Vec3<R>& v) {
    const R x = v.x < R(0) ? -v.x : v.x, y = v.y < R(0) ? -v.y : v.y, z = v.z < R(0) ? -v.z : v.z;
    return x > y ? (x > z ? x : z) : (y > z ? y : z);
  }

  Vec3<R> shade(const Ray<R>& ray, const Hit<R>& h, int depth, int gi_level, R weight, CounterRng& rng) const {
    if constexpr ((F & kPhong) != 0) {
      if (s_.finish == model::Finish::kMinirt) return shade_phong(ray, h);
    }
    const Vec3<R> p = ray.origin + ray.dir * h.t;
    Vec3<R> n;
    uint32_t mat_index;
    switch (h.kind) {
      case HitKind::kSphere: {
        const model::Sphere<R>& sp = s_.spheres[h.index];
        n = (p - sp.center) / sp.radius;
        mat_index = sp.material;
        break;
      }
      case HitKind::kPlane:
        n = normalize<M>(s_.planes[h.index].normal);
        mat_index = s_.planes[h.index].material;
        break;
      default:
        n = normalize<M>(s_.triangles[h.index].normal);
        mat_index = s_.triangles[h.index].material;
        break;
    }
    const model::Material<R>& mat = s_.materials[mat_index];
    const bool entering = dot(ray.dir, n) < R(0);
    if (!entering) n = -n;
    if constexpr ((F & kRoughness) != 0) {
      if (mat.roughness > R(0)) n = normalize<M>(n + gaussian3<M>(rng) * mat.roughness);
    }
    Vec3<R> color = mat.color;
    if constexpr ((F & kTextures) != 0) {
      if (mat.texture != model::kNoTexture && h.kind != HitKind::kPlane) color = texel(h, p, mat.texture);
    }

    const R eps = static_cast<R>(kSecondaryEpsilon);
    Vec3<R> diffuse{};
    for (uint32_t i = 0; i < s_.light_count; ++i) {
      const model::Light<R>& light = s_.lights[i];
      Vec3<R> dir, energy;
      R limit = R(3.0e38f);
      if constexpr ((F & kBulbs) != 0) {
        if (light.kind == model::LightKind::kBulb) {
          const Vec3<R> v = light.vector - p;
          const R dist2 = dot(v, v);
          const R dist = M::sqrt(dist2);
          dir = v / dist;
          energy = light.color / dist2;
          limit = dist;
        } else {
          dir = light_dirs_[i];
          energy = light.color;
        }
      } else {
        dir = light_dirs_[i];
        energy = light.color;
      }
      const R lambert = dot(n, dir);
      if (!(lambert > R(0))) continue;
      if (occluded(Ray<R>{p, dir}, eps, limit, i)) continue;
      diffuse += color * energy * lambert;
    }
    if constexpr ((F & kGi) != 0) {
      if (gi_level < s_.gi_depth) {
        const Vec3<R> d = normalize<M>(n + in_unit_ball<M>(rng));
        const R w = weight * max_abs(color);
        if (!(w < min_weight_)) {
          CounterRng child = rng.fork(kBranchGi);
          const Sample<R> g = trace(Ray<R>{p, d}, depth, gi_level + 1, w, eps, child);
          if (g.hit) diffuse += color * g.color;
        }
      }
    }
    if constexpr ((F & kSecondary) == 0) {
      return diffuse;
    } else {
      // At the depth limit the surface is purely diffuse (SPEC.md 1.3).
      if (depth >= s_.bounces) return diffuse;
      const Vec3<R> s = mat.shininess;
      const Vec3<R> t = mat.transparency;
      const Vec3<R> one{R(1), R(1), R(1)};
      const R ni = dot(n, ray.dir);
      const Vec3<R> reflect_dir = ray.dir - n * (R(2) * ni);
      Vec3<R> reflected{}, refracted{};
      const R w_reflect = weight * max_abs(s);
      if (w_reflect != R(0) && !(w_reflect < min_weight_)) {
        CounterRng child = rng.fork(kBranchReflect);
        const Sample<R> r = trace(Ray<R>{p, reflect_dir}, depth + 1, gi_level, w_reflect, eps, child);
        if (r.hit) reflected = r.color;
      }
      const Vec3<R> rest = one - s;
      const R w_refract = weight * max_abs(rest * t);
      if (w_refract != R(0) && !(w_refract < min_weight_)) {
        const R eta = entering ? R(1) / mat.ior : mat.ior;
        const R k = R(1) - eta * eta * (R(1) - ni * ni);
        const Vec3<R> dir = k < R(0) ? reflect_dir : ray.dir * eta - n * (eta * ni + M::sqrt(k));
        CounterRng child = rng.fork(kBranchRefract);
        const Sample<R> r = trace(Ray<R>{p, dir}, depth + 1, gi_level, w_refract, eps, child);
        if (r.hit) refracted = r.color;
      }
      return s * reflected + rest * (t * refracted + (one - t) * diffuse);
    }
  }

  // miniRT's shading (phong_shading.hpp).
  Vec3<R> shade_phong(const Ray<R>& ray, const Hit<R>& h) const;

  // EASTRAY's visibility and shading (eastray_shading.hpp).
  struct EastrayHit {
    R t = R(-1);
    Vec3<R> normal{};  // unit outward normal at the hit (smoothed on meshes)
    Vec3<R> geo{};     // the geometric one: which side a new ray starts on
    int32_t material = model::kNoNode;
    bool found = false;
  };
  EastrayHit eastray_nearest(const Vec3<R>& o, const Vec3<R>& d, R t_min, R t_max, bool shadow) const;
  [[gnu::always_inline]] inline void eastray_triangle(uint32_t i, const Vec3<R>& o, const Vec3<R>& d, R t_min, R& t_max, EastrayHit& hit,
                        bool shadow) const;
  Vec3<R> eastray_shadow(const Vec3<R>& p, const Vec3<R>& l, R dist) const;
  Vec3<R> eastray_sky(const Vec3<R>& d) const;
  Vec3<R> eastray_direct(const Vec3<R>& p, const Vec3<R>& start, const Vec3<R>& n, const Vec3<R>& v,
                         const model::EastrayMaterial<R>& m) const;
  Vec3<R> eastray_specular(const model::EastrayMaterial<R>& m, const Vec3<R>& n, const Vec3<R>& v,
                           const Vec3<R>& l, R ndl, R ndv) const;

  // Nearest texel, rounding to the closest one (SPEC.md 1.3), decoded from
  // sRGB by table.
  Vec3<R> texel(const Hit<R>& h, const Vec3<R>& p, int32_t id) const {
    const model::Texture& tex = s_.textures[id];
    R u, v;
    if (h.kind == HitKind::kSphere) {
      const model::Sphere<R>& sp = s_.spheres[h.index];
      const Vec3<R> q = (p - sp.center) / sp.radius;
      constexpr R kPi = static_cast<R>(3.14159265358979323846);
      const R lon = M::atan2(q.x, q.z);
      const R lat = M::atan2(q.y, M::sqrt(q.x * q.x + q.z * q.z));
      u = lon / (R(2) * kPi) + R(0.25);
      v = R(0.5) - lat / kPi;
    } else {
      const model::Triangle<R>& tr = s_.triangles[h.index];
      const R b0 = R(1) - h.b1 - h.b2;
      u = b0 * tr.u[0] + h.b1 * tr.u[1] + h.b2 * tr.u[2];
      v = b0 * tr.v[0] + h.b1 * tr.v[1] + h.b2 * tr.v[2];
    }
    const int32_t x = wrap(u * M::from_int(tex.width), tex.width);
    const int32_t y = wrap(v * M::from_int(tex.height), tex.height);
    const uint8_t* c = tex.rgb + 3 * (static_cast<uint32_t>(y) * static_cast<uint32_t>(tex.width) + static_cast<uint32_t>(x));
    return {srgb_decode<R>(c[0]), srgb_decode<R>(c[1]), srgb_decode<R>(c[2])};
  }
  // round(x) mod n, for any finite x (non-finite gives 0).
  static int32_t wrap(R x, int32_t n) {
    R r = M::floor(x + R(0.5));
    const R nn = M::from_int(n);
    r = r - M::floor(r / nn) * nn;  // into [0, n)
    int32_t i = (r >= R(0) && r < nn) ? M::to_int(r) : 0;
    if (i >= n) i = n - 1;
    return i;
  }

  static constexpr uint32_t kShadowCache = 16;  // lights with a last-blocker cache
  static constexpr uint32_t kNoBlocker = 0xffffffffu;

  const model::Scene<R>& s_;
  const Bvh<R>& bvh_;
  const Vec3<R>* light_dirs_;
  R min_weight_;
  const CsgObjects<R>* objects_;
  // One tracer per row (per thread): the cache is never shared.
  mutable uint32_t shadow_cache_[kShadowCache] = {kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker, kNoBlocker,
                                                  kNoBlocker};
};

}  // namespace minrt::general

#include "render/general/eastray_shading.hpp"
#include "render/general/phong_shading.hpp"
