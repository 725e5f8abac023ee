// Incremental check of the firmware's reply to a CS418 scene: a PNG stream
// of the expected size (the core's stored-deflate writer sends one IDAT per
// row), or one MINRT_ERROR_MARKER line. Every chunk's CRC-32 is checked as
// it arrives, so a damaged line is caught. Same interface as PpmReceiver, so
// the raw protocol's exchange loop serves both.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "reply_receiver.hpp"

namespace minrt::send {

// kHeader: the signature; kBody: the chunks.
class PngReceiver : public ReplyReceiver {
 public:
  PngReceiver(int width, int height) : width_(width), height_(height) {}

  std::size_t feed(const std::uint8_t* data, std::size_t size);
  void finish();

  int rows_complete() const { return rows_ < height_ ? rows_ : height_; }

 private:
  bool step(std::uint8_t c);
  bool chunk_done();

  int width_, height_;
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
