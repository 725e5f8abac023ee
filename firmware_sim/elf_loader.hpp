// Loads a 32-bit little-endian RISC-V ELF executable into RAM and reads its
// function symbols.
#pragma once
#include <cstdint>
#include <string>

#include "bus.hpp"
#include "symbols.hpp"

namespace fwsim {

struct LoadedElf {
  uint32_t entry = 0;
  uint32_t text_begin = 0, text_end = 0;  // span of executable segments
  SymbolTable symbols;
};

// Throws std::runtime_error with a one-line reason on any problem.
LoadedElf load_elf(const std::string& path, Bus& bus);

}  // namespace fwsim
