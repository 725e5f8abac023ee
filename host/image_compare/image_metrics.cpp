#include "image_metrics.hpp"

#include <cmath>
#include <vector>

namespace minrt::host {

namespace {

double premul(const uint8_t* p, int c) { return p[c] * (p[3] / 255.0); }

std::vector<double> blocks(const RgbaImage& im, int block, int& bw, int& bh) {
  bw = (im.width + block - 1) / block;
  bh = (im.height + block - 1) / block;
  std::vector<double> out(static_cast<std::size_t>(bw) * bh * 3, 0.0);
  std::vector<int> count(static_cast<std::size_t>(bw) * bh, 0);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const uint8_t* p = &im.rgba[(static_cast<std::size_t>(y) * im.width + x) * 4];
      const std::size_t k = static_cast<std::size_t>(y / block) * bw + x / block;
      for (int c = 0; c < 3; ++c) out[3 * k + c] += premul(p, c);
      ++count[k];
    }
  for (std::size_t k = 0; k < count.size(); ++k)
    for (int c = 0; c < 3; ++c) out[3 * k + c] /= count[k];
  return out;
}

}  // namespace

double block_mse(const RgbaImage& a, const RgbaImage& b, int block) {
  int bw, bh;
  const std::vector<double> ba = blocks(a, block, bw, bh), bb = blocks(b, block, bw, bh);
  double sum = 0;
  for (std::size_t i = 0; i < ba.size(); ++i) sum += (ba[i] - bb[i]) * (ba[i] - bb[i]);
  return ba.empty() ? 0.0 : sum / static_cast<double>(ba.size());
}

ImageDiff compare_images(const RgbaImage& a, const RgbaImage& b, int block) {
  ImageDiff d;
  d.block = block > 0 ? block : (a.width >= 800 ? 16 : 4);
  d.pixels = static_cast<long>(a.width) * a.height;
  double sum_a[3] = {}, sum_b[3] = {};
  for (long i = 0; i < d.pixels; ++i) {
    const uint8_t* pa = &a.rgba[4 * i];
    const uint8_t* pb = &b.rgba[4 * i];
    double worst = std::fabs(static_cast<double>(pa[3]) - pb[3]);
    for (int c = 0; c < 3; ++c) {
      const double x = premul(pa, c), y = premul(pb, c);
      sum_a[c] += x;
      sum_b[c] += y;
      worst = std::fmax(worst, std::fabs(x - y));
    }
    if (worst > 1.0 + 1e-9) ++d.off_by_more_than_1;
    if (pa[3] != pb[3]) ++d.alpha_mismatch;
    if (worst > d.max_channel_error) d.max_channel_error = worst;
    d.coverage_a += pa[3] > 0;
    d.coverage_b += pb[3] > 0;
  }
  for (int c = 0; c < 3; ++c) d.mean_diff[c] = (sum_a[c] - sum_b[c]) / static_cast<double>(d.pixels);
  d.block_mse = block_mse(a, b, d.block);
  d.block_psnr = d.block_mse == 0 ? INFINITY : 10.0 * std::log10(255.0 * 255.0 / d.block_mse);
  return d;
}

RgbaImage contact_sheet(const RgbaImage& a, const RgbaImage& b) {
  constexpr int kGap = 4;
  const int w = a.width, h = a.height;
  RgbaImage out;
  out.width = 3 * w + 2 * kGap;
  out.height = h;
  out.rgba.assign(static_cast<std::size_t>(out.width) * h * 4, 255);
  auto put = [&](int x, int y, double r, double g, double bl) {
    uint8_t* o = &out.rgba[(static_cast<std::size_t>(y) * out.width + x) * 4];
    o[0] = static_cast<uint8_t>(std::fmin(255.0, r));
    o[1] = static_cast<uint8_t>(std::fmin(255.0, g));
    o[2] = static_cast<uint8_t>(std::fmin(255.0, bl));
    o[3] = 255;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t* pa = &a.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      const uint8_t* pb = &b.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      const double check = ((x / 4 + y / 4) % 2 == 0) ? 200.0 : 150.0;
      auto over = [&](const uint8_t* p, int c) { return premul(p, c) + check * (1.0 - p[3] / 255.0); };
      put(x, y, over(pa, 0), over(pa, 1), over(pa, 2));
      put(w + kGap + x, y, over(pb, 0), over(pb, 1), over(pb, 2));
      double worst = std::fabs(static_cast<double>(pa[3]) - pb[3]);
      double diff[3];
      for (int c = 0; c < 3; ++c) {
        diff[c] = std::fabs(premul(pa, c) - premul(pb, c));
        worst = std::fmax(worst, diff[c]);
      }
      if (worst > 1.0 + 1e-9) put(2 * (w + kGap) + x, y, 255, 0, 0);
      else put(2 * (w + kGap) + x, y, 16 * diff[0], 16 * diff[1], 16 * diff[2]);
    }
  return out;
}

}  // namespace minrt::host
