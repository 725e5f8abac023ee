// The host's driver for the scene formats on the general tracer (CS418 so
// far): parse into an arena sized from the text, resolve textures from
// files, build, render rows on several threads, keep the image in memory
// for the caller to write.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "core/base/diagnostic.hpp"
#include "png_io.hpp"
#include "render_variants.hpp"

namespace minrt::host {

class LiveWindow;

struct GeneralOptions {
  Variant variant;
  uint32_t seed = 1;
  int threads = 0;          // 0: every core
  bool force_full = false;  // take the path with every feature compiled in
  bool full_tree = false;   // trace every secondary ray, however small its weight
  LiveWindow* window = nullptr;  // --show: each finished row goes there too
  // Set (by the window's thread) when the rows are no longer wanted: the
  // render threads look after each row and stop; the image is then partial.
  const std::atomic<bool>* cancel = nullptr;
};

struct GeneralResult {
  RgbaImage image;
  std::string output_name;  // from the scene (CS418's png line)
  const char* path = "";    // which compiled path rendered it
  uint32_t features = 0;
  double parse_seconds = 0, build_seconds = 0, render_seconds = 0;  // textures count as parsing
  int threads = 1;
};

// Renders CS418 scene text. `name` is used in messages, `base_dir` resolves
// texture names. On a scene error returns false with `error` set to the full
// message line ("scene.txt:3:7: error: ...").
bool render_cs418(const std::string& text, const std::string& name, const std::string& base_dir,
                  const GeneralOptions& options, GeneralResult& out, std::string& error,
                  const WarningSink& warnings);

// Names of the compiled paths, for --stats and the docs.
const char* general_path_name(uint32_t path);

}  // namespace minrt::host
