#include "image_file_output.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

namespace minrt::host {

bool write_ppm(std::FILE* f, const RgbaImage& image) {
  if (std::fprintf(f, "P6\n%d %d\n255\n", image.width, image.height) < 0) return false;
  std::vector<uint8_t> row(static_cast<std::size_t>(image.width) * 3);
  for (int y = 0; y < image.height; ++y) {
    const uint8_t* src = image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4;
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) row[3 * x + c] = src[4 * x + c];
    if (std::fwrite(row.data(), 1, row.size(), f) != row.size()) return false;
  }
  return true;
}

bool write_image_file(std::FILE* f, const std::string& name, const RgbaImage& image, std::string& why) {
  const std::string ppm = ".ppm";
  const bool is_ppm = name.size() >= ppm.size() && name.compare(name.size() - ppm.size(), ppm.size(), ppm) == 0;
  if (!is_ppm) return write_png(f, image, why);
  if (write_ppm(f, image)) return true;
  why = std::strerror(errno);
  return false;
}

}  // namespace minrt::host
