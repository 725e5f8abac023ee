// The firmware's one error line (MINRT_ERROR_MARKER, then the message, then a
// newline), collected byte by byte by the raw protocol's receivers (PPM and
// PNG) once a reply starts with the marker's first byte.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <minrt/serial_protocol.h>

#include "terminal_text.hpp"

namespace minrt::send {

class ErrorLine {
 public:
  enum class Step { kMore, kMessage, kNotMarker, kTooLong };

  void start(std::uint8_t c) { text_.assign(1, static_cast<char>(c)); }

  // After kMessage, text() is the firmware's message without the marker;
  // after kNotMarker it is the whole line; either escaped for the terminal.
  Step feed(std::uint8_t c) {
    if (c == '\n') {
      const std::string marker = MINRT_ERROR_MARKER;
      if (text_.compare(0, marker.size(), marker) != 0) return Step::kNotMarker;
      text_.erase(0, marker.size());
      return Step::kMessage;
    }
    if (text_.size() >= kMaxLength) return Step::kTooLong;
    if (c != '\r') text_.push_back(static_cast<char>(c));
    return Step::kMore;
  }
  std::string text() const { return terminal_safe(text_); }

  // For the receivers: feeds `c`; true while the line goes on. At its end
  // `firmware` says whether it was the firmware's message (then `message`
  // is that message) or something else (then `message` says what).
  bool step(std::uint8_t c, bool& firmware, std::string& message) {
    switch (feed(c)) {
      case Step::kMore: return true;
      case Step::kMessage:
        firmware = true;
        message = text();
        return false;
      case Step::kNotMarker:
        firmware = false;
        message = "unexpected reply line: " + text();
        return false;
      case Step::kTooLong:
        firmware = false;
        message = "error line from the board is too long";
        return false;
    }
    return false;
  }

 private:
  static constexpr std::size_t kMaxLength = 4096;
  std::string text_;
};

}  // namespace minrt::send
