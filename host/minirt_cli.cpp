#include "minirt_cli.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "file_input.hpp"
#include "image_file_output.hpp"
#include "image_window.hpp"
#include "minirt_render.hpp"
#include "posix/output_file.hpp"

namespace minrt::host {

namespace {

bool ends_with(const std::string& s, const char* tail) {
  const std::size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

}  // namespace

void print_minirt_error(const std::string& line) { std::fprintf(stderr, "Error\n%s\n", line.c_str()); }

bool has_rt_extension(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  return base.size() > 3 && ends_with(base, ".rt");
}

int run_minirt_cli(MinirtCli& cli) {
  const std::string& path = cli.scene_path;
  if (path == "-" || path.empty()) {
    print_minirt_error("minrt: a miniRT scene is read from a file whose name ends in .rt, not from standard input");
    return kMinirtExitError;
  }
  if (!has_rt_extension(path)) {
    print_minirt_error(path + ": a miniRT scene file's name must end in .rt");
    return kMinirtExitError;
  }
  std::string text, why;
  if (!read_whole_file(path, text, why, kMaxSceneBytes)) {
    print_minirt_error(path + ": cannot read the scene: " + why);
    return kMinirtExitError;
  }
  std::string base_dir;
  const std::size_t slash = path.rfind('/');
  if (slash != std::string::npos) base_dir = path.substr(0, slash + 1);

  // Where the image goes, checked before the render.
  const bool write = cli.output_path != nullptr;
  const std::string out_path = write ? cli.output_path : "";
  if (write) {
    if (!ends_with(out_path, ".png") && !ends_with(out_path, ".ppm") && out_path != "-") {
      print_minirt_error("minrt: the output " + out_path + " must end in .png or .ppm");
      return kMinirtExitError;
    }
    if (!check_output_target(out_path, cli.write_through, why)) {
      print_minirt_error("minrt: " + why);
      return kMinirtExitError;
    }
  }
  // Without -o the image can only go to a window: with no display at all,
  // say so before the render (and before SDL prints its own complaints).
  auto set = [](const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != 0;
  };
  if (!write && !set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("SDL_VIDEODRIVER")) {
    print_minirt_error("minrt: no display to show the image on (DISPLAY is not set); give -o FILE.png to write "
                       "the image instead");
    return kMinirtExitError;
  }
  const int width = cli.width > 0 ? cli.width : kMinirtDefaultWidth;
  const int height = cli.height > 0 ? cli.height : kMinirtDefaultHeight;
  // The window opens before the render and shows rows as they finish.
  LiveWindow window;
  if ((!write || cli.show) && !window.open("minrt: " + path, why)) {
    if (!write) {
      print_minirt_error("minrt: cannot open a window: " + why + " (give -o FILE.png to write the image instead)");
      return kMinirtExitError;
    }
    std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  }
  cli.options.window = &window;
  // To a window only: closing it (ESC, the close button) ends the program at
  // once, without finishing the render.
  if (!write) cli.options.cancel = window.closed_flag();
  GeneralResult result;
  std::string error;
  if (!render_minirt(text, path, base_dir, width, height, cli.reader, cli.options, result, error)) {
    print_minirt_error(error);
    return kMinirtExitError;
  }
  if (!write && window.closed()) {
    window.finish_and_wait(why);
    return 0;
  }
  if (cli.stats)
    std::fprintf(stderr, "minrt: %s: %dx%d, path %s, features 0x%03x; parse %.4f s, BVH %.4f s, render %.4f s on %d thread%s\n",
                 path.c_str(), width, height, result.path, result.features, result.parse_seconds, result.build_seconds,
                 result.render_seconds, result.threads, result.threads == 1 ? "" : "s");
  if (write) {
    AtomicOutput output(cli.durability);
    if (!output.open(out_path, cli.write_through, why)) {
      print_minirt_error("minrt: " + why);
      return kMinirtExitError;
    }
    if (!write_image_file(output.file(), out_path, result.image, why) || !output.commit(why)) {
      output.discard();
      print_minirt_error("minrt: cannot write " + out_path + ": " + why);
      return kMinirtExitError;
    }
  }
  if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return 0;
}

}  // namespace minrt::host
