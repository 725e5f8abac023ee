// An RGBA image written as the file its name asks for: `.ppm` binary PPM
// (P6, alpha dropped), anything else PNG. minrt's CS418 and miniRT front
// ends both take either from -o.
#pragma once

#include <cstdio>
#include <string>

#include "png_io.hpp"

namespace minrt::host {

// P6, maxval 255, the RGB of each pixel. False when a write fails (errno
// says why).
bool write_ppm(std::FILE* f, const RgbaImage& image);

// PPM when `name` ends in .ppm, else PNG; false with the reason in `why`.
bool write_image_file(std::FILE* f, const std::string& name, const RgbaImage& image, std::string& why);

}  // namespace minrt::host
