// minrt's path for Jaworski's keyword scenes: like the original program,
// the image goes to the scene's name with .bmp (or -o), -n renders without
// saving; errors are our located one-liners with a non-zero status.
#pragma once

#include <string>

#include "posix/output_file.hpp"
#include "render_variants.hpp"

namespace minrt::host {

struct JaworskiCli {
  std::string scene_path;  // "-" for standard input
  std::string scene_text;  // already read when scene_path is "-"
  const char* output_path = nullptr;
  bool save = true;        // -n turns it off
  bool show = false;       // -s/--show: the image in a window afterwards
  int threads = 0;         // --threads (0: every core); the same bytes for any count
  bool write_through = false;
  minrt::host::Durability durability = minrt::host::Durability::kRenameOnly;  // kSynced with --sync
  Variant variant;
};

int run_jaworski_cli(JaworskiCli& cli);

// The original's default output name: the extension replaced by .bmp (a
// name without a dot gets .bmp appended).
std::string jaworski_output_name(const std::string& scene_path);

}  // namespace minrt::host
