// minrt's one driver for every scene format: read the scene (bounded),
// recognise its format (formats/registry.hpp), let the format's host side
// (host/format_sides/) parse and set it up, check where the image goes, render
// the rows on the pool (row_pool.hpp) with the window following, print
// --stats, write the image whole or not at all, and report errors in the
// format's style.
#pragma once

#include "png_io.hpp"
#include "prepared_scene.hpp"

namespace minrt::host {

// Exit statuses.
inline constexpr int kExitOk = 0;
inline constexpr int kExitIoError = 1;
inline constexpr int kExitSceneError = 2;
inline constexpr int kExitMinirtError = 1;  // the subject's "exit properly" after "Error"

// Prints one error line in `style`: the 42 subject's "Error" line first.
void print_error(formats::ErrorStyle style, const std::string& line);

// A scene rendered in memory (tests, tools): the format's prepare and the
// row pool, nothing written or shown.
struct RenderedScene {
  RgbaImage image;
  std::string output_name;  // the scene's name for its image, if it gives one
  const char* path = "";    // the tracer's compiled path (--stats)
  uint32_t features = 0;
  int threads = 1;
};

// Renders `in` as `format` with `options` (threads, variant, seed, size);
// false with the message line in `error`. Not for SLD (stream_sld).
bool render_in_memory(const formats::Format& format, const SceneInput& in, const DriverOptions& options,
                      RenderedScene& out, std::string& error, const WarningSink& warnings = {});

// Runs minrt with `options`; returns the exit status.
int run_driver(const DriverOptions& options);

}  // namespace minrt::host
