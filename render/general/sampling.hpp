// Random samples the general tracer draws, all from the counter-based
// generator (core/base/counter_rng.hpp), so a pixel's samples are the same on
// the host, on the board and in any thread.
#pragma once

#include "core/base/counter_rng.hpp"
#include "core/math/vec3.hpp"

namespace minrt::general {

inline constexpr int kBallTries = 64;  // rejection sampling; P(64 misses) < 1e-20

// Uniform in [-1, 1).
template <class M>
typename M::real signed_unit(CounterRng& rng) {
  using R = typename M::real;
  return rng.uniform<M>() * R(2) - R(1);
}

// Three independent standard normal values by Box-Muller (log, sqrt, cos,
// sin from the math policy).
template <class M>
Vec3<typename M::real> gaussian3(CounterRng& rng) {
  using R = typename M::real;
  constexpr R kTwoPi = static_cast<R>(6.28318530717958647692);
  auto pair = [&](R& a, R& b) {
    const R u1 = R(1) - rng.uniform<M>();  // (0, 1]: log is finite
    const R u2 = rng.uniform<M>();
    const R radius = M::sqrt(R(-2) * M::log(u1));
    a = radius * M::cos(kTwoPi * u2);
    b = radius * M::sin(kTwoPi * u2);
  };
  Vec3<R> g;
  R spare;
  pair(g.x, g.y);
  pair(g.z, spare);
  return g;
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
