// The reversible filter texels pass through before deflate on the wire
// (include/minrt/serial_protocol.h, compressed texture preamble): each
// pixel becomes three planes, G, R-G and B-G (mod 256; a grey texture's
// last two are zero), each predicted from its left, upper and upper-left
// neighbours by the median edge detector, and the residuals of a row are
// laid out plane by plane. On the shared course textures this deflates to
// about a third of the texels, where deflate over the plain texels gives
// about 43%. Both ends: the host filters, the board undoes it in place.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace minrt::send::texel_filter {

// Median edge detector: the smaller or larger of left and up when the
// corner lies outside them, else the plane through the three.
inline int predict(int a, int b, int c) {
  const int lo = a < b ? a : b, hi = a < b ? b : a;
  if (c >= hi) return lo;
  if (c <= lo) return hi;
  return a + b - c;
}

// Plane `p` of the RGB pixel at `px`.
inline int plane(const uint8_t* px, int p) {
  return p == 0 ? px[1] : (px[p == 1 ? 0 : 2] - px[1]) & 0xFF;
}

// The prediction of plane `p` at (x, y) from the finished pixels around it
// in `rgb` (rows of 3*w bytes; outside the texture counts as 0).
inline int predict_at(const uint8_t* rgb, size_t w, size_t x, size_t y, int p) {
  const size_t row = 3 * w;
  const int a = x > 0 ? plane(rgb + y * row + 3 * (x - 1), p) : 0;
  const int b = y > 0 ? plane(rgb + (y - 1) * row + 3 * x, p) : 0;
  const int c = x > 0 && y > 0 ? plane(rgb + (y - 1) * row + 3 * (x - 1), p) : 0;
  return predict(a, b, c);
}

// Host: the residuals of `rgb` (w*h*3 bytes) into `out` (as many).
inline void filter(const uint8_t* rgb, size_t w, size_t h, uint8_t* out) {
  for (size_t y = 0; y < h; ++y)
    for (int p = 0; p < 3; ++p)
      for (size_t x = 0; x < w; ++x)
        out[y * 3 * w + p * w + x] =
            static_cast<uint8_t>((plane(rgb + (y * w + x) * 3, p) - predict_at(rgb, w, x, y, p)) & 0xFF);
}

// Board: turns the residuals in `data` back into RGB where they lie;
// `scratch` holds one row's residuals (3*w bytes).
inline void unfilter(uint8_t* data, size_t w, size_t h, uint8_t* scratch) {
  for (size_t y = 0; y < h; ++y) {
    uint8_t* row = data + y * 3 * w;
    for (size_t i = 0; i < 3 * w; ++i) scratch[i] = row[i];
    for (size_t x = 0; x < w; ++x) {
      int q[3];
      for (int p = 0; p < 3; ++p) q[p] = (scratch[p * w + x] + predict_at(data, w, x, y, p)) & 0xFF;
      row[3 * x + 0] = static_cast<uint8_t>(q[1] + q[0]);
      row[3 * x + 1] = static_cast<uint8_t>(q[0]);
      row[3 * x + 2] = static_cast<uint8_t>(q[2] + q[0]);
    }
  }
}

}  // namespace minrt::send::texel_filter
