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

#include <minrt/serial_protocol.h>

#include "core/base/tile_mask.hpp"

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

// Plane `p` of the pixel at (x, y) less its prediction, mod 256.
inline uint8_t residual(const uint8_t* rgb, size_t w, size_t x, size_t y, int p) {
  return static_cast<uint8_t>((plane(rgb + (y * w + x) * 3, p) - predict_at(rgb, w, x, y, p)) & 0xFF);
}

// The inverse: the pixel at (x, y) of `rgb` from its three residuals
// (res[0], res[stride], res[2*stride]) and the finished pixels around it.
inline void restore(uint8_t* rgb, size_t w, size_t x, size_t y, const uint8_t* res, size_t stride) {
  int q[3];
  for (int p = 0; p < 3; ++p) q[p] = (res[p * stride] + predict_at(rgb, w, x, y, p)) & 0xFF;
  uint8_t* px = rgb + (y * w + x) * 3;
  px[0] = static_cast<uint8_t>(q[1] + q[0]);
  px[1] = static_cast<uint8_t>(q[0]);
  px[2] = static_cast<uint8_t>(q[2] + q[0]);
}

// Host: the residuals of `rgb` (w*h*3 bytes) into `out` (as many).
inline void filter(const uint8_t* rgb, size_t w, size_t h, uint8_t* out) {
  for (size_t y = 0; y < h; ++y)
    for (int p = 0; p < 3; ++p)
      for (size_t x = 0; x < w; ++x) out[y * 3 * w + p * w + x] = residual(rgb, w, x, y, p);
}

// Board: turns the residuals in `data` back into RGB where they lie;
// `scratch` holds one row's residuals (3*w bytes).
inline void unfilter(uint8_t* data, size_t w, size_t h, uint8_t* scratch) {
  for (size_t y = 0; y < h; ++y) {
    uint8_t* row = data + y * 3 * w;
    for (size_t i = 0; i < 3 * w; ++i) scratch[i] = row[i];
    for (size_t x = 0; x < w; ++x) restore(data, w, x, y, scratch + x, w);
  }
}

// Sparse textures (MINRT_TEXTURES_SPARSE_MARKER) send only the tiles a
// TileMask (core/base/tile_mask.hpp) marks.

// Texels of row y in marked tiles.
inline size_t row_sent(const TileMask& m, size_t w, size_t y) {
  size_t n = 0;
  const size_t side = size_t{1} << m.shift;
  for (size_t tx = 0; tx < m.tiles_x; ++tx) {
    const size_t x = tx << m.shift;
    if (m.has(x, y)) n += w - x < side ? w - x : side;
  }
  return n;
}

inline size_t sent_texels(const TileMask& m, size_t w, size_t h) {
  size_t n = 0;
  for (size_t y = 0; y < h; ++y) n += row_sent(m, w, y);
  return n;
}

// The value the board gives a texel that was not sent.
inline constexpr uint8_t kUnsent[3] = MINRT_TEXTURES_UNSENT_RGB;

// Host: the residuals of the marked texels of `view` (the texture as the
// board will hold it: unmarked texels already kUnsent) into `out`, row by
// row, each row's texels plane by plane, predicted from `view` as the whole
// form predicts. Returns the bytes written (3 a texel sent).
inline size_t filter_sparse(const uint8_t* view, size_t w, size_t h, const TileMask& m, uint8_t* out) {
  size_t at = 0;
  for (size_t y = 0; y < h; ++y)
    for (int p = 0; p < 3; ++p)
      for (size_t x = 0; x < w; ++x)
        if (m.has(x, y)) out[at++] = residual(view, w, x, y, p);
  return at;
}

// Board: the texture from the residuals filter_sparse made, which lie in
// the same buffer at or above where their texels go (`residuals`, at the
// buffer's tail): rows in order, each row's residuals copied to `scratch`
// (3*w bytes) first, so no texel is written over a residual still to be
// read; unmarked texels become kUnsent.
inline void unfilter_sparse(uint8_t* data, size_t w, size_t h, const TileMask& m, const uint8_t* residuals,
                            uint8_t* scratch) {
  for (size_t y = 0; y < h; ++y) {
    const size_t n = row_sent(m, w, y);
    for (size_t i = 0; i < 3 * n; ++i) scratch[i] = residuals[i];
    residuals += 3 * n;
    uint8_t* row = data + y * 3 * w;
    size_t j = 0;
    for (size_t x = 0; x < w; ++x) {
      if (m.has(x, y)) {
        restore(data, w, x, y, scratch + j++, n);
      } else {
        for (int c = 0; c < 3; ++c) row[3 * x + c] = kUnsent[c];
      }
    }
  }
}

}  // namespace minrt::send::texel_filter
