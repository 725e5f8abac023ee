// The names of EASTRAY's stereo pair (rmode 1, manual line 57): the output
// file's name with `_r` and `_l` added before its extension, which keeps
// choosing the format (line 173): pic.tif -> pic_r.tif, pic_l.tif.
#pragma once

#include <string>

namespace minrt::host {

// `side` 'r' or 'l'.
std::string eastray_stereo_name(const std::string& path, char side);

}  // namespace minrt::host
