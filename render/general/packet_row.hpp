// A row of a CS418 image on the host with its primary rays traced in
// packets: P neighbouring pixels make their k-th sample's rays, the rays
// are walked through the wide tree together (TracerCore::nearest_packet),
// and each hit is shaded with its pixel's own stream. A pixel's numbers are
// drawn in the order the plain row loop (Renderer::row) draws them: its
// jitter and lens, then the draws of shading that sample, then the next
// sample; pixels' streams are independent, so the bytes are the same.
#pragma once

#include <stdint.h>

#include "core/base/counter_rng.hpp"
#include "formats/model/scene.hpp"
#include "render/general/camera.hpp"
#include "render/general/features.hpp"
#include "render/general/ray.hpp"

namespace minrt::general {

// Rays a packet: eight in one AVX register of floats for the box tests.
inline constexpr int kPacketRays = 8;

template <class M, uint32_t F, int P, class Tracer>
void packet_row(const model::Scene<typename M::real>& s, const Tracer& tracer, const CameraRays<M>& camera,
                uint32_t seed, int y, uint8_t* out) {
  using R = typename M::real;
  struct Pixel {
    CounterRng rng{0, 0};
    Vec3<R> sum{};
    int32_t hits = 0;
  };
  const R half = R(0.5);
  for (int x0 = 0; x0 < s.width; x0 += P) {
    const int n = s.width - x0 < P ? s.width - x0 : P;
    Pixel px[P];
    for (int i = 0; i < n; ++i)
      px[i].rng = CounterRng(seed, static_cast<uint32_t>(y) * static_cast<uint32_t>(s.width) +
                                       static_cast<uint32_t>(x0 + i));
    for (int32_t k = 0; k < s.samples; ++k) {
      Ray<R> rays[P];
      uint32_t active = 0;
      for (int i = 0; i < n; ++i) {
        R fx = M::from_int(x0 + i), fy = M::from_int(y);
        if constexpr ((F & kLensOrAa) != 0) {
          if (s.samples > 1) {
            fx = fx + (px[i].rng.template uniform<M>() - half);
            fy = fy + (px[i].rng.template uniform<M>() - half);
          }
        }
        if (camera.primary(fx, fy, px[i].rng, rays[i])) active |= 1u << i;
      }
      Hit<R> hits[P];
      tracer.template nearest_packet<P>(rays, active, R(0), hits);
      for (uint32_t b = active; b != 0; b &= b - 1) {
        const int i = __builtin_ctz(b);
        if (hits[i].kind == HitKind::kNone) continue;
        px[i].sum += tracer.shade_primary(rays[i], hits[i], px[i].rng);
        ++px[i].hits;
      }
    }
    for (int i = 0; i < n; ++i) Tracer::pixel(s, px[i].sum, px[i].hits, out + 4 * (x0 + i));
  }
}

}  // namespace minrt::general
