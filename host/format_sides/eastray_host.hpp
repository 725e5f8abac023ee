// EASTRAY scenes on the host (host/format_sides/host_formats.cpp's row for it).
#pragma once

#include <memory>
#include <string>

#include "prepared_scene.hpp"

namespace minrt::host {

std::unique_ptr<PreparedScene> prepare_eastray(const SceneInput& in, const DriverOptions& options,
                                               const WarningSink& warnings, std::string& error);

// Where the image goes and in which format, from -o, the scene's output
// statement and the scene's path. `tiff` is set for .tif/.tiff names;
// `warning` is set when an old format's name was replaced by .png.
std::string eastray_output_name(const std::string& option, const std::string& statement,
                                const std::string& scene_path, bool& tiff, std::string& warning);

// What host-send sends the board: the scene preprocessed and checked here
// with the board's reader and arithmetic (so a bad scene is refused with its
// located message before sending), behind the `/* EASTRAY */` marker the
// firmware recognises. Also the image size and the output statement.
bool eastray_board_text(const std::string& path, const std::string& text, std::string& board_text, int& width,
                        int& height, std::string& output_statement, std::string& error);

}  // namespace minrt::host
