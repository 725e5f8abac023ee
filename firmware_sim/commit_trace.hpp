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

// --commit-log: the same events in spike's --log-commits layout, for diffing
// against an RTL trace: "core   0: 3 0x80000000 (0x00000297) x5  0x80000000"
// (privilege 3 = machine mode, pc, instruction bits, then the register
// written, "x5  0x..." or "f1  0x...", and a store's " mem 0xADDR 0xVALUE"
// with the value as wide as the store). Writes to x0 are not listed.
void write_spike_commit(std::FILE* out, uint32_t pc, uint32_t word, const HartState& hart);

}  // namespace fwsim
