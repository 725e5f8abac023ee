// CS418's shading (SPEC.md 1.3), the general tracer's policy for the
// course's scenes: direct light from suns and bulbs with shadows,
// reflection, refraction, roughness and global illumination, the texel
// look-up, and the pixel (exposure, sRGB, alpha). The order of operations
// at a hit is in docs/cs418.md (conventions).
#pragma once

#include <stdint.h>

#include "core/base/counter_rng.hpp"
#include "core/image/srgb.hpp"
#include "render/general/sampling.hpp"
#include "render/general/surface_maps.hpp"
#include "render/general/tracer.hpp"

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

template <class M, uint32_t F>
class Cs418Shader : public TracerCore<M, F> {
  using R = typename M::real;
  using Base = TracerCore<M, F>;

 public:
  using Base::Base;

  // Colour along a ray; `hit` false when it meets nothing.
  // `weight` bounds how much this ray can still change the pixel: children
  // whose weight falls below the renderer's cut-off are not traced.
  Sample<R> trace(const Ray<R>& ray, int depth, int gi_level, R weight, R eps, CounterRng& rng) const {
    Hit<R> h{};
    this->nearest(ray, eps, h);
    if (h.kind == HitKind::kNone) return {{}, false};
    return {shade(ray, h, depth, gi_level, weight, rng), true};
  }

  // The colour of a primary ray whose hit `h` (not kNone) was found apart,
  // by nearest_packet: what trace(ray, 0, 0, 1, 0, rng) gives.
  Vec3<R> shade_primary(const Ray<R>& ray, const Hit<R>& h, CounterRng& rng) const {
    return shade(ray, h, 0, 0, R(1), rng);
  }

  // The pixel's bytes from the sum of its `hits` samples' colours (of
  // s.samples): the mean, exposure, sRGB; alpha the share of samples that
  // hit; (0, 0, 0, 0) where none did.
  // Inlined into the row loop, as it was written there (the firmware's
  // counts).
  [[gnu::always_inline]] static inline void pixel(const model::Scene<R>& s, const Vec3<R>& sum, int32_t hits,
                                                  uint8_t* px_out) {
    if (hits == 0) {
      px_out[0] = px_out[1] = px_out[2] = px_out[3] = 0;
      return;
    }
    Vec3<R> c = hits == 1 ? sum : sum / M::from_int(hits);
    if constexpr ((F & kExposure) != 0) {
      if (s.exposure) {
        c = Vec3<R>{R(1) - M::exp(-s.exposure_value * c.x), R(1) - M::exp(-s.exposure_value * c.y),
                    R(1) - M::exp(-s.exposure_value * c.z)};
      }
    }
    px_out[0] = srgb_encode<R>(c.x);
    px_out[1] = srgb_encode<R>(c.y);
    px_out[2] = srgb_encode<R>(c.z);
    px_out[3] = alpha(hits, s.samples);
  }

 private:
  using Base::light_dirs_;
  using Base::max_abs;
  using Base::min_weight_;
  using Base::occluded;
  using Base::s_;

  // floor(255 hits / samples), in 32 bits while 255 * samples fits (any
  // count aa asks for).
  static uint8_t alpha(int32_t hits, int32_t samples) {
    const uint32_t h = static_cast<uint32_t>(hits), n = static_cast<uint32_t>(samples);
    if constexpr ((F & kLensOrAa) != 0) {
      if (n > 0xffffffffu / 255u)
        return static_cast<uint8_t>(static_cast<uint64_t>(h) * 255u / static_cast<uint64_t>(n));
    }
    return static_cast<uint8_t>(255u * h / n);
  }

  Vec3<R> shade(const Ray<R>& ray, const Hit<R>& hit, int depth, int gi_level, R weight, CounterRng& rng) const {
    // A local of the shading, not an argument: the compiler keeps its
    // fields in registers (the firmware's counts).
    const SurfaceHit<R> h = this->template surface<false>(ray, hit);
    const Vec3<R> p = h.point;
    Vec3<R> n = h.normal;
    const model::Material<R>& mat = s_.materials[h.material];
    // Roughness perturbs the object's own normal; the two-sided flip then
    // looks at the perturbed one (docs/cs418.md, conventions): at grazing
    // angles a perturbed normal that faces away from the viewer is turned
    // round, away from the light above the surface, as in the reference.
    if constexpr ((F & kRoughness) != 0) {
      // (squarable_direction: a roughness of 1e15 and more would square to
      // infinity in float and leave a zero normal.)
      if (mat.roughness > R(0)) n = rough_normal(n + gaussian3<M>(rng) * mat.roughness);
    }
    const bool entering = dot(ray.dir, n) < R(0);
    if (!entering) n = -n;
    Vec3<R> color = mat.color;
    if constexpr ((F & kTextures) != 0) {
      if (mat.texture != model::kNoTexture && h.kind != HitKind::kPlane) color = texel(h, mat.texture);
    }

    const R eps = static_cast<R>(kSecondaryEpsilon);
    Vec3<R> diffuse{};
    for (uint32_t i = 0; i < s_.light_count; ++i) {
      const model::Light<R>& light = s_.lights[i];
      Vec3<R> dir, energy;
      R limit = kFarDistance<R>;
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


  // normalize(squarable_direction(v)), the same bits, with v's square
  // taken once inline in the usual case (the out-of-line call and the
  // second square cost about 30 instructions a rough hit).
  static Vec3<R> rough_normal(const Vec3<R>& v) {
    if (squarable(v)) [[likely]] return v / M::sqrt(dot(v, v));
    return normalize<M>(squarable_direction(v));
  }

  // Nearest texel, rounding to the closest one (SPEC.md 1.3), decoded from
  // sRGB by table.
  Vec3<R> texel(const SurfaceHit<R>& h, int32_t id) const {
    const model::Texture& tex = s_.textures[id];
    R u, v;
    if (h.kind == HitKind::kSphere) {
      const model::Sphere<R>& sp = s_.spheres[h.index];
      const Vec3<R> q = (h.point - sp.center) / sp.radius;
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
    const uint8_t* c = read_texel<(F & kTexelWatch) != 0>(tex, x, y);
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
};

}  // namespace minrt::general
