#include "render_driver.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "file_input.hpp"
#include "format_sides/host_formats.hpp"
#include "image_file_output.hpp"
#include "image_window.hpp"
#include "row_file_writer.hpp"
#include "row_pool.hpp"

namespace minrt::host {

namespace {

struct WarningContext {
  const char* file;
};

void print_warning(void* ctx, const Diagnostic& d) {
  const auto* w = static_cast<const WarningContext*>(ctx);
  std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w->file, d.pos.line, d.pos.col, d.message);
}

int scene_status(formats::ErrorStyle style) {
  return style == formats::ErrorStyle::kMinirtError ? kExitMinirtError : kExitSceneError;
}
int io_status(formats::ErrorStyle style) {
  return style == formats::ErrorStyle::kMinirtError ? kExitMinirtError : kExitIoError;
}

bool display_available() {
  auto set = [](const char* name) {
    const char* v = std::getenv(name);
    return v != nullptr && *v != 0;
  };
  return set("DISPLAY") || set("WAYLAND_DISPLAY") || set("SDL_VIDEODRIVER");
}

}  // namespace

void print_error(formats::ErrorStyle style, const std::string& line) {
  if (style == formats::ErrorStyle::kMinirtError) std::fprintf(stderr, "Error\n");
  std::fprintf(stderr, "%s\n", line.c_str());
}

bool render_in_memory(const formats::Format& format, const SceneInput& in, const DriverOptions& options,
                      RenderedScene& out, std::string& error, const WarningSink& warnings) {
  const HostFormat& host = host_format(format.id);
  if (host.prepare == nullptr) {
    error = std::string(format.name) + " scenes are streamed, not rendered in memory";
    return false;
  }
  std::unique_ptr<PreparedScene> scene = host.prepare(in, options, warnings, error);
  if (!scene) {
    if (error.empty()) error = "this combination of --precision and --shims is not built";
    return false;
  }
  out.threads = render_rows(*scene, options.threads, out.image, nullptr);
  out.output_name = scene->output_name;
  out.path = scene->path;
  out.features = scene->features;
  return true;
}

