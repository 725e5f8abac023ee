// Pixel differences between two P6 images of the same size.
#pragma once

#include <string>

namespace minrt_accuracy {

struct ImageDiff {
  bool valid = false;  // both are complete P6 images of the same size
  int width = 0, height = 0;
  int pixels = 0;
  int max_error = 0;   // largest difference of one channel, 0..255
  int differing = 0;   // pixels with any channel different
  int over8 = 0;       // pixels with a channel differing by more than 8
};

// Parses "P6\nW H\n255\n" and checks that exactly W*H*3 bytes follow.
bool parse_p6(const std::string& image, int& width, int& height, size_t& data_offset);

ImageDiff diff_p6(const std::string& a, const std::string& b);

}  // namespace minrt_accuracy
