// Board description files (boards/NAME.board, shared with the firmware
// build): `key = value` lines giving the ISA, memory map, UART kind, halt
// method and reset address of a target board. firmware-sim --board FILE
// models that board.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "isa_subset.hpp"
#include "memory_map.hpp"

namespace fwsim {

struct Board {
  std::string name, mirrors;
  IsaSpec isa;
  uint32_t reset = 0;
  MemoryMap map;                          // RAM, ROM, UART, halt
  std::optional<uint32_t> uart_divisor;   // for the firmware's UART set-up
  // Generic UART: the register writes (offset, value) the firmware makes at
  // start-up (the simulator models their effect through map.uart's enable).
  std::vector<std::pair<uint32_t, uint32_t>> uart_init;
  uint32_t clock_hz = 0;                  // 0: not given (the cycle model's clock)
};

// Throws std::runtime_error("ORIGIN:LINE: reason") for a bad line, a
// missing or repeated key, or a map whose regions overlap.
Board parse_board_file(const std::string& text, const std::string& origin);

}  // namespace fwsim
