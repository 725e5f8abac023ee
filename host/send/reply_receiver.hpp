// What the raw protocol's receivers (PpmReceiver, PngReceiver, BmpReceiver)
// share: the board's reply is either the image or one MINRT_ERROR_MARKER
// line, checked byte by byte as it arrives. How the reply starts, the error
// line, how it ended, the message and the byte count are the same for every
// image format; each receiver adds its image's two parts (kHeader, kBody)
// and the checks on them. One interface, so the exchange loop serves all.
#pragma once

#include <cstdint>
#include <string>

#include "error_line.hpp"

namespace minrt::send {

class ReplyReceiver {
 public:
  // kHeader, kBody: PPM header and pixels, PNG signature and chunks, BMP
  // header and pixels.
  enum class State { kStart, kHeader, kBody, kErrorLine, kDone, kFailed, kFirmwareError };

  State state() const { return state_; }
  bool done() const { return state_ == State::kDone; }
  bool failed() const { return state_ == State::kFailed; }
  bool firmware_error() const { return state_ == State::kFirmwareError; }
  bool ended() const { return done() || failed() || firmware_error(); }
  bool started() const { return state_ != State::kStart; }
  // Whether the bytes fed last belong to the image (not an error line).
  bool image_bytes() const { return state_ == State::kHeader || state_ == State::kBody || done(); }
  // What went wrong (kFailed), or the firmware's message without the marker.
  const std::string& message() const { return message_; }
  std::uint64_t bytes() const { return bytes_; }

 protected:
  // The reply's first byte, in kStart: the error line's first, then read by
  // error_line_step; else it must be `image_first`, the first byte of a
  // `format` image (kHeader follows). False when the reply has ended.
  bool start(std::uint8_t c, std::uint8_t image_first, const char* format);
  // One byte of the error line; false once it has ended.
  bool error_line_step(std::uint8_t c);
  bool fail(std::string msg);
  // For finish(): a reply that stopped before its image began (nothing, or
  // a cut-off error line) fails with the reason; true when it did.
  bool fail_if_no_image();

  State state_ = State::kStart;
  std::string message_;
  std::uint64_t bytes_ = 0;

 private:
  ErrorLine error_line_;
};

}  // namespace minrt::send
