// What minrt's one driver (render_driver.cpp) needs from a scene format on
// the host: parse and set up a scene (`prepare`), then render any row on any
// thread. Each format's side lives in host/format_sides/FORMAT_host.cpp and has
// one row in kHostFormats (host/format_sides/host_formats.hpp), indexed by the
// registry's FormatId (formats/registry.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/base/diagnostic.hpp"
#include "formats/registry.hpp"
#include "image_file_output.hpp"
#include "posix/output_file.hpp"
#include "render_variants.hpp"

namespace minrt::host {

class LiveWindow;

// The run's settings, the same for every format (minrt --help).
struct DriverOptions {
  const formats::Format* format = nullptr;  // --scene-format; null: detect
  std::string scene_path = "-";             // "-": standard input
  std::string output_path;                  // -o; empty: the format's default name
  bool save = true;                         // -n turns it off
  bool show = false;                        // --show
  bool quiet = false;                       // -q: no warnings
  bool progress = false;                    // the progress line on stderr for long renders (minrt: on a terminal)
  bool stats = false;                       // --stats
  bool write_through = false;
  bool allow_any_output = false;            // a scene's own output name may leave its and the working folder
  Durability durability = Durability::kRenameOnly;
  Variant variant;
  int threads = 0;                          // 0: every core
  uint32_t seed = 1;                        // CS418's random numbers
  bool force_full = false;                  // --all-features
  bool full_tree = false;                   // --full-tree
  bool mandatory = false;                   // miniRT: --mandatory
  bool cylinder_base = false;               // miniRT: --cylinder-base
  std::vector<std::string> format_options;  // the format-only options given (formats::Format::options)
  int width = 0, height = 0;                // --size; 0: the format's
  bool p6 = false;                          // SLD: --format p6
};

// The scene file as read: its text (a UTF-8 byte-order mark removed), its
// path as given ("-" for standard input), the name messages use and the
// folder textures and includes are found from (with its slash, or "").
struct SceneInput {
  std::string path, shown, base_dir, text;
};

// A render shows its progress line only once it has run this long and will
// take at least twice that in all (posix/progress_line.hpp).
inline constexpr double kProgressAfterSeconds = 1.0;

// A scene ready to render. render_row may be called from several threads
// at once, each row once.
class PreparedScene {
 public:
  virtual ~PreparedScene() = default;
  // Row y (0 = top) as RGBA, width*4 bytes.
  virtual void render_row(int y, uint8_t* rgba) const = 0;

  int width = 0, height = 0;
  std::string output_name;  // where the scene puts its image ("": the driver's default)
  bool opaque = true;       // alpha is 255 everywhere (not for CS418's background)
  // Images one render makes (EASTRAY's stereo pair: 2); select_view(v)
  // comes before the rows of image v, which goes to view_output_name.
  int views = 1;
  virtual void select_view(int) {}
  virtual std::string view_output_name(const std::string& out_path, int) const { return out_path; }
  // Just before `image` is written to `out_path` as `kind`: a format may
  // change the pixels (EASTRAY: 32K colours, an existing file's pixels
  // outside the display window). Returns a warning line, or "".
  virtual std::string finish_image(const std::string&, ImageFile, RgbaImage&) const { return ""; }
  // The rows as rendered are the file's pixels (finish_image changes
  // nothing), so the driver may write them as they are done.
  bool rows_final = false;

  // --stats
  const char* path = "";
  uint32_t features = 0;
  double parse_seconds = 0, build_seconds = 0;
};

// A format's host side. `prepare` parses and sets up; on failure it returns
// null with `error` set to the message line (without the "Error" line of
// miniRT's style, which the driver prints). `stream` instead writes the
// image's bytes itself (SLD: the original's PPM, byte for byte). Both report
// warnings through the driver's sink.
struct HostFormat {
  formats::FormatId id;
  std::unique_ptr<PreparedScene> (*prepare)(const SceneInput& in, const DriverOptions& options,
                                            const WarningSink& warnings, std::string& error);
  int (*stream)(const SceneInput& in, const DriverOptions& options, const WarningSink& warnings);
};

}  // namespace minrt::host
