// Rendering a window into an existing image file (EASTRAY manual line 180):
// when the file is there with the same format and size, only the window's
// pixels change; otherwise it is made afresh, black outside the window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace minrt::host {

struct PixelWindow {
  int x0, y0, x1, y1;  // inclusive
};

enum class MergeOutcome { kNoFile, kMerged, kReplaced };

// `rgb` (width x height, 3 bytes a pixel) is about to be written to `path`
// as TIFF (`tiff`) or PNG. If `path` holds an image of that format and size,
// its pixels outside `window` are copied into `rgb` (kMerged). If it holds
// anything else (another format, another size, not an image), `why` says
// what and the file will be replaced (kReplaced). No file: kNoFile.
MergeOutcome merge_outside_window(const std::string& path, bool tiff, int width, int height, const PixelWindow& window,
                                  std::vector<uint8_t>& rgb, std::string& why);

}  // namespace minrt::host
