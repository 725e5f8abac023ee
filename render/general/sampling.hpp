// Random samples the general tracer draws, all from the counter-based
// generator (core/base/counter_rng.hpp), so a pixel's samples are the same on
// the host, on the board and in any thread.
#pragma once

#include <stdint.h>

#include "core/base/counter_rng.hpp"
#include "core/math/vec3.hpp"
#include "render/general/normal_tables.hpp"

namespace minrt::general {

inline constexpr int kBallTries = 64;  // rejection sampling; P(64 misses) < 1e-20

// Uniform in [-1, 1).
template <class M>
typename M::real signed_unit(CounterRng& rng) {
  using R = typename M::real;
  return rng.uniform<M>() * R(2) - R(1);
}

// Ziggurat tries for one normal value: a try is turned down with
// probability below 0.013, so 64 refusals in a row (then 0) never happen.
inline constexpr int kNormalTries = 64;

namespace normal_detail {
inline const double* widths(double) { return normal_tables::kWidthD; }
inline const float* widths(float) { return normal_tables::kWidthF; }
inline const double* heights(double) { return normal_tables::kHeightD; }
inline const float* heights(float) { return normal_tables::kHeightF; }
static_assert((normal_tables::kStrips & (normal_tables::kStrips - 1)) == 0, "a strip is a draw's low bits");

// |x| beyond the ziggurat's last strip (x > r, density ~ exp(-x^2/2)):
// r + a with a exponential of rate r, kept when 2b > a^2 for b exponential
// of rate 1 (Marsaglia's tail; about 92 % of tries kept).
template <class M>
typename M::real tail(CounterRng& rng) {
  using R = typename M::real;
  const R r = static_cast<R>(normal_tables::kTailStart);
  for (int i = 0; i < kNormalTries; ++i) {
    const R a = -M::log(R(1) - rng.uniform<M>()) / r;  // (0, 1]: log is finite
    const R b = -M::log(R(1) - rng.uniform<M>());
    if (R(2) * b > a * a) return r + a;
  }
  return r;
}

// A draw's strip (its low bits) and signed 24-bit point across the strip
// (its high bits, [-2^23, 2^23)), and that point's value.
template <class M>
struct ZigguratDraw {
  uint32_t strip;
  int32_t point;
  typename M::real x;
  explicit ZigguratDraw(uint32_t bits)
      : strip(bits & static_cast<uint32_t>(normal_tables::kStrips - 1)),
        point(static_cast<int32_t>(bits) >> 8),
        x(M::from_int(point) * widths(typename M::real{})[strip]) {}
  // Under the curve without a test: inside the width of the strip above.
  bool inside() const { return (point < 0 ? -point : point) < normal_tables::kAccept[strip]; }
};

// The draws that land outside every inner rectangle (about 1.2 %): a wedge
// point is kept if a uniform height across its strip falls under the curve
// (one exp), strip 0's outer points become the tail; a refused draw is
// followed by a new one. Out of line: the caller keeps only the fast path.
template <class M>
[[gnu::noinline]] typename M::real standard_normal_rest(CounterRng& rng, uint32_t bits) {
  using R = typename M::real;
  const R* height = heights(R{});
  for (int i = 1;; ++i) {
    const ZigguratDraw<M> d(bits);
    if (d.inside()) return d.x;
    if (d.strip == 0) {
      const R t = tail<M>(rng);
      return d.point < 0 ? -t : t;
    }
    const R y = height[d.strip] + rng.uniform<M>() * (height[d.strip + 1] - height[d.strip]);
    if (y < M::exp(R(-0.5) * d.x * d.x)) return d.x;
    if (i == kNormalTries) return R(0);
    bits = rng.next_u32();
  }
}
}  // namespace normal_detail

// One standard normal value by the ziggurat (normal_tables.hpp, 128 strips
// of equal area under exp(-x^2/2)): one 32-bit draw picks a strip and a
// point across it; about 98.8 % of draws lie under the curve and are the
// answer with one multiplication, no log, sin or cos (nor their soft-float
// shims on the board). Inlined: a call would cost about as much.
template <class M>
[[gnu::always_inline]] inline typename M::real standard_normal(CounterRng& rng) {
  const uint32_t bits = rng.next_u32();
  const normal_detail::ZigguratDraw<M> d(bits);
  if (d.inside()) [[likely]] return d.x;
  return normal_detail::standard_normal_rest<M>(rng, bits);
}

// Three independent standard normal values, drawn in the order x, y, z.
// Not forced inline: inside the shading it costs the board's scenes
// without roughness 0.35 % more instructions (registers), and saves rough
// scenes only 1 %.
template <class M>
Vec3<typename M::real> gaussian3(CounterRng& rng) {
  using R = typename M::real;
  const R x = standard_normal<M>(rng);
  const R y = standard_normal<M>(rng);
  const R z = standard_normal<M>(rng);
  return {x, y, z};
}

// Uniform in the unit ball, by rejection from the cube.
template <class M>
Vec3<typename M::real> in_unit_ball(CounterRng& rng) {
  using R = typename M::real;
  for (int i = 0; i < kBallTries; ++i) {
    const Vec3<R> q{signed_unit<M>(rng), signed_unit<M>(rng), signed_unit<M>(rng)};
    if (dot(q, q) <= R(1)) return q;
  }
  return Vec3<R>{};
}

}  // namespace minrt::general
