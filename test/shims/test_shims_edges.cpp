// Special values and exact cases of the portable math shims, for every level.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "core/math/math_portable.hpp"
#include "ulp_stats.hpp"

using minrt::PortableFloatT;
using shim_ulp::bits_of;
using shim_ulp::float_of;

namespace {
constexpr float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kMinSub = 0x1p-149f;
constexpr float kMaxSub = 0x1.fffffcp-127f;
constexpr float kMax = std::numeric_limits<float>::max();

bool same_bits(float a, float b) { return bits_of(a) == bits_of(b); }
bool is_neg_zero(float x) { return bits_of(x) == 0x80000000u; }
bool is_pos_zero(float x) { return bits_of(x) == 0u; }
}  // namespace

// The functions are constexpr.
static_assert(minrt::PortableFloat::floor(-1.5f) == -2.0f);
static_assert(minrt::PortableFloat::sqrt(6.25f) == 2.5f);
static_assert(minrt::PortableFloat::to_int(255.9f) == 255);
static_assert(minrt::PortableFloat::from_int(16777217) == 16777216.0f);
static_assert(std::string_view(minrt::PortableFloatT<2>::name) == "float/portable");
static_assert(std::string_view(minrt::PortableFloatT<1>::name) == "float/portable-fast");
static_assert(std::string_view(minrt::PortableFloatT<0>::name) == "float/portable-min");
static_assert(minrt::PortableFloatMin::sin(0.5f) > 0.479f && minrt::PortableFloatMin::sin(0.5f) < 0.48f);
static_assert(minrt::PortableFloatMin::atan(1.0f) > 0.785f);

TEMPLATE_TEST_CASE("floor special values and boundaries", "[shims][floor]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  CHECK(is_pos_zero(P::floor(0.0f)));
  CHECK(is_neg_zero(P::floor(-0.0f)));
  CHECK(P::floor(kInf) == kInf);
  CHECK(P::floor(-kInf) == -kInf);
  CHECK(std::isnan(P::floor(kNaN)));
  CHECK(std::isnan(P::floor(-kNaN)));
  CHECK(is_pos_zero(P::floor(kMinSub)));
  CHECK(P::floor(-kMinSub) == -1.0f);
  CHECK(P::floor(-kMaxSub) == -1.0f);
  CHECK(is_pos_zero(P::floor(0.5f)));
  CHECK(is_pos_zero(P::floor(0.99999994f)));
  CHECK(P::floor(-0.5f) == -1.0f);
  CHECK(P::floor(-0.99999994f) == -1.0f);
  CHECK(P::floor(1.0f) == 1.0f);
  CHECK(P::floor(-1.0f) == -1.0f);
  CHECK(P::floor(1.5f) == 1.0f);
  CHECK(P::floor(-1.5f) == -2.0f);
  CHECK(P::floor(-2.5f) == -3.0f);
  // Carry into the exponent: -(2^k - 1/2) -> -2^k.
  CHECK(P::floor(-1.5f) == -2.0f);
  CHECK(P::floor(-3.75f) == -4.0f);
  CHECK(P::floor(-8388607.5f) == -8388608.0f);
  CHECK(P::floor(8388607.5f) == 8388607.0f);
  CHECK(P::floor(8388608.0f) == 8388608.0f);
  CHECK(P::floor(-8388609.0f) == -8388609.0f);
  CHECK(P::floor(1e30f) == 1e30f);
  CHECK(P::floor(-1e30f) == -1e30f);
  CHECK(P::floor(kMax) == kMax);
  CHECK(P::floor(-kMax) == -kMax);
  // Every n + 1/2 and -(n + 1/2) up to 2^22.
  for (std::int32_t n = 0; n < (1 << 22); n += 37) {
    const float x = float(n) + 0.5f;
    REQUIRE(P::floor(x) == float(n));
    REQUIRE(P::floor(-x) == -float(n) - 1.0f);
  }
}

