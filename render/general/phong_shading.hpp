// miniRT's shading (SPEC.md 2.3), the general tracer's policy for miniRT
// scenes: c = colour * ambient + sum over the lights that see the point of
// colour * light * max(0, n.l) + light * ks * max(0, r.v)^n, lights without
// falloff, hard shadows. Normals face the viewer, so the insides of objects
// are lit from inside. Pixels are opaque, black where nothing is hit.
#pragma once

#include <stdint.h>

#include "core/base/counter_rng.hpp"
#include "render/general/surface_maps.hpp"
#include "render/general/tracer.hpp"

namespace minrt::general {

inline constexpr double kSpecularStrength = 0.5;
inline constexpr int kSpecularSquarings = 5;  // exponent 2^5 = 32
// Shadow rays start this far above the surface, relative to the size of the
// point's coordinates (the shared scenes range from units to thousands).
inline constexpr double kShadowBias = 1e-4;

template <class M>
uint8_t minirt_byte(typename M::real c);

template <class M, uint32_t F>
class PhongShader : public TracerCore<M, F> {
  using R = typename M::real;
  using Base = TracerCore<M, F>;

 public:
  using Base::Base;

  // Colour along a ray; `hit` false when it meets nothing. One level: no
  // secondary rays, no random numbers (the signature is the paths' own).
  Sample<R> trace(const Ray<R>& ray, int, int, R, R eps, CounterRng&) const {
    Hit<R> h{};
    this->nearest(ray, eps, h);
    if (h.kind == HitKind::kNone) return {{}, false};
    return {shade_phong(ray, h), true};
  }

  // Opaque, black where nothing is hit: clamp, then floor(255 c).
  [[gnu::always_inline]] static inline void pixel(const model::Scene<R>&, const Vec3<R>& sum, int32_t hits,
                                                  uint8_t* px_out) {
    const Vec3<R> c = hits == 0 ? Vec3<R>{} : sum;
    px_out[0] = minirt_byte<M>(c.x);
    px_out[1] = minirt_byte<M>(c.y);
    px_out[2] = minirt_byte<M>(c.z);
    px_out[3] = 255;
  }

 private:
  using Base::max_abs;
  using Base::occluded;
  using Base::s_;

  Vec3<R> shade_phong(const Ray<R>& ray, const Hit<R>& hit) const;
};

template <class M, uint32_t F>
Vec3<typename M::real> PhongShader<M, F>::shade_phong(const Ray<R>& ray, const Hit<R>& hit) const {
  // Plane normals are unit as stored: the reader normalised them.
  const SurfaceHit<R> h = this->template surface<true>(ray, hit);
  const Vec3<R> p = h.point;
  Vec3<R> n = h.normal;
  const model::Material<R>& mat = s_.materials[h.material];
  Vec3<R> color = mat.color;
  if (mat.checker && h.kind == HitKind::kPlane) color = checker_colour<M>(s_.planes[h.index], n, p, color);
  if constexpr ((F & kTextures) != 0) {
    if (h.kind == HitKind::kSphere) {
      if (mat.texture != model::kNoTexture) color = sphere_colour<M>(n, s_.textures[mat.texture]);
      if (mat.bump != model::kNoTexture) n = bumped_normal<M>(n, s_.textures[mat.bump]);
    }
  }
  if (dot(ray.dir, n) > R(0)) n = -n;

  Vec3<R> out = color * s_.ambient;
  const R scale = max_abs(p);
  const R bias = static_cast<R>(kShadowBias) * (R(1) + scale);
  const Vec3<R> origin = p + n * bias;
  const Vec3<R> view = -ray.dir;
  for (uint32_t i = 0; i < s_.light_count; ++i) {
    const model::Light<R>& light = s_.lights[i];
    const Vec3<R> to_light = light.vector - origin;
    const R dist2 = dot(to_light, to_light);
    if (!(dist2 > R(0))) continue;
    const R dist = M::sqrt(dist2);
    const Vec3<R> l = to_light / dist;
    const R lambert = dot(n, l);
    if (!(lambert > R(0))) continue;
    // Nothing closer than the bias to the light shadows it: a light lying
    // on a plane (room_test2.rt) must not be hidden by that plane.
    if (occluded(Ray<R>{origin, l}, R(0), dist - bias, i)) continue;
    out += color * light.color * lambert;
    if (!s_.specular) continue;
    const Vec3<R> reflected = n * (R(2) * lambert) - l;
    R spec = dot(reflected, view);
    if (spec > R(0)) {
      for (int k = 0; k < kSpecularSquarings; ++k) spec = spec * spec;
      out += light.color * (spec * static_cast<R>(kSpecularStrength));
    }
  }
  return out;
}

// Bytes of a miniRT pixel: clamp to [0, 1], then floor(255 c).
template <class M>
uint8_t minirt_byte(typename M::real c) {
  using R = typename M::real;
  if (!(c > R(0))) return 0;  // NaN too
  if (!(c < R(1))) return 255;
  return static_cast<uint8_t>(M::to_int(M::floor(c * R(255))));
}

}  // namespace minrt::general
