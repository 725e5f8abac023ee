// Text form of one instruction ("addi a0, a0, 1"), for traces, error
// messages and profiles. Branch/jump targets are shown as absolute addresses.
#pragma once
#include <cstdint>
#include <string>

namespace fwsim {

std::string disassemble(uint32_t word, uint32_t pc);
// ABI names: "a0", "fa0" (index 0..31).
const char* x_reg_name(unsigned i);
const char* f_reg_name(unsigned i);

}  // namespace fwsim
