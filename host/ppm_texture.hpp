// Texture files of miniRT scenes: binary (P6) or text (P3) PPM, any maxval up
// to 255 (scaled to 0..255), `#` comments in the header. Decoded to RGB8,
// rows top first, as the core's model::Texture wants them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace minrt::host {

struct RgbTexture {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;
};

// Parses PPM bytes; false with the reason ("not a PPM file", "truncated
// pixel data", ...).
bool decode_ppm(const std::string& bytes, RgbTexture& out, std::string& error);

// Width and height from a PPM file's header alone; false with the reason.
bool ppm_header_size(const std::string& path, int& width, int& height, std::string& error);

// Reads and decodes a file; false with the reason.
bool read_ppm(const std::string& path, RgbTexture& out, std::string& error);

}  // namespace minrt::host
