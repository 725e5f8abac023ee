// SLD scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include "prepared_scene.hpp"

namespace minrt::host {

// Renders and writes the PPM itself, warnings to `warnings`; returns the
// exit status.
int stream_sld(const SceneInput& in, const DriverOptions& options, const WarningSink& warnings);

}  // namespace minrt::host
