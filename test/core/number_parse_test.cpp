// Number tokens: read_float must round exactly like strtod/strtof (what
// OCaml's float_of_string calls), read_int must follow int_of_string.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>

#include "core/base/number_parse.hpp"

namespace {

template <class R>
R reference(const std::string& s) {
  std::string no_underscores;
  for (char c : s)
    if (c != '_') no_underscores += c;
  if constexpr (sizeof(R) == sizeof(double))
    return std::strtod(no_underscores.c_str(), nullptr);
  else
    return std::strtof(no_underscores.c_str(), nullptr);
}

template <class R>
void expect_same_as_libc(const std::string& s) {
  R got = 0;
  const auto st = minrt::parse_real<R>(s.data(), static_cast<int>(s.size()), got);
  const R want = reference<R>(s);
  CAPTURE(s);
  if (!std::isfinite(want)) {
    CHECK(st == minrt::NumberStatus::kNonFinite);
    return;
  }
  REQUIRE(st == minrt::NumberStatus::kOk);
  CHECK(std::memcmp(&got, &want, sizeof(R)) == 0);
}

// Exact decimal expansion of the point halfway between x and its successor:
// x86 long double holds it exactly and glibc prints it exactly.
template <class R>
std::string midpoint_string(R x) {
  const long double a = x, b = std::nextafter(x, R(INFINITY));
  char buf[512];
  std::snprintf(buf, sizeof buf, "%.80Lg", a + (b - a) / 2);
  return buf;
}

}  // namespace

TEMPLATE_TEST_CASE("read_float: rounds every decimal exactly like the C library", "[number]",
                   double, float) {
  std::mt19937_64 rng(20261121);
  std::uniform_int_distribution<int> ndigits(1, 30), digit(0, 9), exp10(-340, 320);
  for (int i = 0; i < 20000; ++i) {
    std::string s = rng() % 2 ? "-" : "";
    const int n = ndigits(rng);
    const int point = static_cast<int>(rng() % (n + 1));
    for (int k = 0; k < n; ++k) {
      if (k == point) s += '.';
      s += static_cast<char>('0' + digit(rng));
    }
    if (rng() % 2) s += "e" + std::to_string(exp10(rng));
    expect_same_as_libc<TestType>(s);
  }
}

TEMPLATE_TEST_CASE("read_float: halfway cases and round trips", "[number]", double, float) {
  std::mt19937_64 rng(42);
  for (int i = 0; i < 5000; ++i) {
    // Random finite values across the range, subnormals included.
    TestType x;
    do {
      const uint64_t bits = rng();
      std::memcpy(&x, &bits, sizeof x);
    } while (!std::isfinite(x) || std::isfinite(std::nextafter(x, TestType(INFINITY))) == false);
    x = std::fabs(x);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*g", sizeof(TestType) == 8 ? 17 : 9, static_cast<double>(x));
    expect_same_as_libc<TestType>(buf);
    const std::string mid = midpoint_string(x);
    if (mid.size() < 250) expect_same_as_libc<TestType>(mid);
  }
}

TEST_CASE("read_float: forms float_of_string accepts", "[number]") {
  for (const char* s : {"1", "1.", ".5", "-0", "+2.5", "1e2", "1E-2", "1_000.5", "2.5e+3",
                        "0.000000000000000000000000000000000001", "4.9e-324", "2.4703282292062327e-324",
                        "2.4703282292062328e-324", "1.7976931348623157e308", "1e-400", "123456789012345678901234567890"})
    expect_same_as_libc<double>(s);
  double v = 0;
  CHECK(minrt::parse_real<double>("0x1.8p3", 7, v) == minrt::NumberStatus::kOk);
  CHECK(v == 12.0);
  CHECK(minrt::parse_real<double>("-0x10", 5, v) == minrt::NumberStatus::kOk);
  CHECK(v == -16.0);
  CHECK(std::signbit(v));
  CHECK(minrt::parse_real<double>("-0", 2, v) == minrt::NumberStatus::kOk);
  CHECK(std::signbit(v));
}

TEST_CASE("read_float: what it rejects", "[number]") {
  double v = 0;
  for (const char* s : {"abc", "", ".", "-", "1e", "1e+", "1.2.3", "1,5", "0x", "1f", "e5", "--1"})
    CHECK(minrt::parse_real<double>(s, static_cast<int>(std::strlen(s)), v) ==
          minrt::NumberStatus::kInvalid);
  for (const char* s : {"nan", "NaN", "inf", "-Infinity", "1e999", "1.8e308"})
    CHECK(minrt::parse_real<double>(s, static_cast<int>(std::strlen(s)), v) ==
          minrt::NumberStatus::kNonFinite);
  float f = 0;
  CHECK(minrt::parse_real<float>("3.5e38", 6, f) == minrt::NumberStatus::kNonFinite);
}

TEST_CASE("read_int: follows int_of_string", "[number]") {
  struct Case {
    const char* text;
    int64_t value;
  };
  for (auto c : {Case{"0", 0}, Case{"-1", -1}, Case{"+7", 7}, Case{"99", 99}, Case{"0x1F", 31},
                 Case{"0b101", 5}, Case{"0o17", 15}, Case{"1_000", 1000}, Case{"007", 7},
                 Case{"4611686018427387903", 4611686018427387903LL},
                 Case{"-4611686018427387904", -4611686018427387904LL},
                 Case{"0x7FFFFFFFFFFFFFFF", -1}}) {
    CAPTURE(c.text);
    int64_t v = 12345;
    REQUIRE(minrt::parse_int(c.text, static_cast<int>(std::strlen(c.text)), v) ==
            minrt::NumberStatus::kOk);
    CHECK(v == c.value);
  }
  int64_t v = 0;
  for (const char* s : {"", "-", "1.0", "_1", "0x", "12a", "1e3", "0b2"})
    CHECK(minrt::parse_int(s, static_cast<int>(std::strlen(s)), v) == minrt::NumberStatus::kInvalid);
  for (const char* s : {"4611686018427387904", "-4611686018427387905", "99999999999999999999",
                        "0x8000000000000000"})
    CHECK(minrt::parse_int(s, static_cast<int>(std::strlen(s)), v) == minrt::NumberStatus::kOutOfRange);
}
