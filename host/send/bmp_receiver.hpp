// Incremental check of the firmware's reply to a Jaworski scene: a 32-bit
// bottom-up BMP (54-byte header, then 4 x W x H bytes), or one
// MINRT_ERROR_MARKER line. The header must describe exactly the image the
// writer sends; the pixel bytes carry no check (like raw P6).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "reply_receiver.hpp"

namespace minrt::send {

// kBody: the pixels.
class BmpReceiver : public ReplyReceiver {
 public:
  std::size_t feed(const std::uint8_t* data, std::size_t size);
  void finish();

  int rows_complete() const;

 private:
  bool step(std::uint8_t c);
  bool header_done();

  std::uint8_t header_[54] = {};
  std::size_t at_ = 0;
  int width_ = 0, height_ = 0;
  std::uint64_t pixel_bytes_ = 0, pixels_seen_ = 0;
};

}  // namespace minrt::send
