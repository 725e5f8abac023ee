// minrt's path for miniRT scenes (`.rt`), as the 42 subject wants it: the
// image in a window (ESC or the close button quit), or with -o written to a
// PNG or PPM file for headless use. Any misconfiguration prints "Error" and
// one explicit line naming what and where on standard error, exit status 1,
// and neither image nor window.
#pragma once

#include <string>

#include "formats/minirt/minirt_reader.hpp"
#include "general_render.hpp"
#include "posix/output_file.hpp"

namespace minrt::host {

inline constexpr int kMinirtExitError = 1;

struct MinirtCli {
  std::string scene_path;
  const char* output_path = nullptr;  // -o: write instead of showing
  bool show = false;                  // --show with -o: both
  bool write_through = false;
  minrt::host::Durability durability = minrt::host::Durability::kRenameOnly;  // kSynced with --sync
  bool stats = false;
  int width = 0, height = 0;          // 0: the default size
  GeneralOptions options;
  minirt::ReaderOptions reader;       // --mandatory, --cylinder-base
};

int run_minirt_cli(MinirtCli& cli);

// Prints the subject's error form: "Error", then the line.
void print_minirt_error(const std::string& line);

// True when the name ends in ".rt" after at least one character.
bool has_rt_extension(const std::string& path);

}  // namespace minrt::host
