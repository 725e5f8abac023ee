// Primary rays of the CS418 cameras (SPEC.md 1.3): flat, fisheye and
// panorama, with optional thin-lens depth of field. Pixel coordinates are
// the integer indices (no half-pixel offset) plus the anti-aliasing jitter.
#pragma once

#include "formats/model/scene.hpp"
#include "render/general/ray.hpp"
#include "render/general/sampling.hpp"

namespace minrt::general {

template <class M>
class CameraRays {
  using R = typename M::real;

 public:
  CameraRays(const model::Scene<R>& scene)
      : cam_(scene.camera),
        w_(M::from_int(scene.width)),
        h_(M::from_int(scene.height)),
        m_(scene.width > scene.height ? w_ : h_),
        fhat_(normalize<M>(scene.camera.forward)) {}

  // The ray through pixel position (x, y); false when the projection has no
  // ray there (fisheye outside its circle).
  bool primary(R x, R y, CounterRng& rng, Ray<R>& ray) const {
    constexpr R kPi = static_cast<R>(3.14159265358979323846);
    Vec3<R> d;
    switch (cam_.projection) {
      case model::Projection::kFlat: {
        const R sx = (R(2) * x - w_) / m_;
        const R sy = (h_ - R(2) * y) / m_;
        d = normalize<M>(cam_.forward + cam_.right * sx + cam_.up * sy);
        break;
      }
      case model::Projection::kFisheye: {
        const R sx = (R(2) * x - w_) / m_;
        const R sy = (h_ - R(2) * y) / m_;
        const R r2 = sx * sx + sy * sy;
        if (r2 > R(1)) return false;
        d = normalize<M>(cam_.right * sx + cam_.up * sy + fhat_ * M::sqrt(R(1) - r2));
        break;
      }
      case model::Projection::kPanorama: {
        const R lon = kPi * (R(2) * x - w_) / w_;
        const R lat = (kPi / R(2)) * (h_ - R(2) * y) / h_;
        d = normalize<M>((cam_.right * M::sin(lon) + fhat_ * M::cos(lon)) * M::cos(lat) + cam_.up * M::sin(lat));
        break;
      }
    }
    ray.origin = cam_.eye;
    ray.dir = d;
    if (cam_.depth_of_field) {
      // Lens offsets uniform on the square [-1, 1)^2: the course's reference
      // image matches this, not the disk its text describes (SPEC.md 1.6).
      const Vec3<R> target = cam_.eye + d * cam_.focus;
      const R a = signed_unit<M>(rng);
      const R b = signed_unit<M>(rng);
      ray.origin = cam_.eye + (cam_.right * a + cam_.up * b) * cam_.lens;
      ray.dir = normalize<M>(target - ray.origin);
    }
    return true;
  }

 private:
  const model::Camera<R>& cam_;
  R w_, h_, m_;
  Vec3<R> fhat_;
};

}  // namespace minrt::general
