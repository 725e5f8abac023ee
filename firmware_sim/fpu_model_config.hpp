// Which arithmetic fadd.s/fsub.s/fmul.s/fdiv.s/fsqrt.s use: exact IEEE (the
// default) or a description of a course team's own FPU (fpu_approx.hpp).
// Set by a `key = value` file (--fpu-model, same syntax as the cycle model)
// and/or `--fpu key=value,...`; docs/firmware_sim.md lists the keys.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>

namespace fwsim {

struct FpuModelConfig {
  enum class Div : uint8_t { Exact, RecipMul };
  enum class Sqrt : uint8_t { Exact, TableNewton };
  enum class Rounding : uint8_t { Exact, Truncate };

  Div div = Div::Exact;
  unsigned recip_table_bits = 10;    // index bits of the reciprocal table (0..16)
  unsigned recip_entry_bits = 23;    // fraction bits kept per entry (1..23)
  unsigned recip_newton_steps = 1;   // 0..4
  Sqrt sqrt = Sqrt::Exact;
  unsigned rsqrt_table_bits = 11;    // 1..16: exponent parity + (bits - 1) fraction bits
  unsigned rsqrt_entry_bits = 23;
  unsigned rsqrt_newton_steps = 1;
  Rounding mul = Rounding::Exact;
  Rounding add = Rounding::Exact;    // fadd.s and fsub.s
  bool flush_subnormals = false;     // `subnormals = flush`

  // True when nothing differs from IEEE: the simulator then runs unchanged.
  bool is_ieee() const {
    return div == Div::Exact && sqrt == Sqrt::Exact && mul == Rounding::Exact &&
           add == Rounding::Exact && !flush_subnormals;
  }
};

// Parses a model file; keys not given keep the IEEE defaults above.
// Throws std::runtime_error("origin:line: reason").
FpuModelConfig parse_fpu_model(const std::string& text, const std::string& origin);

// Applies `key=value,key=value` (the --fpu option) on top of `cfg`.
// Throws std::runtime_error("--fpu 'item': reason").
void apply_fpu_settings(FpuModelConfig& cfg, const std::string& list);

// One line such as "div=recip-mul(table 10 bits, entries 23 bits, 1 Newton step) sqrt=exact ...".
std::string describe(const FpuModelConfig& cfg);

}  // namespace fwsim