int run_driver(const DriverOptions& options) {
  SceneInput in;
  in.path = options.scene_path;
  const bool from_stdin = in.path == "-";
  in.shown = from_stdin ? "<stdin>" : in.path;
  if (!from_stdin) {
    const std::size_t slash = in.path.rfind('/');
    if (slash != std::string::npos) in.base_dir = in.path.substr(0, slash + 1);
  }
  std::string why;
  const bool read_ok = from_stdin ? read_whole_fd(STDIN_FILENO, in.text, why, kMaxSceneBytes)
                                  : read_whole_file(in.path, in.text, why, kMaxSceneBytes);
  // Recognised once, from the name and the text's start; of a file that
  // cannot be read the name alone decides the error style (no text: {}).
  const auto* bytes = reinterpret_cast<const uint8_t*>(in.text.data());
  const formats::TextStart start = read_ok ? formats::text_start(bytes, in.text.size()) : formats::TextStart{};
  const formats::Format& format =
      options.format != nullptr ? *options.format : formats::detect_format(from_stdin ? nullptr : in.path.c_str(), start);
  if (!read_ok) {
    print_error(format.errors, (format.errors == formats::ErrorStyle::kMinirtError ? in.shown + ": cannot read the scene: "
                                                                                    : "minrt: error: cannot read " + in.shown + ": ") +
                                   why);
    return scene_status(format.errors);
  }
  in.text.erase(0, formats::bom_bytes(bytes, in.text.size()));
  for (const std::string& name : options.format_options)
    if (!formats::takes_option(format, name.c_str())) {
      std::string owners;
      for (const formats::Format& f : formats::kFormats)
        if (formats::takes_option(f, name.c_str())) owners += (owners.empty() ? "" : ", ") + std::string(f.title);
      print_error(format.errors, "minrt: error: --" + name + " applies to " + owners + " scenes only, not " +
                                     format.title + " (see minrt --help)");
      return scene_status(format.errors);
    }
  WarningContext wctx{in.shown.c_str()};
  WarningSink warnings;
  if (!options.quiet) warnings = WarningSink{&print_warning, &wctx};
  const HostFormat& host = host_format(format.id);
  if (host.stream != nullptr) return host.stream(in, options, warnings);

  const formats::ErrorStyle style = format.errors;
  std::string error;
  start_row_threads(options.threads);  // running by the time the scene is ready
  std::unique_ptr<PreparedScene> scene = host.prepare(in, options, warnings, error);
  if (!scene) {
    print_error(style, error.empty() ? "minrt: error: this combination of --precision and --shims is not built" : error);
    return scene_status(style);
  }

  // Where the image goes, checked before the render: -o, else the scene's
  // name for it; a format that names none (miniRT) shows a window.
  std::string out_path;
  if (options.save) out_path = !options.output_path.empty() ? options.output_path : scene->output_name;
  const bool window_only = options.save && out_path.empty();
  if (!options.output_path.empty() && has_foreign_extension(options.output_path)) {
    print_error(style, "minrt: error: the output " + options.output_path + " must end in " + kImageExtensions);
    return io_status(style);
  }
  // A name the scene gives (CS418's png line, EASTRAY's output) stays in the
  // scene's or the working folder unless allowed; -o is the user's own.
  const bool named_by_scene = options.output_path.empty() && !out_path.empty() && out_path != "-";
  if (named_by_scene && !options.allow_any_output && !scene_named_output_allowed(in.path, out_path, why)) {
    print_error(style, "minrt: error: " + why);
    return io_status(style);
  }
  if (!out_path.empty() && !check_output_target(out_path, options.write_through, why)) {
    print_error(style, "minrt: error: " + why);
    return io_status(style);
  }
  if (window_only && !display_available()) {
    print_error(style, "minrt: no display to show the image on (DISPLAY is not set); give -o FILE.png to write the "
                       "image instead");
    return io_status(style);
  }
  LiveWindow window;
  if ((options.show || window_only) && !window.open("minrt: " + in.shown, why)) {
    if (window_only) {
      print_error(style, "minrt: cannot open a window: " + why + " (give -o FILE.png to write the image instead)");
      return io_status(style);
    }
    std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  }

  // Not between the image's bytes on a terminal (-o -).
  const bool progress_shown = options.progress && !(out_path == "-" && ::isatty(STDOUT_FILENO) != 0);
  WorkProgress progress(progress_shown, "minrt: rendering", "rows",
                        static_cast<std::uint64_t>(scene->height) * scene->views, kProgressAfterSeconds);
  for (int view = 0; view < scene->views; ++view) {
    scene->select_view(view);
    const std::string target = out_path.empty() ? std::string() : scene->view_output_name(out_path, view);
    const ImageFile kind = image_file_for(target, format.reply);
    // Rows final as rendered go to a BMP or PPM file as they are done.
    AtomicOutput output(options.durability);
    RowFileWriter rows_to_file;
    if (scene->rows_final && !target.empty()) {
      if (!output.open(target, options.write_through, why)) {
        print_error(style, "minrt: error: " + why);
        return io_status(style);
      }
      rows_to_file.start(output.file(), kind, scene->width, scene->height);
    }
    RgbaImage image;
    const auto t0 = std::chrono::steady_clock::now();
    // To a window only: closing it (ESC, the close button) ends the program
    // at once, without finishing the render. The window shows the first view.
    LiveWindow* shown = view == 0 ? &window : nullptr;
    const int threads =
        render_rows(*scene, options.threads, image, shown, window_only ? window.closed_flag() : nullptr,
                    rows_to_file.started() ? &rows_to_file : nullptr, &progress);
    // Off the terminal before --stats and the writer's messages; a second
    // view's rows draw the line again from where the first left it.
    progress.finish();
    const double render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (window_only && window.closed()) {
      window.finish_and_wait(why);
      return kExitOk;
    }
    if (options.stats)
      std::fprintf(stderr,
                   "minrt: %s: %s %dx%d, path %s, features 0x%03x; parse %.4f s, BVH %.4f s, render %.4f s on %d "
                   "thread%s\n",
                   in.shown.c_str(), format.name, scene->width, scene->height, scene->path, scene->features,
                   scene->parse_seconds, scene->build_seconds, render_seconds, threads, threads == 1 ? "" : "s");
    if (target.empty()) continue;
    if (!rows_to_file.started()) {
      const std::string warning = scene->finish_image(target, kind, image);
      if (!warning.empty() && !options.quiet) std::fprintf(stderr, "minrt: warning: %s\n", warning.c_str());
      if (output.file() == nullptr && !output.open(target, options.write_through, why)) {
        print_error(style, "minrt: error: " + why);
        return io_status(style);
      }
    }
    const bool written =
        rows_to_file.started() ? rows_to_file.finish(why) : write_image(output.file(), kind, image, why);
    if (!written || !output.commit(why)) {
      output.discard();
      // commit's reason already names the file; the writers' do not.
      print_error(style, "minrt: error: " + (written ? why : "cannot write " + target + ": " + (why.empty() ? "write error" : why)));
      return io_status(style);
    }
  }
  if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return kExitOk;
}

}  // namespace minrt::host
