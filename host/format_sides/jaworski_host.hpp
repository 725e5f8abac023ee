// Jaworski's scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include <memory>
#include <string>

#include "prepared_scene.hpp"

namespace minrt::host {

std::unique_ptr<PreparedScene> prepare_jaworski(const SceneInput& in, const DriverOptions& options,
                                                const WarningSink& warnings, std::string& error);

// The original's default output name: the extension replaced by .bmp (a
// name without a dot gets .bmp appended).
std::string jaworski_output_name(const std::string& scene_path);

}  // namespace minrt::host
