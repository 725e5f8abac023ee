// Incremental check of the firmware's reply to a CS418 scene: a PNG stream
// of the expected size (the core's stored-deflate writer sends one IDAT per
// row), or one MINRT_ERROR_MARKER line. Every chunk's CRC-32 is checked as
// it arrives, so a damaged line is caught. Same interface as PpmReceiver, so
// the raw protocol's exchange loop serves both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "error_line.hpp"

namespace minrt::send {

class PngReceiver {
 public:
  enum class State { kStart, kSignature, kChunk, kErrorLine, kDone, kFailed, kFirmwareError };

  PngReceiver(int width, int height) : width_(width), height_(height) {}

  std::size_t feed(const std::uint8_t* data, std::size_t size);
  void finish();

  State state() const { return state_; }
  bool done() const { return state_ == State::kDone; }
  bool failed() const { return state_ == State::kFailed; }
  bool firmware_error() const { return state_ == State::kFirmwareError; }
  bool started() const { return state_ != State::kStart; }
  // The bytes that belong to the image (the caller appends what feed took).
  bool image_bytes() const { return state_ == State::kSignature || state_ == State::kChunk || done(); }
  const std::string& message() const { return message_; }
  std::uint64_t bytes() const { return bytes_; }
  int rows_complete() const { return rows_ < height_ ? rows_ : height_; }

 private:
  bool step(std::uint8_t c);
  bool fail(std::string msg);
  bool chunk_done();

  int width_, height_;
  State state_ = State::kStart;
  std::string message_;
  ErrorLine error_line_;
  std::uint64_t bytes_ = 0;
  int rows_ = 0;
  // Current chunk: 8 header bytes, data, 4 CRC bytes.
  std::uint8_t head_[8] = {};
  std::size_t at_ = 0;  // bytes of the current chunk (or signature) seen
  std::uint32_t length_ = 0;
  std::uint32_t crc_ = 0;
  std::uint8_t ihdr_[13] = {};
  std::uint8_t crc_bytes_[4] = {};
  bool seen_ihdr_ = false;
};

}  // namespace minrt::send
