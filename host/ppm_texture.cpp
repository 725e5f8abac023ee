#include "ppm_texture.hpp"

#include <unistd.h>

#include <cerrno>

#include <minrt/limits.hpp>

#include "file_input.hpp"

namespace minrt::host {

namespace {

constexpr std::size_t kMaxTextureFileBytes = std::size_t{1} << 28;

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }

// Header number after blanks and comments; false when there is none.
bool header_number(const std::string& s, std::size_t& i, long& out) {
  for (;;) {
    while (i < s.size() && is_blank(s[i])) ++i;
    if (i < s.size() && s[i] == '#') {
      while (i < s.size() && s[i] != '\n') ++i;
      continue;
    }
    break;
  }
  if (i >= s.size() || s[i] < '0' || s[i] > '9') return false;
  out = 0;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') {
    out = out * 10 + (s[i] - '0');
    if (out > 1000000) return false;
    ++i;
  }
  return true;
}

}  // namespace

bool decode_ppm(const std::string& bytes, RgbTexture& out, std::string& error) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '6' && bytes[1] != '3')) {
    error = "not a PPM file (expected P6 or P3)";
    return false;
  }
  const bool binary = bytes[1] == '6';
  std::size_t i = 2;
  long w = 0, h = 0, maxval = 0;
  if (!header_number(bytes, i, w) || !header_number(bytes, i, h) || !header_number(bytes, i, maxval)) {
    error = "bad PPM header";
    return false;
  }
  if (w < 1 || h < 1 || w > limits::kMaxImageWidth || h > limits::kMaxImageHeight) {
    error = "PPM size " + std::to_string(w) + "x" + std::to_string(h) + " is outside 1..4096";
    return false;
  }
  if (maxval < 1 || maxval > 255) {
    error = "PPM maxval " + std::to_string(maxval) + " is not in 1..255";
    return false;
  }
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3;
  // Too few bytes for the pixels the header claims (P6: one a sample, P3: a
  // digit and a blank): refused before the pixels are allocated.
  if (bytes.size() - i < (binary ? n : 2 * n - 1)) {
    error = binary ? "truncated pixel data" : "truncated or bad pixel data";
    return false;
  }
  out.width = static_cast<int>(w);
  out.height = static_cast<int>(h);
  out.rgb.assign(n, 0);
  auto scaled = [&](long v) { return static_cast<uint8_t>((v * 255 + maxval / 2) / maxval); };
  if (binary) {
    if (i >= bytes.size() || !is_blank(bytes[i])) {
      error = "bad PPM header";
      return false;
    }
    ++i;  // the single blank before the pixels
    if (bytes.size() - i < n) {
      error = "truncated pixel data";
      return false;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const long v = static_cast<unsigned char>(bytes[i + k]);
      if (v > maxval) {
        error = "sample above maxval";
        return false;
      }
      out.rgb[k] = scaled(v);
    }
    return true;
  }
  for (std::size_t k = 0; k < n; ++k) {
    long v = 0;
    if (!header_number(bytes, i, v)) {
      error = "truncated or bad pixel data";
      return false;
    }
    if (v > maxval) {
      error = "sample above maxval";
      return false;
    }
    out.rgb[k] = scaled(v);
  }
  return true;
}

bool ppm_header_size(const std::string& path, int& width, int& height, std::string& error) {
  const int fd = open_regular_file(path, error);
  if (fd < 0) return false;
  std::string head(4096, '\0');
  std::size_t got = 0;
  while (got < head.size()) {
    const ssize_t n = ::read(fd, head.data() + got, head.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += static_cast<std::size_t>(n);
  }
  ::close(fd);
  head.resize(got);
  std::size_t i = 2;
  long w = 0, h = 0;
  if (head.size() < 2 || head[0] != 'P' || (head[1] != '6' && head[1] != '3')) {
    error = "not a PPM file (expected P6 or P3)";
    return false;
  }
  if (!header_number(head, i, w) || !header_number(head, i, h) || w < 1 || h < 1) {
    error = "bad PPM header";
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

bool read_ppm(const std::string& path, RgbTexture& out, std::string& error) {
  std::string bytes;
  if (!read_whole_file(path, bytes, error, kMaxTextureFileBytes)) return false;
  return decode_ppm(bytes, out, error);
}

}  // namespace minrt::host
