#include "image_diff.hpp"

#include <cstdio>
#include <cstdlib>

namespace minrt_accuracy {

bool parse_p6(const std::string& image, int& width, int& height, size_t& data_offset) {
  int consumed = 0;
  if (std::sscanf(image.c_str(), "P6\n%d %d\n255\n%n", &width, &height, &consumed) != 2 ||
      consumed == 0 || width <= 0 || height <= 0)
    return false;
  data_offset = static_cast<size_t>(consumed);
  return image.size() == data_offset + static_cast<size_t>(width) * height * 3;
}

ImageDiff diff_p6(const std::string& a, const std::string& b) {
  ImageDiff d;
  int wb = 0, hb = 0;
  size_t oa = 0, ob = 0;
  if (!parse_p6(a, d.width, d.height, oa) || !parse_p6(b, wb, hb, ob) || wb != d.width ||
      hb != d.height)
    return d;
  d.valid = true;
  d.pixels = d.width * d.height;
  for (int p = 0; p < d.pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int e = std::abs(static_cast<unsigned char>(a[oa + 3 * p + c]) -
                             static_cast<unsigned char>(b[ob + 3 * p + c]));
      if (e > worst) worst = e;
    }
    if (worst > d.max_error) d.max_error = worst;
    if (worst > 0) ++d.differing;
    if (worst > 8) ++d.over8;
  }
  return d;
}

}  // namespace minrt_accuracy
