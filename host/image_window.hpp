// A window that shows a finished image (minrt --show), with SDL2: ESC, q and
// the close button quit; resizing, covering or minimising keep the image
// (it is drawn again on every expose). Without a display it says so in one
// line and the caller goes on. For tests, MINRT_SHOW_SNAPSHOT=FILE.ppm saves
// what the window shows after the first frame and closes it.
#pragma once

#include <string>

#include "png_io.hpp"

namespace minrt::host {

// Shows `image` (RGBA; transparency over black) titled `title` until the
// user closes the window. False with the reason when there is no window to
// be had (no display, SDL2 not built in); the caller warns and goes on.
bool show_image(const RgbaImage& image, const std::string& title, std::string& why);

}  // namespace minrt::host
