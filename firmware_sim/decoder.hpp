// Decodes one 32-bit RV32IMF/Zicsr instruction word into its fields
// (compressed ones: compressed.hpp).
#pragma once
#include <cstdint>

#include "isa_table.hpp"

namespace fwsim {

struct DecodedInsn {
  Op op = Op::ILLEGAL;
  uint8_t rd = 0, rs1 = 0, rs2 = 0, rs3 = 0;
  uint8_t rm = 0;    // FP rounding-mode field (7 = dynamic)
  int32_t imm = 0;   // sign-extended immediate; CSR number for CSR ops
  uint8_t length = 4;  // bytes: 2 for a compressed instruction (compressed.hpp)
};

DecodedInsn decode(uint32_t word);

}  // namespace fwsim
