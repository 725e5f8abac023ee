// An RGBA image written as the file its name asks for: `.png`, `.ppm`
// (binary P6, alpha dropped), `.bmp` (32-bit, as Jaworski's program writes
// it), `.tif`/`.tiff` (RGB through libtiff); any other name gets the
// format's own kind (formats/registry.hpp's reply image).
#pragma once

#include <cstdio>
#include <string>

#include "formats/registry.hpp"
#include "png_io.hpp"

namespace minrt::host {

enum class ImageFile { kPng, kPpm, kBmp, kTiff };

// The kind `name`'s extension asks for (without case), else the one the
// format writes.
ImageFile image_file_for(const std::string& name, formats::ImageKind format_default);

// Whether `name` has an extension that is not one of the kinds above
// ("out.jpg"): -o refuses it rather than write a PNG under that name.
bool has_foreign_extension(const std::string& name);
inline constexpr const char* kImageExtensions = ".png, .ppm, .bmp, .tif or .tiff";

// `path` with the extension of its last name replaced by `ext` (".bmp"), or
// with `ext` appended when that name has no dot: a scene's default image name.
std::string with_extension(const std::string& path, const char* ext);

// P6, maxval 255, the RGB of each pixel. False when a write fails (errno
// says why).
bool write_ppm(std::FILE* f, const RgbaImage& image);

// Writes `image` as `kind`; false with the reason in `why`.
bool write_image(std::FILE* f, ImageFile kind, const RgbaImage& image, std::string& why);

}  // namespace minrt::host
