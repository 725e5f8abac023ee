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

  static constexpr uint32_t kHeaderBytes = 54;

  // The whole file's size: header and rows (4 bytes a pixel, no padding).
  static size_t file_bytes(int width, int height) {
    return kHeaderBytes + 4u * static_cast<size_t>(width) * static_cast<size_t>(height);
  }

  // The header into `h` (kHeaderBytes), for callers that lay out the whole
  // file in memory: the rows follow it, bottom row first.
  static void header(uint8_t* h, int width, int height) {
    const uint32_t image = 4u * static_cast<uint32_t>(width) * static_cast<uint32_t>(height);
    for (uint32_t i = 0; i < kHeaderBytes; ++i) h[i] = 0;
    h[0] = 'B';
    h[1] = 'M';
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
  }

  // One row of RGBA pixels as the file stores them (BGRA); `bgra` may be
  // `rgba` itself.
  static void to_bgra(const uint8_t* rgba, uint8_t* bgra, int width) {
    for (int x = 0; x < width; ++x) {
      const uint8_t r = rgba[4 * x], g = rgba[4 * x + 1], b = rgba[4 * x + 2], a = rgba[4 * x + 3];
      bgra[4 * x] = b;
      bgra[4 * x + 1] = g;
      bgra[4 * x + 2] = r;
      bgra[4 * x + 3] = a;
    }
  }

  void begin(int width, int height) {
    width_ = width;
    uint8_t h[kHeaderBytes];
    header(h, width, height);
    out_.put(h, sizeof h);
  }

  // `rgba`: one row, bottom row first.
  void row(int /*y*/, const uint8_t* rgba) {
    uint8_t px[4 * 64];
    for (int x = 0; x < width_; x += 64) {
      const int n = width_ - x < 64 ? width_ - x : 64;
      to_bgra(rgba + 4 * x, px, n);
      out_.put(px, static_cast<size_t>(4 * n));
    }
  }

  void end() {}

 private:
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
