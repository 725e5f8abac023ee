// The board's instruction set (base + extensions), and which decoded
// instructions fall outside it. The decode cache consults this once per
// instruction word, so the interpreter pays nothing for the check.
#pragma once
#include <cstdint>
#include <string>

#include "decoder.hpp"

namespace fwsim {

struct IsaSpec {
  bool rv32e = false;  // E base: only x0..x15
  bool m = true, f = true, c = false;
  bool zicsr = true;
  bool zifencei = true;  // a board file says yes or (by default) no
};

// The simulator's full set, the reference board's: rv32imf + Zicsr + Zifencei.
inline constexpr IsaSpec kReferenceIsa{};

// "rv32i", "rv32imf", "rv32emc"...: the names the board format allows.
// False for any other text.
bool parse_isa(const std::string& text, IsaSpec& isa);
std::string isa_name(const IsaSpec& isa);

// Null when the instruction word (decoded as `d`) belongs to `isa`;
// otherwise what it needs, e.g. "the M extension".
const char* missing_extension(const IsaSpec& isa, uint32_t word, const DecodedInsn& d);

}  // namespace fwsim
