#include "colour_depth.hpp"

namespace minrt::host {

namespace {

constexpr int kLevels = 31;  // 5 bits: 0..31
// The 4x4 Bayer matrix: thresholds (b + 0.5) / 16 spread evenly over each block.
constexpr int kBayer[4][4] = {{0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};

}  // namespace

void reduce_to_32k_colours(std::vector<uint8_t>& rgb, int width, int height, bool dither) {
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      // level = v * 31 / 255; rounded (threshold 1/2) or against the
      // pixel's Bayer threshold, in integers: floor((v * 31 * 32 + t) / (255 * 32)).
      const int t = dither ? 2 * kBayer[y & 3][x & 3] + 1 : 16;  // (b + 0.5) / 16 in 32nds, or 1/2
      uint8_t* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
      for (int c = 0; c < 3; ++c) {
        const int level = (p[c] * kLevels * 32 + t * 255) / (255 * 32);
        p[c] = static_cast<uint8_t>((level * 255 + kLevels / 2) / kLevels);
      }
    }
}

}  // namespace minrt::host
