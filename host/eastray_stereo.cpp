#include "eastray_stereo.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "png_io.hpp"

namespace minrt::host {

std::string eastray_stereo_name(const std::string& path, char side) {
  const std::string tag = std::string("_") + side;
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1) return path + tag;
  return path.substr(0, dot) + tag + path.substr(dot);
}

namespace {

bool encode(const RgbaImage& image, std::string& out, std::string& error) {
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* mem = open_memstream(&buffer, &size);
  if (mem == nullptr) {
    error = std::strerror(errno);
    return false;
  }
  const bool ok = write_png(mem, image, error);
  if (std::fclose(mem) != 0 && ok) error = std::strerror(errno);
  if (ok && buffer != nullptr) out.assign(buffer, size);
  std::free(buffer);
  return ok && buffer != nullptr;
}

}  // namespace

bool split_stereo_png(const std::string& png, std::string& right, std::string& left, std::string& error) {
  std::FILE* in = fmemopen(const_cast<char*>(png.data()), png.size(), "rb");
  if (in == nullptr) {
    error = std::strerror(errno);
    return false;
  }
  RgbaImage both;
  if (!read_png(in, both, error, 2 * kMaxPngPixels)) return false;
  if (both.height % 2 != 0) {
    error = "the stereo reply has an odd height (" + std::to_string(both.height) + ")";
    return false;
  }
  RgbaImage half;
  half.width = both.width;
  half.height = both.height / 2;
  const std::size_t bytes = static_cast<std::size_t>(half.width) * half.height * 4;
  half.rgba.assign(both.rgba.begin(), both.rgba.begin() + static_cast<std::ptrdiff_t>(bytes));
  if (!encode(half, right, error)) return false;
  half.rgba.assign(both.rgba.begin() + static_cast<std::ptrdiff_t>(bytes), both.rgba.end());
  return encode(half, left, error);
}

}  // namespace minrt::host
