// minrt's path for the formats on the general tracer (CS418 so far): read
// the scene file, check where the image goes before the long work, render,
// then write PNG (or PPM when the output name ends in .ppm) all or nothing.
#pragma once

#include <string>

#include "general_render.hpp"
#include "posix/output_file.hpp"

namespace minrt::host {

struct GeneralCli {
  std::string scene_path;      // "-" for standard input
  std::string scene_text;      // already read when scene_path is "-"
  const char* output_path = nullptr;  // -o, else the name in the scene
  bool write_through = false;
  bool allow_any_output = false;  // the png line's name may leave the scene's and working folder
  minrt::host::Durability durability = minrt::host::Durability::kRenameOnly;  // kSynced with --sync
  bool quiet = false;
  bool stats = false;  // print the path and features on standard error
  bool show = false;   // --show: the image in a window afterwards
  GeneralOptions options;
};

// Returns the process's exit status; messages go to standard error.
int run_cs418_cli(GeneralCli& cli);

// The name on a CS418 file's first line ("png W H NAME"), or "" if none.
std::string cs418_output_name(const std::string& text);

// The whole png line: false when the first line is not "png W H NAME" with
// W and H in 1..4096.
bool cs418_png_line(const std::string& text, int& width, int& height, std::string& name);

}  // namespace minrt::host