TEMPLATE_TEST_CASE("sqrt special values and exact squares", "[shims][sqrt]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  CHECK(is_pos_zero(P::sqrt(0.0f)));
  CHECK(is_neg_zero(P::sqrt(-0.0f)));
  CHECK(std::isnan(P::sqrt(-1.0f)));
  CHECK(std::isnan(P::sqrt(-kMinSub)));
  CHECK(std::isnan(P::sqrt(-kInf)));
  CHECK(std::isnan(P::sqrt(kNaN)));
  CHECK(P::sqrt(kInf) == kInf);
  // Exact powers of two at levels 1 and 2; level 0 returns the Newton
  // estimate uncorrected, so only within its few ULPs (sqrt(1) may be
  // 1 - 2^-24).
  for (float x : {1.0f, 4.0f, 0.25f, 0x1p-148f, 0x1p126f}) {
    if (P::level >= 1) {
      CHECK(P::sqrt(x) == float(std::sqrt(double(x))));
    } else {
      CHECK(shim_ulp::ulp_error(P::sqrt(x), std::sqrt(double(x))) < 3.0);
    }
  }
  // Correctly rounded at level 2, within an ULP at level 1, within 3 ULP at
  // level 0 (no correction after the Newton steps).
  for (float x : {kMinSub, kMaxSub, 0x1p-126f, kMax, 2.0f, 3.0f, 0.1f}) {
    if (P::level >= 2) {
      CHECK(same_bits(P::sqrt(x), std::sqrt(x)));
    } else {
      CHECK(shim_ulp::ulp_error(P::sqrt(x), std::sqrt(double(x))) < (P::level == 1 ? 1.0 : 3.0));
    }
  }
  // Perfect squares are exact at levels 1 and 2; level 0 only keeps them
  // within its few ULPs.
  for (std::int32_t k = 1; k <= 4096; ++k) {
    if (P::level >= 1) {
      REQUIRE(P::sqrt(float(k) * float(k)) == float(k));
    } else {
      REQUIRE(shim_ulp::ulp_error(P::sqrt(float(k) * float(k)), double(k)) < 3.0);
    }
  }
}

TEMPLATE_TEST_CASE("sin/cos special values and symmetry", "[shims][sin][cos]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  CHECK(is_pos_zero(P::sin(0.0f)));
  CHECK(is_neg_zero(P::sin(-0.0f)));
  CHECK(P::cos(0.0f) == 1.0f);
  CHECK(P::cos(-0.0f) == 1.0f);
  CHECK(same_bits(P::sin(kMinSub), kMinSub));
  CHECK(same_bits(P::sin(-kMaxSub), -kMaxSub));
  CHECK(P::cos(kMinSub) == 1.0f);
  for (float x : {kInf, -kInf, kNaN}) {
    CHECK(std::isnan(P::sin(x)));
    CHECK(std::isnan(P::cos(x)));
  }
  for (float x : {1e-3f, 0.5f, 0.785398f, 1.0f, 2.0f, 3.14159265f, 100.0f,
                  4539.08f, 1e4f, 1e6f, 1e22f, kMax}) {
    CHECK(same_bits(P::sin(-x), -P::sin(x)));
    CHECK(same_bits(P::cos(-x), P::cos(x)));
    // Bounded and close to the reference even for huge arguments.
    const double bound = P::level == 0 ? 3.5 : 2.5;
    CHECK(shim_ulp::ulp_error(P::sin(x), std::sin(double(x))) < bound);
    CHECK(shim_ulp::ulp_error(P::cos(x), std::cos(double(x))) < bound);
  }
  // Around multiples of pi/2 the result is tiny; the reduction must keep it
  // accurate in relative terms.
  const float pi_f = 3.14159274f;
  CHECK(std::fabs(P::sin(pi_f) - std::sin(double(pi_f))) <
        std::fabs(std::sin(double(pi_f))) * 0x1p-20);
  CHECK(std::fabs(P::cos(pi_f / 2) - std::cos(double(pi_f / 2))) <
        std::fabs(std::cos(double(pi_f / 2))) * 0x1p-20);
}

TEMPLATE_TEST_CASE("atan special values and symmetry", "[shims][atan]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  const float half_pi = float_of(0x3fc90fdbu);  // pi/2 rounded to float
  CHECK(is_pos_zero(P::atan(0.0f)));
  CHECK(is_neg_zero(P::atan(-0.0f)));
  CHECK(same_bits(P::atan(kMinSub), kMinSub));
  CHECK(same_bits(P::atan(-kMaxSub), -kMaxSub));
  CHECK(std::isnan(P::atan(kNaN)));
  CHECK(P::atan(kInf) == half_pi);
  CHECK(P::atan(-kInf) == -half_pi);
  CHECK(P::atan(kMax) == half_pi);
  CHECK(P::atan(1e30f) == half_pi);
  CHECK(P::atan(1.0f) == float_of(0x3f490fdbu));  // pi/4
  for (float x : {1e-5f, 0.4375f, 0.5f, 0.6875f, 1.0f, 1.1875f, 2.4375f, 10.0f, 1e6f,
                  0x1.a8279ap-2f, 0x1.3504f4p+1f}) {
    CHECK(same_bits(P::atan(-x), -P::atan(x)));
  }
}

