// --trace output: one line per retired instruction with what it changed,
// in the spirit of spike's --log-commits.
#pragma once
#include <cstdint>
#include <cstdio>

#include "hart_state.hpp"

namespace fwsim {

// Writes "PC: WORD  DISASSEMBLY  EFFECTS\n" for the instruction at `pc`
// (encoded as `word`) that has just executed, reading its results from
// `hart`: "rd=0x..." for an integer destination, "fd=0x... (value)" for a
// float one, "mem32[0x...]=0x..." for a store (8, 16 or 32 bits).
void write_commit_trace(std::FILE* out, uint32_t pc, uint32_t word, const HartState& hart);

}  // namespace fwsim
