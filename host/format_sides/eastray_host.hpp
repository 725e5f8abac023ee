// EASTRAY scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "prepared_scene.hpp"

namespace minrt::host {

std::unique_ptr<PreparedScene> prepare_eastray(const SceneInput& in, const DriverOptions& options,
                                               const WarningSink& warnings, std::string& error);

// Where the image goes and in which format, from -o, the scene's output
// statement and the scene's path. `tiff` is set for .tif/.tiff names;
// `unsupported` is set (the reason) for the manual's .fal, .ipr and .hpi,
// which no library writes.
std::string eastray_output_name(const std::string& option, const std::string& statement,
                                const std::string& scene_path, bool& tiff, std::string& unsupported);

// What host-send sends the board: the scene preprocessed and checked here
// with the board's reader and arithmetic (so a bad scene is refused with its
// located message before sending), behind the `/* EASTRAY */` marker the
// firmware recognises. Also the image size and the output statement, and
// (when `maps` is given) the map_data file names as written, each with the
// "FILE:LINE:COL: error: " its load errors start with.
bool eastray_board_text(const std::string& path, const std::string& text, std::string& board_text, int& width,
                        int& height, std::string& output_statement, std::string& error,
                        std::vector<std::pair<std::string, std::string>>* maps = nullptr);

}  // namespace minrt::host
