#include "verify.hpp"

#include "file_input.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>

#include "sha256.hpp"

namespace minrt::send {

namespace {

struct Cursor {
  const std::string& s;
  std::size_t i = 0;

  void skip_space_and_comments() {
    while (i < s.size()) {
      if (std::isspace(static_cast<unsigned char>(s[i]))) {
        ++i;
      } else if (s[i] == '#') {
        while (i < s.size() && s[i] != '\n') ++i;
      } else {
        break;
      }
    }
  }
  bool number(long& v) {
    skip_space_and_comments();
    if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return false;
    v = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) {
      v = v * 10 + (s[i++] - '0');
      if (v > 1000000) return false;
    }
    return true;
  }
};

}  // namespace

bool parse_ppm(const std::string& bytes, Image& image, std::string& error) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '3' && bytes[1] != '6')) {
    error = "not a P3 or P6 file";
    return false;
  }
  const bool binary = bytes[1] == '6';
  Cursor c{bytes, 2};
  long w = 0, h = 0, maxval = 0;
  if (!c.number(w) || !c.number(h) || !c.number(maxval) || w < 1 || h < 1 || w > 16384 || h > 16384) {
    error = "bad PPM header";
    return false;
  }
  if (maxval != 255) {
    error = "PPM maxval is not 255";
    return false;
  }
  image.width = static_cast<int>(w);
  image.height = static_cast<int>(h);
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3;
  image.rgb.resize(n);
  if (binary) {
    ++c.i;  // the single whitespace byte after maxval
    if (bytes.size() - std::min(c.i, bytes.size()) < n) {
      error = "P6 pixel data is truncated";
      return false;
    }
    for (std::size_t k = 0; k < n; ++k) image.rgb[k] = static_cast<std::uint8_t>(bytes[c.i + k]);
    return true;
  }
  for (std::size_t k = 0; k < n; ++k) {
    long v = 0;
    if (!c.number(v) || v > 255) {
      error = "P3 pixel data is truncated or malformed";
      return false;
    }
    image.rgb[k] = static_cast<std::uint8_t>(v);
  }
  return true;
}

bool load_ppm(const std::string& path, Image& image, std::string& error) {
  std::string bytes, why;
  if (!minrt::host::read_whole_file(path, bytes, why, kMaxReferenceBytes)) {
    error = "cannot read " + path + ": " + why;
    return false;
  }
  if (!parse_ppm(bytes, image, error)) {
    error = path + ": " + error;
    return false;
  }
  return true;
}

Comparison compare_images(const Image& a, const Image& b) {
  Comparison c;
  c.same_size = a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size();
  if (!c.same_size) return c;
  double sq = 0;
  for (std::size_t p = 0; p + 2 < a.rgb.size(); p += 3) {
    bool differs = false;
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(static_cast<int>(a.rgb[p + k]) - static_cast<int>(b.rgb[p + k]));
      if (d != 0) differs = true;
      if (d > c.max_channel_error) c.max_channel_error = d;
      sq += static_cast<double>(d) * d;
    }
    if (differs) ++c.differing_pixels;
  }
  const double mse = a.rgb.empty() ? 0 : sq / static_cast<double>(a.rgb.size());
  c.psnr_db = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  return c;
}

std::string describe(const Comparison& c) {
  if (!c.same_size) return "sizes differ";
  char buf[160];
  if (std::isinf(c.psnr_db))
    std::snprintf(buf, sizeof buf, "%llu pixels differ, max channel error %d, PSNR inf dB",
                  static_cast<unsigned long long>(c.differing_pixels), c.max_channel_error);
  else
    std::snprintf(buf, sizeof buf, "%llu pixels differ, max channel error %d, PSNR %.2f dB",
                  static_cast<unsigned long long>(c.differing_pixels), c.max_channel_error, c.psnr_db);
  return buf;
}

std::string sha256_hex_of(const std::string& bytes) { return minrt::host::sha256_hex(bytes); }

bool valid_sha256_hex(const std::string& hex) {
  if (hex.size() != 64) return false;
  for (char ch : hex)
    if (!std::isxdigit(static_cast<unsigned char>(ch))) return false;
  return true;
}

bool same_sha256(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace minrt::send
