// 42 miniRT scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include <memory>
#include <string>

#include "prepared_scene.hpp"

namespace minrt::host {

std::unique_ptr<PreparedScene> prepare_minirt(const SceneInput& in, const DriverOptions& options,
                                              const WarningSink& warnings, std::string& error);

// Whether a file name ends in .rt (not ".rt" alone), the subject's rule.
bool has_rt_extension(const std::string& path);

}  // namespace minrt::host
