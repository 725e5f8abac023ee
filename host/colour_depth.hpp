// EASTRAY's 16-bit output (output_mode 16, manual lines 152-164): the
// image reduced to 32K colours (5 bits a channel), with an ordered dither
// when asked, which hides the Mach bands the coarser steps make. Only TIFF
// output varies in depth (line 157); the 5-bit levels are stored in 8-bit
// samples (level x 255 / 31), which every TIFF reader reads.
#pragma once

#include <cstdint>
#include <vector>

namespace minrt::host {

// `rgb`: width x height, 3 bytes a pixel, reduced in place.
void reduce_to_32k_colours(std::vector<uint8_t>& rgb, int width, int height, bool dither);

}  // namespace minrt::host
