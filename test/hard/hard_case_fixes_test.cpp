// What the hard cases (test/hard/scenes) found, each pinned where it was
// caused, in double and in the board's float.
#include <catch2/catch.hpp>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "render/general/quadric_shape.hpp"

namespace {

using namespace minrt;

// An axis-aligned ellipsoid with semi-axes (1, thin, 1) at the origin, as
// EASTRAY's kind 3 is in its local frame: x^2 + y^2/thin^2 + z^2 - 1 < 0.
template <class R>
model::Quadric<R> thin_ellipsoid(R thin) {
  model::Quadric<R> s{};
  s.shape = model::QuadricShape::kQuadric;
  s.q[0] = R(1), s.q[1] = R(1) / (thin * thin), s.q[2] = R(1), s.q[9] = R(-1);
  return s;
}

template <class M>
int crossings_of(const model::Quadric<typename M::real>& s, Vec3<typename M::real> o, Vec3<typename M::real> d) {
  general::Crossing<typename M::real> out[4];
  return general::crossings<M>(s, o, d, typename M::real(0), typename M::real(1e30), out);
}

template <class M>
void check_thin_ellipsoid(typename M::real thin) {
  using R = typename M::real;
  const auto s = thin_ellipsoid<R>(thin);
  // Through the disc's plane outside its rim (x = 3 at y = 0): no crossing,
  // at any slope. The discriminant b^2 - 4ac of these rays cancels terms of
  // 1/thin^2 times the origin's size squared; only a form without that
  // cancellation says "miss".
  for (const R slope : {R(0.001), R(0.1), R(0.7), R(3)}) {
    INFO("slope " << slope);
    CHECK(crossings_of<M>(s, Vec3<R>{R(3) - R(2) * slope, R(2), R(0.5)}, Vec3<R>{slope, R(-1), R(0)}) == 0);
    CHECK(crossings_of<M>(s, Vec3<R>{R(-5), R(2) * slope, R(2)}, Vec3<R>{R(1), -slope, R(0)}) == 0);
  }
  // Through its middle: two crossings, about thin apart along y.
  general::Crossing<R> out[4];
  REQUIRE(general::crossings<M>(s, Vec3<R>{R(0.2), R(2), R(0.1)}, Vec3<R>{R(0), R(-1), R(0)}, R(0), R(1e30), out) == 2);
  CHECK(out[0].t == Approx(2 - thin * 0.97468).epsilon(1e-3));
  CHECK(out[1].t == Approx(2 + thin * 0.97468).epsilon(1e-3));
}

}  // namespace

TEST_CASE("a thin quadric: no crossing where a ray passes its rim", "[hard][eastray]") {
  check_thin_ellipsoid<LibmDouble>(1e-8);
  check_thin_ellipsoid<LibmDouble>(1e-30);
  check_thin_ellipsoid<LibmFloat>(1e-4f);
  check_thin_ellipsoid<PortableFloat>(1e-4f);
  check_thin_ellipsoid<PortableFloat>(1e-3f);
}
