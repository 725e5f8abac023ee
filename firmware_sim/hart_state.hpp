// Architectural state of the single RV32IMF hart.
#pragma once
#include <cstdint>

namespace fwsim {

// x[32] is a write sink: instructions whose rd is x0 are decoded to write
// there, so x[0] stays 0 without a check in every handler.
inline constexpr unsigned kSinkReg = 32;

struct HartState {
  uint32_t x[33] = {};
  uint32_t f[32] = {};  // raw single-precision bit patterns
  uint32_t pc = 0;
  uint8_t frm = 0;
  uint8_t fflags = 0;   // flags raised on the soft path; host flags are merged on read
  uint64_t instret = 0;
  uint64_t cycles = 0;  // simulated cycles (equals instret without a cycle model)
};

}  // namespace fwsim
