// PNG on the host through libpng (which compresses with zlib): textures in,
// images out. The board never sees this: it streams stored-deflate PNG from
// the core (core/image/png_writer.hpp) or sends rows for host-send to write.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace minrt::host {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes a pixel, top row first
};

// Decodes any PNG (palette, grey, 16-bit, interlaced, ...) to 8-bit RGBA.
// False with the reason ("not a PNG file", libpng's message, the system's
// error) when it cannot.
bool read_png(const std::string& path, RgbaImage& out, std::string& error);
// The same from an open stream, which it closes.
bool read_png(std::FILE* f, RgbaImage& out, std::string& error);

// Writes 8-bit RGBA, compressed. False with the reason.
bool write_png(std::FILE* f, const RgbaImage& image, std::string& error);

// The same pixels compressed: the board streams stored-deflate PNG (no
// compressor fits its budget), host-send writes what libpng makes of it.
bool compress_png(const std::string& png, std::string& out, std::string& error);

}  // namespace minrt::host
