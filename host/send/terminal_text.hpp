// Bytes from the board or the simulator shown on the user's terminal (an
// error line, the simulator's last words): control bytes, DEL and bytes
// outside ASCII become \xHH, as minrt's messages escape a scene's bytes, so
// a board cannot move the cursor, clear the screen, set the window title or
// hide text behind \r. A backslash stays: the firmware's messages carry
// minrt's escapes already and must read the same.
#pragma once

#include <string>

namespace minrt::send {

inline std::string terminal_safe(const std::string& bytes) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(bytes.size());
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) {
      out.push_back(ch);
    } else {
      out += "\\x";
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    }
  }
  return out;
}

}  // namespace minrt::send
