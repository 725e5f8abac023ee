// Follows an image file as its bytes go by (minrt's PPM output, or what
// host-send receives: PPM, PNG or BMP) and hands every row to the live
// window as soon as its last byte is in. The format comes from the first
// bytes. PPM: P3 and P6, any maxval. BMP: 24 or 32 bits, either row order.
// PNG: 8-bit RGB or RGBA, not interlaced, in stored (uncompressed) deflate
// blocks as the board's PNG writer sends them; anything else stops the
// live view (the caller fills the window from the finished file). Nothing
// here judges the image: the receivers and readers do that.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace minrt::host {

class LiveWindow;

class ImageStreamDecoder {
 public:
  explicit ImageStreamDecoder(LiveWindow& window) : window_(window) {}

  void feed(const uint8_t* data, size_t size);
  // Whether the stream stopped being followable (unknown or unsupported).
  bool gave_up() const { return state_ == State::kGaveUp; }

 private:
  enum class Kind { kUnknown, kPpm, kBmp, kPng };
  enum class State { kMagic, kPpmHeader, kPpmPixels, kBmpHeader, kBmpPixels, kPng, kGaveUp, kDone };

  void step(uint8_t c);
  void give_up() { state_ = State::kGaveUp; }
  void start_image(int width, int height);
  void ppm_header_byte(uint8_t c);
  void ppm_pixel_byte(uint8_t c);
  void bmp_byte(uint8_t c);
  void png_byte(uint8_t c);
  void png_idat_byte(uint8_t c);
  void png_inflated_byte(uint8_t c);
  void row_done(int file_row);

  LiveWindow& window_;
  State state_ = State::kMagic;
  Kind kind_ = Kind::kUnknown;
  std::string magic_;
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> row_;  // the row being received, 8-bit RGB (PNG: its raw bytes)
  size_t at_ = 0;             // bytes of row_ filled
  int row_index_ = 0;         // rows finished, in file order

  // PPM.
  bool p3_ = false, in_comment_ = false;
  int field_ = 0;  // width, height, maxval
  long fields_[3] = {0, 0, 0};
  bool in_token_ = false;
  long value_ = -1;  // P3: the value being read; P6 16-bit: the high byte
  int bytes_per_sample_ = 1;

  // BMP.
  uint8_t header_[138] = {};
  size_t header_at_ = 0;
  uint32_t data_offset_ = 0;
  int bmp_bytes_per_pixel_ = 4;
  size_t bmp_stride_ = 0;
  bool bottom_up_ = true;

  // PNG: chunk framing, then zlib's stored blocks, then filtered rows.
  uint8_t chunk_head_[8] = {};
  size_t chunk_at_ = 0;
  uint32_t chunk_length_ = 0;
  int png_channels_ = 4;
  int zlib_header_ = 0;     // bytes of the 2-byte zlib header seen
  int block_head_ = 0;      // bytes of the current stored block's 5-byte head seen
  uint8_t block_bytes_[5] = {};
  uint32_t block_left_ = 0;
  bool last_block_ = false;
  std::vector<uint8_t> previous_;  // the previous row, unfiltered
};

}  // namespace minrt::host
