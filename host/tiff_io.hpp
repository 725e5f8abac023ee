// TIFF on the host through libtiff, loaded at first use: EASTRAY's `output NAME.tif` (8-bit RGB,
// uncompressed strips of one row) and its map_data images.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace minrt::host {

// Writes `rgb` (3 bytes a pixel, top row first) to the open, seekable file
// `f` (left open). False with the reason.
bool write_tiff_rgb(std::FILE* f, int width, int height, const std::vector<uint8_t>& rgb,
                    std::string& error);

// Reads any TIFF libtiff decodes (bilevel, palette, grey, RGB, 16-bit,
// compressed) to 8-bit RGB, top row first (EASTRAY's map_data images).
// False with the reason.
bool read_tiff_rgb(const std::string& path, int& width, int& height, std::vector<uint8_t>& rgb, std::string& error);

}  // namespace minrt::host
