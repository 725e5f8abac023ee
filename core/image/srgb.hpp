// Linear light to sRGB bytes and back, by table (srgb_tables.hpp): no pow on
// the board, and exactly the CS418 rule floor(255 * OETF(l)), l >= 1 -> 255.
#pragma once

#include <stdint.h>

#include "core/image/srgb_tables.hpp"

namespace minrt {

namespace srgb_detail {
inline const double* thresholds(double) { return srgb_tables::kThresholdD; }
inline const float* thresholds(float) { return srgb_tables::kThresholdF; }
inline const double* decode_table(double) { return srgb_tables::kDecodeD; }
inline const float* decode_table(float) { return srgb_tables::kDecodeF; }
}  // namespace srgb_detail

// The byte of a linear value: how many thresholds it reaches (binary search,
// 8 comparisons). Below 0 and NaN give 0, 1 and above give 255.
template <class R>
uint8_t srgb_encode(R linear) {
  const R* t = srgb_detail::thresholds(R{});
  int lo = 0, hi = 255;  // answer in [lo, hi]
  while (lo < hi) {
    const int mid = (lo + hi + 1) >> 1;
    if (linear >= t[mid - 1]) lo = mid;
    else hi = mid - 1;
  }
  return static_cast<uint8_t>(lo);
}

template <class R>
R srgb_decode(uint8_t byte) {
  return srgb_detail::decode_table(R{})[byte];
}

}  // namespace minrt
