// The image comparison of SPEC.md 1.6, on premultiplied RGBA (a pixel's RGB
// scaled by its alpha, so a transparent pixel's colour does not count).
#pragma once

#include "png_io.hpp"

namespace minrt::host {

struct ImageDiff {
  long pixels = 0;
  long off_by_more_than_1 = 0;  // max channel |difference| > 1 (RGBA, premultiplied)
  long alpha_mismatch = 0;
  double max_channel_error = 0;
  double block_psnr = 0;        // dB, premultiplied RGB box-averaged over block x block
  int block = 4;
  double mean_diff[3] = {};     // mean(A) - mean(B) per channel, in byte units
  long coverage_a = 0, coverage_b = 0;  // pixels with alpha > 0
  double block_mse = 0;
};

// Block size: 4, or 16 for images 800 pixels wide or more (SPEC.md 1.6),
// unless `block` > 0. Both images must have the same size.
ImageDiff compare_images(const RgbaImage& a, const RgbaImage& b, int block = 0);

// Block-averaged MSE only (for the random tests' self-calibrated rule).
double block_mse(const RgbaImage& a, const RgbaImage& b, int block);

// A | B | difference, side by side with 4-pixel gaps, on an opaque
// checkerboard so transparency is visible. Difference: red where a pixel is
// off by more than 1, else the premultiplied difference amplified 16x.
RgbaImage contact_sheet(const RgbaImage& a, const RgbaImage& b);

}  // namespace minrt::host
