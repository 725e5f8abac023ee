// Writes the image as the original prints it: "P3\nW H 255\n" then one
// "R G B\n" line per pixel, or the same header with P6 and raw bytes. A row
// sink (row_sink.hpp): buffers a little and flushes after every row, so rows
// stream as they finish.
#pragma once

#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/text_numbers.hpp"
#include "core/image/row_sink.hpp"

namespace minrt {

enum class PpmFormat { kP3, kP6 };

class PpmWriter {
 public:
  PpmWriter(ByteSink out, PpmFormat format) : out_(out), format_(format) {}

  RowSink sink() { return row_sink_of(*this); }

  void begin(int width, int height) {
    width_ = width;
    header(width, height);
  }
  void row(int /*y*/, const uint8_t* rgb) {
    for (int x = 0; x < width_; ++x, rgb += 3) pixel(rgb[0], rgb[1], rgb[2]);
    flush();
  }
  void end() { flush(); }

  void header(int width, int height) {
    put('P');
    put(format_ == PpmFormat::kP3 ? '3' : '6');
    put('\n');
    put_int(width);
    put(' ');
    put_int(height);
    put(' ');
    put_int(255);
    put('\n');
  }

  // Channels already clamped to 0..255.
  void pixel(int r, int g, int b) {
    if (format_ == PpmFormat::kP6) {
      put(static_cast<char>(r));
      put(static_cast<char>(g));
      put(static_cast<char>(b));
      return;
    }
    put_int(r);
    put(' ');
    put_int(g);
    put(' ');
    put_int(b);
    put('\n');
  }

  void flush() {
    if (used_ != 0) out_.put(buf_, used_);
    used_ = 0;
  }

 private:
  void put(char c) {
    if (used_ == sizeof buf_) flush();
    buf_[used_++] = static_cast<uint8_t>(c);
  }
  void put_int(int v) {  // v >= 0: clamped channels and image sizes
    if (used_ + 10 > sizeof buf_) flush();
    used_ += format_decimal_u32(static_cast<uint32_t>(v), reinterpret_cast<char*>(buf_ + used_));
  }

  ByteSink out_;
  PpmFormat format_;
  int width_ = 0;
  uint8_t buf_[1024];
  size_t used_ = 0;
};

}  // namespace minrt
