// PNG on the host through libpng (which compresses with zlib): textures in,
// images out. The board never sees this: it streams stored-deflate PNG from
// the core (core/image/png_writer.hpp) or sends rows for host-send to write.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace minrt::host {

// The most pixels read_png decodes by default: 2^25 (8192 x 4096), 128 MiB
// of RGBA.
inline constexpr std::uint64_t kMaxPngPixels = std::uint64_t{1} << 25;

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes a pixel, top row first
};

// Decodes any PNG (palette, grey, 16-bit, interlaced, ...) to 8-bit RGBA.
// False with the reason ("not a PNG file", libpng's message, the system's
// error) when it cannot.
// `max_pixels` bounds width x height, checked on the header before any
// pixel is decoded (a small file may inflate to gigabytes). The file must
// be a regular file (file_input.hpp's open_regular_file).
bool read_png(const std::string& path, RgbaImage& out, std::string& error,
              std::uint64_t max_pixels = kMaxPngPixels);
// The same from an open stream, which it closes.
bool read_png(std::FILE* f, RgbaImage& out, std::string& error, std::uint64_t max_pixels = kMaxPngPixels);

// Width and height from a PNG file's header (signature and IHDR), without
// decoding; false with the reason.
bool png_header_size(const std::string& path, int& width, int& height, std::string& error);

// Writes 8-bit RGBA, compressed. False with the reason.
bool write_png(std::FILE* f, const RgbaImage& image, std::string& error);

// A PNG held in memory decoded, and an image encoded as a PNG in memory.
bool decode_png(const std::string& png, RgbaImage& image, std::string& error,
                std::uint64_t max_pixels = kMaxPngPixels);
bool encode_png(const RgbaImage& image, std::string& out, std::string& error);

// The same pixels compressed: the board streams stored-deflate PNG (no
// compressor fits its budget), host-send writes what libpng makes of it.
bool compress_png(const std::string& png, std::string& out, std::string& error);

}  // namespace minrt::host