TEMPLATE_TEST_CASE("from_int rounds to nearest even", "[shims][from_int]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  constexpr std::int32_t kMinI = std::numeric_limits<std::int32_t>::min();
  constexpr std::int32_t kMaxI = std::numeric_limits<std::int32_t>::max();
  CHECK(is_pos_zero(P::from_int(0)));
  CHECK(P::from_int(1) == 1.0f);
  CHECK(P::from_int(-1) == -1.0f);
  CHECK(P::from_int(255) == 255.0f);
  CHECK(P::from_int(kMaxI) == 0x1p31f);
  CHECK(P::from_int(kMinI) == -0x1p31f);
  CHECK(P::from_int(kMinI + 1) == -0x1p31f);
  CHECK(P::from_int(16777216) == 16777216.0f);
  CHECK(P::from_int(16777217) == 16777216.0f);  // tie -> even
  CHECK(P::from_int(16777219) == 16777220.0f);  // tie -> even
  CHECK(P::from_int(-16777219) == -16777220.0f);
  CHECK(P::from_int(16777218) == 16777218.0f);
  // Halfway, just below and just above halfway, at every shift.
  for (int drop = 1; drop <= 7; ++drop) {
    for (std::int32_t m = 0x800000; m < 0x1000000; m += 4099) {
      const std::int32_t base = m << drop, half = 1 << (drop - 1);
      for (std::int32_t i : {base + half, base + half - 1, base + half + 1, base}) {
        REQUIRE(same_bits(P::from_int(i), static_cast<float>(i)));
        REQUIRE(same_bits(P::from_int(-i), static_cast<float>(-i)));
      }
    }
  }
}

TEMPLATE_TEST_CASE("to_int truncates toward zero", "[shims][to_int]",
                   PortableFloatT<0>, PortableFloatT<1>, PortableFloatT<2>) {
  using P = TestType;
  CHECK(P::to_int(0.0f) == 0);
  CHECK(P::to_int(-0.0f) == 0);
  CHECK(P::to_int(kMinSub) == 0);
  CHECK(P::to_int(0.5f) == 0);
  CHECK(P::to_int(-0.5f) == 0);
  CHECK(P::to_int(0.99999994f) == 0);
  CHECK(P::to_int(1.0f) == 1);
  CHECK(P::to_int(1.5f) == 1);
  CHECK(P::to_int(-1.5f) == -1);
  CHECK(P::to_int(2.5f) == 2);
  CHECK(P::to_int(255.99998f) == 255);
  CHECK(P::to_int(8388607.5f) == 8388607);
  CHECK(P::to_int(16777216.0f) == 16777216);
  CHECK(P::to_int(2147483520.0f) == 2147483520);
  CHECK(P::to_int(-2147483520.0f) == -2147483520);
  CHECK(P::to_int(-0x1p31f) == std::numeric_limits<std::int32_t>::min());
  // Outside int32 (undefined for a C cast): saturates; NaN gives 0.
  CHECK(P::to_int(0x1p31f) == std::numeric_limits<std::int32_t>::max());
  CHECK(P::to_int(-kInf) == std::numeric_limits<std::int32_t>::min());
  CHECK(P::to_int(kNaN) == 0);
  // The renderer's range [0, 256): every 61st float, and all n + 1/2.
  std::uint64_t mismatches = 0;
  for (std::uint32_t b = 0; b < 0x43800000u; b += 61) {
    const float x = float_of(b);
    if (P::to_int(x) != static_cast<std::int32_t>(x)) ++mismatches;
  }
  CHECK(mismatches == 0);
  for (std::int32_t n = 0; n < (1 << 22); n += 41) {
    REQUIRE(P::to_int(float(n) + 0.5f) == n);
    REQUIRE(P::to_int(-(float(n) + 0.5f)) == -n);
  }
}

TEST_CASE("Payne-Hanek and Cody-Waite reductions agree where both apply",
          "[shims][sin][cos][reduction]") {
  namespace d = minrt::portable_detail;
  const double half_pi = 1.5707963267948966;
  double worst = 0.0;
  for (std::uint32_t b = bits_of(2.0f); b < bits_of(8192.0f); b += 997) {
    const d::Reduced ph = d::reduce_payne_hanek(b);
    const d::Reduced cw = d::reduce_cody_waite<true>(float_of(b));
    // The quadrants may differ by one where r is close to +-pi/4.
    const int dq = int((ph.quadrant - cw.quadrant) & 3u);
    const double turn = dq == 3 ? -1.0 : double(dq);
    REQUIRE(dq != 2);
    const double diff = (double(ph.hi) + double(ph.lo)) -
                        (double(cw.hi) + double(cw.lo)) + turn * half_pi;
    worst = std::fmax(worst, std::fabs(diff));
  }
  INFO("largest difference " << worst);
  CHECK(worst < 0x1p-44);
}
