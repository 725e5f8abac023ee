// CS418 scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include <memory>
#include <string>

#include "prepared_scene.hpp"

namespace minrt::host {

std::unique_ptr<PreparedScene> prepare_cs418(const SceneInput& in, const DriverOptions& options,
                                             const WarningSink& warnings, std::string& error);

// The png line ("png W H NAME"), the first line that is not blank or a
// comment: false when it is missing or malformed (W and H in 1..the image
// limit); fields after the name are ignored, as the reader ignores them.
bool cs418_png_line(const std::string& text, int& width, int& height, std::string& name);

}  // namespace minrt::host
