// The C extension (RV32C, with the F extension's compressed loads and
// stores): each 16-bit instruction is expanded here, at decode time, into the
// decoded form of the 32-bit instruction it stands for, so the interpreter,
// the generated code, the disassembler and the commit log run and show one
// definition of every instruction. Only `length` (2) tells them apart.
#pragma once
#include <cstdint>

#include "decoder.hpp"

namespace fwsim {

// The expansion of the 16-bit instruction `half` (its low two bits are not
// 11). Reserved encodings, the all-zero word, RV64/RV128-only and D-extension
// encodings decode to Op::ILLEGAL; hints expand to their (effect-free) base
// instruction, as the specification lets an implementation execute them.
DecodedInsn decode_compressed(uint16_t half);

// `word` is 32-bit when its low two bits are 11, otherwise its low half is a
// compressed instruction (the upper half is ignored then).
inline bool is_compressed(uint32_t word) { return (word & 3) != 3; }
inline DecodedInsn decode_any(uint32_t word) {
  return is_compressed(word) ? decode_compressed(static_cast<uint16_t>(word)) : decode(word);
}

}  // namespace fwsim
