// Incremental check of the firmware's reply to a Jaworski scene: a 32-bit
// bottom-up BMP (54-byte header, then 4 x W x H bytes), or one
// MINRT_ERROR_MARKER line. The header must describe exactly the image the
// writer sends; the pixel bytes carry no check (like raw P6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "error_line.hpp"

namespace minrt::send {

class BmpReceiver {
 public:
  enum class State { kStart, kHeader, kPixels, kErrorLine, kDone, kFailed, kFirmwareError };

  std::size_t feed(const std::uint8_t* data, std::size_t size);
  void finish();

  State state() const { return state_; }
  bool done() const { return state_ == State::kDone; }
  bool failed() const { return state_ == State::kFailed; }
  bool firmware_error() const { return state_ == State::kFirmwareError; }
  bool started() const { return state_ != State::kStart; }
  bool image_bytes() const { return state_ == State::kHeader || state_ == State::kPixels || done(); }
  const std::string& message() const { return message_; }
  std::uint64_t bytes() const { return bytes_; }
  int rows_complete() const;

 private:
  bool step(std::uint8_t c);
  bool fail(std::string msg);
  bool header_done();

  State state_ = State::kStart;
  std::string message_;
  ErrorLine error_line_;
  std::uint64_t bytes_ = 0;
  std::uint8_t header_[54] = {};
  std::size_t at_ = 0;
  int width_ = 0, height_ = 0;
  std::uint64_t pixel_bytes_ = 0, pixels_seen_ = 0;
};

}  // namespace minrt::send
