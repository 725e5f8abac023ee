// The names of EASTRAY's stereo pair (rmode 1, manual line 57): the output
// file's name with `_r` and `_l` added before its extension, which keeps
// choosing the format (line 173): pic.tif -> pic_r.tif, pic_l.tif; and the
// board's pair cut in two.
#pragma once

#include <string>

namespace minrt::host {

// `side` 'r' or 'l'.
std::string eastray_stereo_name(const std::string& path, char side);

// The board sends the pair as one PNG, the right image above the left (each
// half of its height). Cuts it into the two images, each compressed; false
// with the reason.
bool split_stereo_png(const std::string& png, std::string& right, std::string& left, std::string& error);

}  // namespace minrt::host
