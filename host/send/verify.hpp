// Comparing a received image with a reference (P3 or P6) and hashing it.
#pragma once

#include <minrt/limits.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace minrt::send {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;
};

// The largest reference --verify reads: a P3 of the largest image the board
// sends (minrt/limits.hpp) at up to 16 bytes a pixel (three numbers of up to
// three digits with their separators, as other writers lay them out), and a
// header. A larger file cannot be such an image.
inline constexpr std::size_t kMaxReferenceBytes =
    std::size_t{16} * minrt::limits::kMaxImageWidth * minrt::limits::kMaxImageHeight + 4096;

// Parses a P3 or P6 file's bytes (maxval 255); false with a message.
bool parse_ppm(const std::string& bytes, Image& image, std::string& error);
bool load_ppm(const std::string& path, Image& image, std::string& error);

struct Comparison {
  bool same_size = false;
  std::uint64_t differing_pixels = 0;
  int max_channel_error = 0;
  double psnr_db = 0;  // +infinity when identical
};

Comparison compare_images(const Image& a, const Image& b);
std::string describe(const Comparison& c);

std::string sha256_hex_of(const std::string& bytes);
// Accepts upper or lower case; false when `hex` is not 64 hex digits.
bool valid_sha256_hex(const std::string& hex);
bool same_sha256(const std::string& a, const std::string& b);

}  // namespace minrt::send
