#include "image_load.hpp"

#include <cctype>
#include <cstdint>

#include "file_input.hpp"

namespace minrt::host {

namespace {

constexpr std::size_t kMaxImageFile = std::size_t{1} << 30;
constexpr int kMaxSide = 32768;

uint32_t le32(const std::string& b, std::size_t at) {
  return static_cast<uint32_t>(static_cast<uint8_t>(b[at])) | static_cast<uint32_t>(static_cast<uint8_t>(b[at + 1])) << 8 |
         static_cast<uint32_t>(static_cast<uint8_t>(b[at + 2])) << 16 |
         static_cast<uint32_t>(static_cast<uint8_t>(b[at + 3])) << 24;
}
uint16_t le16(const std::string& b, std::size_t at) {
  return static_cast<uint16_t>(static_cast<uint8_t>(b[at]) | static_cast<uint8_t>(b[at + 1]) << 8);
}

bool load_bmp(const std::string& b, RgbaImage& out, std::string& error) {
  if (b.size() < 54) return error = "truncated BMP header", false;
  const uint32_t offset = le32(b, 10);
  const int32_t w = static_cast<int32_t>(le32(b, 18));
  int32_t h = static_cast<int32_t>(le32(b, 22));
  const uint16_t bpp = le16(b, 28);
  const uint32_t compression = le32(b, 30);
  const bool top_down = h < 0;
  if (top_down) h = -h;
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide) return error = "bad BMP size", false;
  if ((bpp != 24 && bpp != 32) || (compression != 0 && compression != 3))
    return error = "only uncompressed 24- and 32-bit BMP are read", false;
  const std::size_t stride = (static_cast<std::size_t>(w) * (bpp / 8) + 3) & ~std::size_t{3};
  if (offset > b.size() || b.size() - offset < stride * h) return error = "truncated BMP pixels", false;
  out.width = w;
  out.height = h;
  out.rgba.assign(static_cast<std::size_t>(w) * h * 4, 0);
  for (int y = 0; y < h; ++y) {
    const int row = top_down ? y : h - 1 - y;
    const std::size_t at = offset + stride * row;
    for (int x = 0; x < w; ++x) {
      const std::size_t p = at + static_cast<std::size_t>(x) * (bpp / 8);
      uint8_t* o = &out.rgba[(static_cast<std::size_t>(y) * w + x) * 4];
      o[0] = static_cast<uint8_t>(b[p + 2]);
      o[1] = static_cast<uint8_t>(b[p + 1]);
      o[2] = static_cast<uint8_t>(b[p]);
      o[3] = 255;  // BMP alpha is not meaningful for the formats we compare
    }
  }
  return true;
}

bool load_ppm(const std::string& b, RgbaImage& out, std::string& error) {
  const bool binary = b[1] == '6';
  std::size_t i = 2;
  auto number = [&](int& v) {
    for (;;) {
      while (i < b.size() && std::isspace(static_cast<unsigned char>(b[i]))) ++i;
      if (i < b.size() && b[i] == '#') {
        while (i < b.size() && b[i] != '\n') ++i;
        continue;
      }
      break;
    }
    if (i >= b.size() || !std::isdigit(static_cast<unsigned char>(b[i]))) return false;
    long long x = 0;
    while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i]))) {
      x = x * 10 + (b[i++] - '0');
      if (x > 1 << 30) return false;
    }
    v = static_cast<int>(x);
    return true;
  };
  int w = 0, h = 0, maxval = 0;
  if (!number(w) || !number(h) || !number(maxval)) return error = "bad PPM header", false;
  if (w <= 0 || h <= 0 || w > kMaxSide || h > kMaxSide) return error = "bad PPM size", false;
  if (maxval != 255) return error = "only PPM with maxval 255 is read", false;
  out.width = w;
  out.height = h;
  out.rgba.assign(static_cast<std::size_t>(w) * h * 4, 255);
  const std::size_t n = static_cast<std::size_t>(w) * h;
  if (binary) {
    ++i;  // the single whitespace byte after maxval
    if (b.size() < i || b.size() - i < n * 3) return error = "truncated PPM pixels", false;
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) out.rgba[4 * p + c] = static_cast<uint8_t>(b[i + 3 * p + c]);
  } else {
    for (std::size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) {
        int v = 0;
        if (!number(v) || v > 255) return error = "bad or missing P3 sample", false;
        out.rgba[4 * p + c] = static_cast<uint8_t>(v);
      }
  }
  return true;
}

}  // namespace

bool load_image(const std::string& path, RgbaImage& out, std::string& error) {
  std::string bytes;
  if (!read_whole_file(path, bytes, error, kMaxImageFile)) return false;
  if (bytes.size() >= 8 && static_cast<uint8_t>(bytes[0]) == 0x89 && bytes.compare(1, 3, "PNG") == 0)
    return read_png(path, out, error);
  if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return load_bmp(bytes, out, error);
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '3' || bytes[1] == '6')) return load_ppm(bytes, out, error);
  error = "not a PNG, PPM or BMP file";
  return false;
}

}  // namespace minrt::host
