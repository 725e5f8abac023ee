// The Jaworski tracer's colour byte (render/jaworski/tracer.hpp, to_byte):
// round-half-to-even of 255 x the value clamped to [0, 1], NaN giving 0, as
// docs/jaworski.md says. Checked against a reference written here another
// way (the product exact in long double, then rounded to the tracer's real;
// the tie rule by integer parity) for double and for both float policies.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "render/jaworski/tracer.hpp"

namespace {

static_assert(std::numeric_limits<long double>::digits >= 64,
              "the reference needs 255 x a double exact in long double");

// 255 x clamp(v), rounded once to R as the tracer's product is; then round
// half to even by the integer part's parity.
template <class R>
int reference_byte(R v) {
  long double c = v;
  if (std::isnan(v) || v < R(0)) c = 0;
  if (v > R(1)) c = 1;
  const R x = static_cast<R>(255.0L * c);  // exact product, one rounding to R
  const long long n = static_cast<long long>(x);
  const long double frac = static_cast<long double>(x) - n;
  if (frac > 0.5L) return static_cast<int>(n + 1);
  if (frac < 0.5L) return static_cast<int>(n);
  return static_cast<int>(n % 2 == 0 ? n : n + 1);
}

// A value whose product with 255 in R is exactly `target`, searched within
// 256 steps of target / 255; false where no value of R gives it.
template <class R>
bool value_for_product(long double target, R& v) {
  const R start = static_cast<R>(target / 255.0L);
  R up = start, down = start;
  for (int i = 0; i < 256; ++i) {
    if (R(255) * up == static_cast<R>(target)) return v = up, true;
    if (R(255) * down == static_cast<R>(target)) return v = down, true;
    up = std::nextafter(up, R(2));
    down = std::nextafter(down, R(-1));
  }
  return false;
}

template <class M>
void check_policy() {
  using R = typename M::real;
  auto to_byte = [](R v) { return static_cast<int>(minrt::jaworski::Tracer<M>::to_byte(v)); };
  INFO(M::name);

  // Every half-integer 0.5 .. 254.5 that 255 x v can give exactly: the tie
  // goes to the even neighbour. Count how many the type can reach.
  int ties = 0;
  for (int k = 0; k < 255; ++k) {
    R v{};
    if (!value_for_product<R>(k + 0.5L, v)) continue;
    ++ties;
    INFO("v = " << static_cast<double>(v) << ", 255 v = " << k << ".5");
    CHECK(to_byte(v) == (k % 2 == 0 ? k : k + 1));
    CHECK(to_byte(v) == reference_byte(v));
    // The nearest values whose products are not the tie round to the
    // nearer integer (a few neighbours of v may share its product).
    R above = v, below = v;
    while (R(255) * above == R(k + 0.5L)) above = std::nextafter(above, R(2));
    while (R(255) * below == R(k + 0.5L)) below = std::nextafter(below, R(-1));
    CHECK(to_byte(above) == k + 1);
    CHECK(to_byte(below) == k);
  }
  CHECK(ties == 255);  // every half-integer is reachable in both types

  // Every integer exactly, and a sweep of values against the reference.
  for (int k = 0; k <= 255; ++k) {
    R v{};
    REQUIRE(value_for_product<R>(k, v));
    CHECK(to_byte(v) == k);
  }
  for (int i = 0; i <= 100000; ++i) {
    const R v = static_cast<R>(i / 100000.0L);
    CHECK(to_byte(v) == reference_byte(v));
  }

  // Clamping, infinities, signed zero and NaN (documented: NaN gives 0).
  const R inf = std::numeric_limits<R>::infinity();
  const R nan = std::numeric_limits<R>::quiet_NaN();
  CHECK(to_byte(R(0)) == 0);
  CHECK(to_byte(-R(0)) == 0);
  CHECK(to_byte(R(1)) == 255);
  CHECK(to_byte(std::nextafter(R(1), R(2))) == 255);
  CHECK(to_byte(R(1.5)) == 255);
  CHECK(to_byte(R(1e30)) == 255);
  CHECK(to_byte(inf) == 255);
  CHECK(to_byte(-std::numeric_limits<R>::denorm_min()) == 0);
  CHECK(to_byte(R(-0.5)) == 0);
  CHECK(to_byte(-inf) == 0);
  CHECK(to_byte(nan) == 0);
  CHECK(to_byte(-nan) == 0);
  CHECK(to_byte(std::numeric_limits<R>::denorm_min()) == 0);
}

}  // namespace

TEST_CASE("Jaworski colour byte: round half to even of 255 x the clamped value, NaN 0", "[jaworski][unit]") {
  check_policy<minrt::LibmDouble>();
  check_policy<minrt::LibmFloat>();
  check_policy<minrt::PortableFloat>();
}
