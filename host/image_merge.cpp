#include "image_merge.hpp"

#include <sys/stat.h>

#include <cstdio>

#include "png_io.hpp"
#include "tiff_io.hpp"

namespace minrt::host {

MergeOutcome merge_outside_window(const std::string& path, bool tiff, int width, int height, const PixelWindow& window,
                                  std::vector<uint8_t>& rgb, std::string& why) {
  struct stat st {};
  if (path == "-" || ::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return MergeOutcome::kNoFile;
  int w = 0, h = 0;
  std::vector<uint8_t> old;
  std::string reason;
  bool read = false;
  if (tiff) {
    read = read_tiff_rgb(path, w, h, old, reason);
  } else {
    RgbaImage img;
    read = read_png(path, img, reason);
    if (read) {
      w = img.width, h = img.height;
      old.resize(static_cast<std::size_t>(w) * h * 3);
      for (std::size_t i = 0, n = static_cast<std::size_t>(w) * h; i < n; ++i)
        for (int c = 0; c < 3; ++c) old[3 * i + c] = img.rgba[4 * i + c];
    }
  }
  if (!read) {
    why = "the existing " + path + " is not a " + (tiff ? "TIFF" : "PNG") + " image (" + reason + ")";
    return MergeOutcome::kReplaced;
  }
  if (w != width || h != height) {
    why = "the existing " + path + " is " + std::to_string(w) + "x" + std::to_string(h) + ", not " +
          std::to_string(width) + "x" + std::to_string(height);
    return MergeOutcome::kReplaced;
  }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (x >= window.x0 && x <= window.x1 && y >= window.y0 && y <= window.y1) continue;
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
      for (int c = 0; c < 3; ++c) rgb[i + c] = old[i + c];
    }
  return MergeOutcome::kMerged;
}

}  // namespace minrt::host
