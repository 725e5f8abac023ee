#include "image_file_output.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/image/bmp_writer.hpp"
#include "tiff_io.hpp"

namespace minrt::host {

ImageFile image_file_for(const std::string& name, formats::ImageKind format_default) {
  if (formats::has_extension(name.c_str(), ".png")) return ImageFile::kPng;
  if (formats::has_extension(name.c_str(), ".ppm")) return ImageFile::kPpm;
  if (formats::has_extension(name.c_str(), ".bmp")) return ImageFile::kBmp;
  if (formats::has_extension(name.c_str(), ".tif") || formats::has_extension(name.c_str(), ".tiff"))
    return ImageFile::kTiff;
  switch (format_default) {
    case formats::ImageKind::kPpm: return ImageFile::kPpm;
    case formats::ImageKind::kBmp: return ImageFile::kBmp;
    case formats::ImageKind::kPng: break;
  }
  return ImageFile::kPng;
}

bool has_foreign_extension(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::size_t slash = name.rfind('/');
  if (dot == std::string::npos || dot + 1 == name.size() || (slash != std::string::npos && dot < slash) ||
      dot == (slash == std::string::npos ? 0 : slash + 1))
    return false;  // no extension (a leading dot names a hidden file)
  for (const char* ext : {".png", ".ppm", ".bmp", ".tif", ".tiff"})
    if (formats::has_extension(name.c_str(), ext)) return false;
  return true;
}

std::string with_extension(const std::string& path, const char* ext) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ext;
  return path.substr(0, dot) + ext;
}

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

namespace {

// The BMP stores the bottom row first, each pixel as BGRA.
bool write_bmp(std::FILE* f, const RgbaImage& image) {
  uint8_t header[BmpWriter::kHeaderBytes];
  BmpWriter::header(header, image.width, image.height);
  if (std::fwrite(header, 1, sizeof header, f) != sizeof header) return false;
  std::vector<uint8_t> row(static_cast<std::size_t>(image.width) * 4);
  for (int y = image.height - 1; y >= 0; --y) {
    BmpWriter::to_bgra(image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4, row.data(), image.width);
    if (std::fwrite(row.data(), 1, row.size(), f) != row.size()) return false;
  }
  return true;
}

bool write_tiff(std::FILE* f, const RgbaImage& image, std::string& why) {
  std::vector<uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(image.width) * image.height; i < n; ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
  return write_tiff_rgb(f, image.width, image.height, rgb, why);
}

}  // namespace

bool write_image(std::FILE* f, ImageFile kind, const RgbaImage& image, std::string& why) {
  bool ok = false;
  switch (kind) {
    case ImageFile::kPng: return write_png(f, image, why);
    case ImageFile::kTiff: return write_tiff(f, image, why);
    case ImageFile::kPpm: ok = write_ppm(f, image); break;
    case ImageFile::kBmp: ok = write_bmp(f, image); break;
  }
  if (!ok) why = std::strerror(errno);
  return ok;
}

}  // namespace minrt::host
