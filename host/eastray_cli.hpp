// minrt's path for EASTRAY `.ray` scenes: preprocess on the host, read,
// render, and write the image to -o, else the scene's `output` name, else
// the scene's name with .png. `.tif` goes through libtiff, anything else is
// PNG (the old .fal/.ipr/.hpi formats: a warning, and PNG under .png).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "posix/output_file.hpp"
#include "render_variants.hpp"

namespace minrt::host {

class LiveWindow;

struct EastrayCli {
  std::string scene_path;  // "-" for standard input
  std::string scene_text;  // already read when scene_path is "-"
  const char* output_path = nullptr;
  bool save = true;        // -n turns it off
  bool quiet = false;      // -q: no warnings
  bool write_through = false;
  minrt::host::Durability durability = minrt::host::Durability::kRenameOnly;  // kSynced with --sync
  bool show = false;       // -s: a window that shows the rows as they render
  Variant variant;
};

int run_eastray_cli(EastrayCli& cli);

struct EastrayImage {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;      // 3 bytes a pixel, top row first
  std::string output_statement;  // the scene's `output` name, if any
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // the display window: the pixels computed
  int output_bits = 24;          // output_mode
  bool dither = false;
  bool stereo = false;           // rmode 1: rgb is the right eye's image,
  std::vector<uint8_t> rgb_left; // this the left's
};

// Preprocesses `text` (read from `path`, shown as `shown`; includes are
// found from it), reads and renders it. False with the one-line message.
// Warnings go to standard error unless `quiet`.
// `window` (--show), when open, gets each row as it is rendered.
bool render_eastray(const std::string& path, const std::string& shown, const std::string& text, Variant v,
                    bool quiet, EastrayImage& out, std::string& error, LiveWindow* window = nullptr);

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
