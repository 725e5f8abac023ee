// exp, log and atan2 of the portable policies (portable_exp_log.hpp): error
// against the double-precision C library on a sweep of the float range, and
// the special values the general tracer can meet.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "core/math/math_portable.hpp"

namespace {

double ulps(float got, double want) {
  if (std::isinf(want)) return got == static_cast<float>(want) ? 0.0 : 1e30;
  const float w = static_cast<float>(want);
  float step = std::nextafter(std::fabs(w), INFINITY) - std::fabs(w);
  if (step == 0.0f) step = std::numeric_limits<float>::denorm_min();
  return std::fabs(static_cast<double>(got) - want) / step;
}

float from_bits(uint32_t b) {
  float f;
  std::memcpy(&f, &b, 4);
  return f;
}

}  // namespace

TEMPLATE_TEST_CASE("exp and log stay within their documented ULP bounds", "[shims][exp][log]",
                   minrt::PortableFloat, minrt::PortableFloatMin) {
  double worst_exp = 0, worst_log = 0;
  for (uint32_t b = 0; b < 0x7f800000u; b += 4099) {
    const float x = from_bits(b);
    worst_exp = std::fmax(worst_exp, ulps(TestType::exp(x), std::exp(static_cast<double>(x))));
    worst_exp = std::fmax(worst_exp, ulps(TestType::exp(-x), std::exp(-static_cast<double>(x))));
    worst_log = std::fmax(worst_log, ulps(TestType::log(x), std::log(static_cast<double>(x))));
  }
  CHECK(worst_exp <= 1.02);  // docs/shims.md
  CHECK(worst_log <= 2.0);
}

TEMPLATE_TEST_CASE("atan2 covers every quadrant within 2 ULP", "[shims][atan2]", minrt::PortableFloat) {
  double worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const float y = static_cast<float>(std::sin(i * 0.37) * std::exp(std::fmod(i * 0.013, 20.0) - 10));
    const float x = static_cast<float>(std::cos(i * 0.71) * std::exp(std::fmod(i * 0.017, 20.0) - 10));
    worst = std::fmax(worst, ulps(TestType::atan2(y, x), std::atan2(static_cast<double>(y), static_cast<double>(x))));
  }
  CHECK(worst <= 2.0);
}

TEST_CASE("exp, log and atan2 special values", "[shims][exp][log][atan2]") {
  using P = minrt::PortableFloat;
  CHECK(P::exp(0.0f) == 1.0f);
  CHECK(P::exp(-200.0f) == 0.0f);
  CHECK(std::isinf(P::exp(100.0f)));
  CHECK(std::isnan(P::exp(NAN)));
  CHECK(P::log(1.0f) == 0.0f);
  CHECK(std::isinf(P::log(0.0f)));
  CHECK(P::log(0.0f) < 0.0f);
  CHECK(std::isnan(P::log(-1.0f)));
  CHECK(std::isinf(P::log(INFINITY)));
  CHECK(P::log(from_bits(1)) == Approx(std::log(static_cast<double>(from_bits(1)))).epsilon(1e-6));
  CHECK(P::atan2(0.0f, 0.0f) == 0.0f);
  CHECK(P::atan2(1.0f, 0.0f) == Approx(M_PI / 2));
  CHECK(P::atan2(0.0f, -1.0f) == Approx(M_PI));
  CHECK(P::atan2(-1.0f, -1.0f) == Approx(-3 * M_PI / 4));
}
