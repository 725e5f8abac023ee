// A course team's FPU as FpuModelConfig describes it: fdiv.s as
// x * reciprocal(y) with a table + Newton-Raphson reciprocal, fsqrt.s from a
// table + Newton-Raphson inverse square root, truncating fmul.s/fadd.s,
// subnormals flushed or kept. The arithmetic is defined bit for bit in
// docs/firmware_sim.md ("FPU models") so that a team can compare it with its
// Verilog; the functions below follow that text step by step.
//
// Values are raw single-precision bit patterns, as in fpu.hpp. Every
// function honours the IEEE rules for NaN, infinity and zero operands; only
// finite nonzero operands take the approximate path.
#pragma once
#include <cstdint>
#include <vector>

#include "fpu_model_config.hpp"

namespace fwsim {

// Table entries by definition: the value of the function at the midpoint
// of the entry's interval, rounded to nearest with `entry_bits` fraction
// bits, as float bits. Reciprocal: interval i of [1, 2) in 2^table_bits
// parts. Inverse square root: the top index bit selects [1, 2) (0) or
// [2, 4) (1), the rest splits that range in 2^(table_bits-1) parts.
uint32_t recip_table_entry(unsigned table_bits, unsigned entry_bits, uint32_t index);
uint32_t rsqrt_table_entry(unsigned table_bits, unsigned entry_bits, uint32_t index);

class FpuApprox {
 public:
  explicit FpuApprox(const FpuModelConfig& cfg);
  const FpuModelConfig& config() const { return cfg_; }

  // Whether the interpreter must route the op here (else the IEEE path runs).
  bool models_add() const { return cfg_.add != FpuModelConfig::Rounding::Exact || cfg_.flush_subnormals; }
  bool models_mul() const { return cfg_.mul != FpuModelConfig::Rounding::Exact || cfg_.flush_subnormals; }
  bool models_div() const { return cfg_.div != FpuModelConfig::Div::Exact || cfg_.flush_subnormals; }
  bool models_sqrt() const { return cfg_.sqrt != FpuModelConfig::Sqrt::Exact || cfg_.flush_subnormals; }

  // The instructions. `rm` is used only by ops that are `exact` (with
  // subnormals flushed); approximate ops have one fixed behaviour.
  uint32_t add(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const;
  uint32_t sub(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const;
  uint32_t mul(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const;
  uint32_t div(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const;
  uint32_t sqrt(uint32_t a, unsigned rm, uint8_t& flags) const;

  // The approximation cores, on significands: m in [1, 2) for the
  // reciprocal (result in (0.5, 1]), m in [1, 4) for the inverse square
  // root (result in (0.5, 1]).
  uint32_t recip_significand(uint32_t m) const;
  uint32_t rsqrt_significand(uint32_t m) const;

 private:
  // The unit's own multiplier and subtracter on in-range operands (no
  // specials, no subnormals): round to nearest even, or toward zero.
  uint32_t unit_mul(uint32_t a, uint32_t b) const;
  template <class Op>
  uint32_t rounded(FpuModelConfig::Rounding mode, uint32_t a, uint32_t b, unsigned rm, uint8_t& flags, Op op) const;
  uint32_t unit_sub(uint32_t a, uint32_t b) const;
  uint32_t flush_in(uint32_t a) const;
  uint32_t flush_out(uint32_t r, uint8_t& flags) const;
  // q * 2^k with q a normal float; rounds or flushes a subnormal result.
  uint32_t scale(bool negative, uint32_t q, int k, uint8_t& flags) const;

  FpuModelConfig cfg_;
  std::vector<uint32_t> recip_table_, rsqrt_table_;
};

}  // namespace fwsim
