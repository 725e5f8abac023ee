// The FPU-model checker against what the arithmetic must give: a table of
// T index bits starts the reciprocal within about 2^-(T+1), one Newton step
// squares that, and rounding adds a few 2^-24; so T=10 with one step must
// meet the course's 2^-20 for fdiv and T=8 must miss it by about 4x.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "fpu_check.hpp"

using fwsim::FpuModelConfig;
using fwsim::FpuOpCheck;

namespace {
constexpr uint64_t kRandom = 20'000;  // the exhaustive significand sweeps run in full

const FpuOpCheck& op(const fwsim::FpuCheckReport& r, const std::string& name) {
  for (const FpuOpCheck& o : r.ops)
    if (o.op == name) return o;
  FAIL("no op " << name);
  return r.ops.front();
}

FpuModelConfig recip(unsigned table_bits, unsigned steps) {
  FpuModelConfig c;
  c.div = FpuModelConfig::Div::RecipMul;
  c.recip_table_bits = table_bits;
  c.recip_newton_steps = steps;
  return c;
}

FpuModelConfig rsqrt(unsigned table_bits, unsigned steps) {
  FpuModelConfig c;
  c.sqrt = FpuModelConfig::Sqrt::TableNewton;
  c.rsqrt_table_bits = table_bits;
  c.rsqrt_newton_steps = steps;
  return c;
}
}  // namespace

TEST_CASE("exact IEEE arithmetic is within half an ulp and meets every rule", "[fpu-check]") {
  const auto r = fwsim::check_fpu_model(FpuModelConfig{}, kRandom);
  REQUIRE(r.ops.size() == 5);
  for (const FpuOpCheck& o : r.ops) {
    CAPTURE(o.op);
    CHECK(o.max_error <= 0x1p-24);
    CHECK(o.max_error > 0x1p-25);  // the sweeps do hit a rounding near half an ulp
    CHECK(o.invalid == 0);
    CHECK(o.meets());
  }
  CHECK(r.all_meet());
  CHECK(op(r, "fdiv").operands > (1u << 24));  // two divisions per divisor significand
  CHECK(op(r, "fsqrt").operands > (1u << 24));
}

TEST_CASE("reciprocal table of 10 bits and one Newton step meets 2^-20", "[fpu-check]") {
  const auto r = fwsim::check_fpu_model(recip(10, 1), kRandom);
  const FpuOpCheck& d = op(r, "fdiv");
  CHECK(d.meets());
  CHECK(d.max_error < 0x1p-20);
  CHECK(d.max_error > 0x1p-24);  // but it is visibly not exact
  CHECK(r.all_meet());
}

TEST_CASE("reciprocal table of 8 bits and one Newton step misses 2^-20", "[fpu-check]") {
  const auto r = fwsim::check_fpu_model(recip(8, 1), kRandom);
  const FpuOpCheck& d = op(r, "fdiv");
  CHECK_FALSE(d.meets());
  CHECK_FALSE(r.all_meet());
  // (2^-9)^2 = 2^-18 from the table's start, give or take rounding.
  CHECK(d.max_error > std::ldexp(1.0, -18) * 0.7);
  CHECK(d.max_error < std::ldexp(1.0, -18) * 1.3);
  CHECK(op(r, "fsqrt").meets());  // untouched ops still exact
}

TEST_CASE("two Newton steps from a 5-bit table meet 2^-20", "[fpu-check]") {
  // (2^-6)^4 = 2^-24 before rounding.
  CHECK(op(fwsim::check_fpu_model(recip(5, 2), kRandom), "fdiv").meets());
}

TEST_CASE("inverse square root tables meet or miss 2^-20 by size", "[fpu-check]") {
  const auto good = fwsim::check_fpu_model(rsqrt(11, 1), kRandom);
  CHECK(op(good, "fsqrt").meets());
  CHECK(op(good, "fsqrt").max_error > 0x1p-24);
  const auto bad = fwsim::check_fpu_model(rsqrt(8, 1), kRandom);
  CHECK_FALSE(op(bad, "fsqrt").meets());
  CHECK(op(bad, "fdiv").meets());
}

TEST_CASE("truncation costs up to one ulp and still meets the mul and add rules", "[fpu-check]") {
  FpuModelConfig c;
  c.mul = FpuModelConfig::Rounding::Truncate;
  c.add = FpuModelConfig::Rounding::Truncate;
  const auto r = fwsim::check_fpu_model(c, kRandom);
  for (const char* name : {"fadd", "fsub", "fmul"}) {
    CAPTURE(name);
    CHECK(op(r, name).max_error > 0x1p-24);  // worse than nearest
    CHECK(op(r, name).max_error <= 0x1p-23);
    CHECK(op(r, name).meets());
  }
}

TEST_CASE("flushing subnormals stays within the rules' 2^-126 floor", "[fpu-check]") {
  FpuModelConfig c;
  c.flush_subnormals = true;
  const auto r = fwsim::check_fpu_model(c, kRandom);
  CHECK(r.all_meet());
  // A flushed quotient just below 2^-126 is off by almost the whole floor.
  CHECK(op(r, "fdiv").max_error > 0x1p-21);
}
