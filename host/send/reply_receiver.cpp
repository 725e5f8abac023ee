#include "reply_receiver.hpp"

#include <cstdio>

#include <minrt/serial_protocol.h>

namespace minrt::send {

bool ReplyReceiver::start(std::uint8_t c, std::uint8_t image_first, const char* format) {
  if (c == static_cast<std::uint8_t>(MINRT_ERROR_MARKER[0])) {
    state_ = State::kErrorLine;
    error_line_.start(c);
    return true;
  }
  if (c != image_first) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "reply does not start like a %s or an error line (first byte 0x%02x)", format, c);
    return fail(buf);
  }
  state_ = State::kHeader;
  return true;
}

bool ReplyReceiver::error_line_step(std::uint8_t c) {
  bool firmware = false;
  std::string message;
  if (error_line_.step(c, firmware, message)) return true;
  if (!firmware) return fail(message);
  message_ = message;
  state_ = State::kFirmwareError;
  return false;
}

bool ReplyReceiver::fail(std::string msg) {
  state_ = State::kFailed;
  message_ = std::move(msg);
  return false;
}

bool ReplyReceiver::fail_if_no_image() {
  if (state_ == State::kStart) return !fail("no reply from the board");
  if (state_ == State::kErrorLine) return !fail("error line from the board is cut off: " + error_line_.text());
  return false;
}

}  // namespace minrt::send
