// Loads PNG, PPM (P3/P6, maxval 255) and BMP (uncompressed 24/32-bit) into
// 8-bit RGBA, for comparing our images with reference ones.
#pragma once

#include <string>

#include "png_io.hpp"

namespace minrt::host {

// By content (the magic bytes), not by name. False with the reason.
bool load_image(const std::string& path, RgbaImage& out, std::string& error);

}  // namespace minrt::host
