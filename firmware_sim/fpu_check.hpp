// `firmware-sim --fpu-check`: measures an FPU model's error against the exact
// result, the way the course's accuracy rules measure it, and says for each
// op whether the model meets the rule: |result - exact| must stay below
// max(bound * scale, 2^-126), bound 2^-23 for fadd/fsub (scale = the largest
// of |x|, |y|, |exact|), 2^-22 for fmul, 2^-20 for fdiv and fsqrt (scale =
// |exact|). Operands are zero or normal with magnitude below 2^127 and the
// exact result below 2^127, as in the course's rules; specials are the unit
// tests' business.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fpu_model_config.hpp"

namespace fwsim {

struct FpuOpCheck {
  std::string op;          // "fadd", "fsub", "fmul", "fdiv", "fsqrt"
  std::string arithmetic;  // what the model does for it
  int bound_log2 = 0;      // the rule: -23, -22 or -20
  uint64_t operands = 0;   // operand pairs checked
  double max_error = 0;    // max of |result - exact| / max(scale, 2^-126 / 2^bound_log2)
  uint64_t invalid = 0;    // NaN or infinite results for a finite exact result
  uint32_t worst_a = 0, worst_b = 0, worst_result = 0;  // operands and result of max_error
  double worst_exact = 0;
  bool meets() const;      // max_error < 2^bound_log2 and no invalid result
};

struct FpuCheckReport {
  std::string model;  // describe(cfg)
  std::vector<FpuOpCheck> ops;
  bool all_meet() const;
};

// Every divisor significand (exhaustive reciprocal), every sqrt operand
// significand in both exponent parities (exhaustive for normal operands),
// `random_samples` random operands of each kind per op (fixed seed), and
// edge operands. Deterministic.
FpuCheckReport check_fpu_model(const FpuModelConfig& cfg, uint64_t random_samples = 1'000'000);

void print_fpu_check(const FpuCheckReport& report, std::FILE* out);

}  // namespace fwsim
