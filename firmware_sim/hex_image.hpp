// Memory images of 32-bit words, as RTL flows use them: Verilog $readmemh
// files (.hex/.mem: hex words separated by white space, `//` and `/* */`
// comments, `@ADDR` = continue at word ADDR) and Xilinx .coe files
// (memory_initialization_radix = 16 or 2 or 10, memory_initialization_vector
// = w0, w1, ...;). Word i goes to byte address base + 4 * i.
#pragma once
#include <cstdint>
#include <string>

#include "bus.hpp"

namespace fwsim {

struct LoadedImage {
  uint32_t begin = 0, end = 0;  // bytes written
};

// Loads `path` (.coe by its extension, else $readmemh) into RAM or ROM at
// `base`. Throws std::runtime_error("PATH:LINE: reason").
LoadedImage load_hex_image(const std::string& path, Bus& bus, uint32_t base);

}  // namespace fwsim
