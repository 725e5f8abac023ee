// A streaming 32-bit BMP writer (BITMAPINFOHEADER, BI_RGB, BGRA with alpha
// 255, positive height: the bottom row first). Jaworski's tracer renders
// the bottom row first, so each row goes out as soon as it is finished.
// The header fields are those of the original program's BMP library
// (2834 pixels a metre), so the files are byte-identical.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt {

class BmpWriter {
 public:
  explicit BmpWriter(ByteSink out) : out_(out) {}

  void begin(int width, int height) {
    width_ = width;
    const uint32_t image = 4u * static_cast<uint32_t>(width) * static_cast<uint32_t>(height);
    uint8_t h[kHeaderBytes] = {'B', 'M'};
    put32(h + 2, kHeaderBytes + image);  // file size
    put32(h + 10, kHeaderBytes);         // pixel data offset
    put32(h + 14, 40);                   // BITMAPINFOHEADER
    put32(h + 18, static_cast<uint32_t>(width));
    put32(h + 22, static_cast<uint32_t>(height));  // positive: bottom-up
    h[26] = 1;                                     // planes
    h[28] = 32;                                    // bits per pixel
    put32(h + 34, image);
    put32(h + 38, kPixelsPerMetre);
    put32(h + 42, kPixelsPerMetre);
    out_.put(h, sizeof h);
  }

  // `rgba`: one row, bottom row first.
  void row(int /*y*/, const uint8_t* rgba) {
    uint8_t px[4 * 64];
    for (int x = 0; x < width_;) {
      int n = 0;
      for (; n < 64 && x < width_; ++n, ++x) {
        px[4 * n] = rgba[4 * x + 2];
        px[4 * n + 1] = rgba[4 * x + 1];
        px[4 * n + 2] = rgba[4 * x];
        px[4 * n + 3] = rgba[4 * x + 3];
      }
      out_.put(px, static_cast<size_t>(4 * n));
    }
  }

  void end() {}

 private:
  static constexpr uint32_t kHeaderBytes = 54;
  static constexpr uint32_t kPixelsPerMetre = 2834;  // 72 dpi

  static void put32(uint8_t* p, uint32_t v) {
    p[0] = static_cast<uint8_t>(v);
    p[1] = static_cast<uint8_t>(v >> 8);
    p[2] = static_cast<uint8_t>(v >> 16);
    p[3] = static_cast<uint8_t>(v >> 24);
  }

  ByteSink out_;
  int width_ = 0;
};

}  // namespace minrt
