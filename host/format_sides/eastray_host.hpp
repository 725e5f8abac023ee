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
// `output`, when given, gets what eastray_board_file needs.
struct EastrayBoardOutput {
  bool stereo = false;       // rmode 1: the board sends the right image above the left (eastray_stereo.hpp)
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the display window (inclusive)
  int bits = 24;             // output_mode
  bool dither = false;
  std::vector<std::string> warnings;  // the scene's warnings, each a "FILE:LINE:COL: warning: ..." line
};
bool eastray_board_text(const std::string& path, const std::string& text, std::string& board_text, int& width,
                        int& height, std::string& output_statement, std::string& error,
                        std::vector<std::pair<std::string, std::string>>* maps = nullptr,
                        EastrayBoardOutput* output = nullptr);

// The file host-send writes at `path` from the board's PNG (one image of a
// stereo pair, or the only one), as minrt writes its own: TIFF for a .tif
// or .tiff name (reduced to 32K colours under output_mode 16), PNG
// otherwise; an existing file of the same format and size keeps its pixels
// outside the display window (line 180). `warning` says when an existing
// file of another kind is replaced. False with the reason.
bool eastray_board_file(const std::string& png, const EastrayBoardOutput& how, const std::string& path,
                        std::string& file, std::string& warning, std::string& error);

}  // namespace minrt::host
