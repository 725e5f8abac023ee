#include "general_cli.hpp"

#include <cstdio>
#include <sstream>

#include <minrt/limits.hpp>

#include "core/base/text_numbers.hpp"
#include "file_input.hpp"
#include "image_file_output.hpp"
#include "image_window.hpp"
#include "posix/output_file.hpp"

namespace minrt::host {

namespace {

constexpr int kExitSceneError = 2;
constexpr int kExitIoError = 1;

struct WarningContext {
  const char* file;
};
void print_warning(void* ctx, const Diagnostic& d) {
  const auto* w = static_cast<const WarningContext*>(ctx);
  std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w->file, d.pos.line, d.pos.col, d.message);
}

}  // namespace

bool cs418_png_line(const std::string& text, int& width, int& height, std::string& name) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kw, w, h, extra;
    if (!(words >> kw)) continue;
    if (kw != "png" || !(words >> w >> h >> name) || (words >> extra)) return false;
    uint32_t wv = 0, hv = 0;
    const char* pw = w.c_str();
    const char* ph = h.c_str();
    if (!parse_decimal(pw, 0, limits::kMaxImageWidth, wv) || !parse_decimal(ph, 0, limits::kMaxImageHeight, hv) ||
        wv == 0 || hv == 0)
      return false;
    width = static_cast<int>(wv);
    height = static_cast<int>(hv);
    return true;
  }
  return false;
}

std::string cs418_output_name(const std::string& text) {
  int w = 0, h = 0;
  std::string name;
  return cs418_png_line(text, w, h, name) ? name : "";
}

int run_cs418_cli(GeneralCli& cli) {
  const bool from_stdin = cli.scene_path == "-";
  const std::string shown = from_stdin ? "<stdin>" : cli.scene_path;
  if (!read_scene_file(cli.scene_path, cli.scene_text, kMaxSceneBytes)) return kExitSceneError;
  std::string base_dir;
  if (!from_stdin) {
    const std::size_t slash = cli.scene_path.rfind('/');
    if (slash != std::string::npos) base_dir = cli.scene_path.substr(0, slash + 1);
  }

  // Where the image goes, checked before the render: -o, else the png line.
  std::string out_path = cli.output_path != nullptr ? cli.output_path : cs418_output_name(cli.scene_text);
  if (!out_path.empty()) {
    std::string why;
    if ((cli.output_path == nullptr && !cli.allow_any_output &&
         !scene_named_output_allowed(cli.scene_path, out_path, why)) ||
        !check_output_target(out_path, cli.write_through, why)) {
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitIoError;
    }
  }

  WarningContext wctx{shown.c_str()};
  WarningSink warnings;
  if (!cli.quiet) warnings = WarningSink{&print_warning, &wctx};
  GeneralResult result;
  std::string error, why;
  LiveWindow window;
  if (cli.show && !window.open("minrt: " + shown, why))
    std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  cli.options.window = &window;
  if (!render_cs418(cli.scene_text, shown, base_dir, cli.options, result, error, warnings)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitSceneError;
  }
  if (cli.stats)
    std::fprintf(stderr,
                 "minrt: %s: %dx%d, path %s, features 0x%03x; parse %.4f s, BVH %.4f s, render %.4f s on %d "
                 "thread%s\n",
                 shown.c_str(), result.image.width, result.image.height, result.path, result.features,
                 result.parse_seconds, result.build_seconds, result.render_seconds, result.threads,
                 result.threads == 1 ? "" : "s");
  if (out_path.empty()) out_path = result.output_name;

  AtomicOutput output(cli.durability);
  if (!output.open(out_path, cli.write_through, why)) {
    std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
    return kExitIoError;
  }
  if (!write_image_file(output.file(), out_path, result.image, why)) {
    output.discard();
    std::fprintf(stderr, "minrt: error: cannot write %s: %s\n", out_path.c_str(), why.c_str());
    return kExitIoError;
  }
  if (!output.commit(why)) {
    std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
    return kExitIoError;
  }
  if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return 0;
}

}  // namespace minrt::host
