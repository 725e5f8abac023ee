// Which square tiles of a texture are present: one bit a tile of 2^shift
// texels a side, rows of tiles top first. Shared by the sparse texture
// preamble (protocol/texel_filter.hpp) and the tracer's texel watch
// (render/general/surface_maps.hpp), which sit side by side above core.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace minrt {

struct TileMask {
  const uint8_t* bits = nullptr;
  size_t tiles_x = 0;
  int shift = 0;
  bool has(size_t x, size_t y) const {
    const size_t t = (y >> shift) * tiles_x + (x >> shift);
    return ((bits[t >> 3] >> (t & 7)) & 1) != 0;
  }
};

inline size_t tiles_along(size_t n, int shift) { return (n + (size_t{1} << shift) - 1) >> shift; }
inline size_t tile_mask_bytes(size_t w, size_t h, int shift) {
  return (tiles_along(w, shift) * tiles_along(h, shift) + 7) / 8;
}

}  // namespace minrt
