#include "eastray_stereo.hpp"

#include "png_io.hpp"

namespace minrt::host {

std::string eastray_stereo_name(const std::string& path, char side) {
  const std::string tag = std::string("_") + side;
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1) return path + tag;
  return path.substr(0, dot) + tag + path.substr(dot);
}

bool split_stereo_png(const std::string& png, std::string& right, std::string& left, std::string& error) {
  RgbaImage both;
  if (!decode_png(png, both, error, 2 * kMaxPngPixels)) return false;
  if (both.height % 2 != 0) {
    error = "the stereo reply has an odd height (" + std::to_string(both.height) + ")";
    return false;
  }
  RgbaImage half;
  half.width = both.width;
  half.height = both.height / 2;
  const std::size_t bytes = static_cast<std::size_t>(half.width) * half.height * 4;
  half.rgba.assign(both.rgba.begin(), both.rgba.begin() + static_cast<std::ptrdiff_t>(bytes));
  if (!encode_png(half, right, error)) return false;
  half.rgba.assign(both.rgba.begin() + static_cast<std::ptrdiff_t>(bytes), both.rgba.end());
  return encode_png(half, left, error);
}

}  // namespace minrt::host
