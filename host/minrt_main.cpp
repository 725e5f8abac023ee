// minrt: the host renderer. For SLD a drop-in for the original min-rt (scene
// on stdin or a file, PPM on stdout or -o FILE); for CS418 scenes like the
// course's program (writes the PNG named in the scene, or -o FILE).
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <unistd.h>

#include "core/base/text_numbers.hpp"
#include "file_input.hpp"
#include "general_cli.hpp"
#include "image_stream_decoder.hpp"
#include "image_window.hpp"
#include "jaworski_cli.hpp"
#include "minirt_cli.hpp"
#include "posix/output_file.hpp"
#include "eastray_cli.hpp"
#include "scene_format.hpp"
#include "render_variants.hpp"
#include "stdio_stream.hpp"

namespace {

constexpr int kExitUsage = 2;
constexpr int kExitSceneError = 2;
constexpr int kExitIoError = 1;

void print_help(std::FILE* f) {
  std::fputs(
      "Usage: minrt [OPTIONS] [SCENE.sld | SCENE.txt]\n"
      "Renders an SLD scene like the original min-rt: the scene comes from SCENE.sld\n"
      "(or standard input), the PPM image goes to standard output.\n"
      "Renders a CS418 scene (a .txt file whose first line is 'png W H NAME.png')\n"
      "like the course's program: the PNG goes to NAME.png, or to -o FILE.\n"
      "\n"
      "Renders a Jaworski scene (keywords imWidth, ..., lights, objects) like the\n"
      "original program: the BMP goes to the scene's name with .bmp, or to -o FILE.\n"
      "\n"
      "Renders a 42 miniRT scene (SCENE.rt) in a window, as the subject asks (ESC or\n"
      "the close button quit), or with -o FILE.png|FILE.ppm into a file (default size\n"
      "800x600; --size, --threads, --precision and --shims apply). Errors print\n"
      "'Error' and one line naming what and where; exit status 1.\n"
      "\n"
      "Renders an EASTRAY scene (.ray; #include and #define expanded first): the\n"
      "image goes to -o FILE, else the scene's output name (.tif is TIFF, else PNG),\n"
      "else the scene's name with .png (docs/eastray.md).\n"
      "\n"
      "  --scene-format sld|cs418|jaworski|minirt|eastray  the scene's format (default: from the\n"
      "                           extension, then the first word: 'png' means CS418,\n"
      "                           a header field such as imWidth means Jaworski)\n"
      "  --size WxH               image size (default 512x512, at most 4096x4096)\n"
      "  --format p3|p6           PPM flavour (default p3, the original's text form)\n"
      "  --precision double|float floating-point type (default double)\n"
      "  --shims libm|portable|portable-fast|portable-min\n"
      "                           math routines: the C library (default) or the\n"
      "                           add/sub/mul/div-only shims of the firmware (float only);\n"
      "                           -fast is cheaper, -min just meets the course's error rules\n"
      "  -o, --output FILE        write the image to FILE (complete or not at all; a\n"
      "                           FIFO, device or symbolic link is refused; - is stdout)\n"
      "  --write-through          write into a FIFO, device or link given to -o\n"
      "  --allow-any-output       let a scene's own output name (CS418 png line, EASTRAY\n"
      "                           output) leave the scene's and the working folder\n"
      "  --sync                   make the -o file durable (fsync) before exiting; without\n"
      "                           it the file is still replaced whole or not at all\n"
      "  -q, --quiet              no warnings on standard error\n"
      "  -n, --no-save            Jaworski, EASTRAY: render without saving the image\n"
      "  -s, --show               show the image in a window as it is rendered; it stays\n"
      "                           until closed (ESC, q or the close button; closing it\n"
      "                           early does not stop the render); without a display a\n"
      "                           one-line warning, and the file is still written\n"
      "  --threads N              render rows on N threads (default: every core;\n"
      "                           the image is the same for any N)\n"
      "CS418 (--all-features and --stats also for miniRT):\n"
      "  --seed N                 random numbers for aa, dof, roughness, gi (default 1)\n"
      "  --all-features           render on the path with every feature compiled in\n"
      "                           (for measuring what the specialised paths save)\n"
      "  --full-tree              trace every reflected, refracted and GI ray; by\n"
      "                           default rays that can change a pixel by less than\n"
      "                           1/65536 of the brightest radiance are skipped\n"
      "  --stats                  say which path rendered the scene and how long the\n"
      "                           parse, the BVH and the render took\n"
      "  -h, --help               this text\n"
      "  --version                version\n"
      "\n"
      "double with libm reproduces the original program's output byte for byte.\n"
      "Errors are printed as FILE:LINE:COL: error: MESSAGE; exit status 2.\n",
      f);
}

// Set when an argument names a .rt file: the miniRT subject wants every
// misconfiguration, the command line's too, reported as "Error" + a line.
bool g_minirt_command = false;

[[noreturn]] void usage_error(const std::string& msg) {
  if (g_minirt_command) {
    minrt::host::print_minirt_error("minrt: " + msg + " (see minrt --help)");
    std::exit(minrt::host::kMinirtExitError);
  }
  std::fprintf(stderr, "minrt: error: %s (see minrt --help)\n", msg.c_str());
  std::exit(kExitUsage);
}

struct WarningContext {
  const char* file;
};

void print_warning(void* ctx, const minrt::Diagnostic& d) {
  const auto* w = static_cast<const WarningContext*>(ctx);
  std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w->file, d.pos.line, d.pos.col, d.message);
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) g_minirt_command = g_minirt_command || minrt::host::has_rt_extension(argv[i]);
  minrt::RenderOptions options;
  minrt::host::Variant variant;
  const char* scene_path = nullptr;
  const char* output_path = nullptr;
  bool quiet = false;
  bool write_through = false;
  bool allow_any_output = false;
  bool sync = false;
  minrt::host::SceneFormat scene_format = minrt::host::SceneFormat::kAuto;
  minrt::host::GeneralCli general;
  bool no_save = false;
  bool show = false;
  bool size_given = false;
  const char* second_scene = nullptr;

  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* name) -> const char* {
      if (i + 1 >= argc) usage_error(std::string(name) + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help") {
      print_help(stdout);
      return 0;
    } else if (arg == "--version") {
      std::printf("minrt %s\n", MINRT_VERSION);
      return 0;
    } else if (arg == "--size") {
      const char* v = value("--size");
      if (!minrt::parse_size(v, options.width, options.height))
        usage_error(std::string("bad --size '") + v + "': expected WxH, each 1..4096");
      size_given = true;
    } else if (arg == "--format") {
      const std::string v = value("--format");
      if (v == "p3" || v == "P3") options.format = minrt::PpmFormat::kP3;
      else if (v == "p6" || v == "P6") options.format = minrt::PpmFormat::kP6;
      else usage_error("bad --format '" + v + "': expected p3 or p6");
    } else if (arg == "--precision") {
      const std::string v = value("--precision");
      if (v == "double") variant.precision = minrt::host::Precision::kDouble;
      else if (v == "float") variant.precision = minrt::host::Precision::kFloat;
      else usage_error("bad --precision '" + v + "': expected double or float");
    } else if (arg == "--shims") {
      const std::string v = value("--shims");
      if (v == "libm") variant.shims = minrt::host::ShimSet::kLibm;
      else if (v == "portable") variant.shims = minrt::host::ShimSet::kPortable;
      else if (v == "portable-fast") variant.shims = minrt::host::ShimSet::kPortableFast;
      else if (v == "portable-min") variant.shims = minrt::host::ShimSet::kPortableMin;
      else usage_error("bad --shims '" + v + "': expected libm, portable, portable-fast or portable-min");
    } else if (arg == "-o" || arg == "--output") {
      output_path = value("--output");
    } else if (arg == "--write-through") {
      write_through = true;
    } else if (arg == "--allow-any-output") {
      allow_any_output = true;
    } else if (arg == "--sync") {
      sync = true;
    } else if (arg == "--scene-format") {
      const std::string v = value("--scene-format");
      if (!minrt::host::parse_scene_format(v, scene_format))
        usage_error("bad --scene-format '" + v + "': expected sld, cs418, jaworski, minirt or eastray");
    } else if (arg == "--threads") {
      const char* v = value("--threads");
      const char* rest = v;  // parse_decimal moves it
      uint32_t n = 0;
      if (!minrt::parse_decimal(rest, 0, 1024, n) || n == 0)
        usage_error(std::string("bad --threads '") + v + "': expected 1..1024");
      general.options.threads = static_cast<int>(n);
    } else if (arg == "--seed") {
      const char* v = value("--seed");
      const char* rest = v;
      uint32_t n = 0;
      if (!minrt::parse_decimal(rest, 0, 0xffffffffu, n))
        usage_error(std::string("bad --seed '") + v + "': expected 0..4294967295");
      general.options.seed = n;
    } else if (arg == "-s" || arg == "--show") {
      show = true;
    } else if (arg == "-n" || arg == "--no-save") {
      no_save = true;
    } else if (arg == "--all-features") {
      general.options.force_full = true;
    } else if (arg == "--full-tree") {
      general.options.full_tree = true;
    } else if (arg == "--stats") {
      general.stats = true;
    } else if (arg == "-q" || arg == "--quiet") {
      quiet = true;
    } else if (arg == "-") {
      scene_path = nullptr;
    } else if (!arg.empty() && arg[0] == '-') {
      usage_error("unknown option '" + arg + "'");
    } else if (scene_path != nullptr) {
      second_scene = argv[i];
      // miniRT's subject wants its own error form for a wrong argument count.
      if (!minrt::host::has_rt_extension(scene_path) && !minrt::host::has_rt_extension(second_scene))
        usage_error("more than one scene file given");
    } else {
      scene_path = argv[i];
    }
  }
  if (second_scene != nullptr) {
    minrt::host::print_minirt_error(std::string("minrt: expected one scene file, got '") + scene_path + "' and '" +
                                    second_scene + "' (usage: minrt SCENE.rt)");
    return minrt::host::kMinirtExitError;
  }
  if (minrt::host::variant_name(variant) == nullptr)
    usage_error("this combination of --precision and --shims is not built (portable shims are float only)");
  // An image is cheap to render again, and syncing took a tenth of a small
  // render's run: atomic replacement by default, durability on request.
  const minrt::host::Durability durability =
      sync ? minrt::host::Durability::kSynced : minrt::host::Durability::kRenameOnly;

  // Which reader: the option, else the extension and the first word. Standard
  // input is read whole first so that it can be looked at.
  std::string stdin_text;
  std::FILE* stdin_copy = nullptr;
  if (scene_format != minrt::host::SceneFormat::kSld) {
    std::string head;
    if (scene_path == nullptr) {
      // Bounded like a scene file (file_input.hpp), before anything is written.
      std::string why;
      if (!minrt::host::read_whole_fd(STDIN_FILENO, stdin_text, why, minrt::host::kMaxSceneBytes)) {
        std::fprintf(stderr, "minrt: error: cannot read <stdin>: %s\n", why.c_str());
        return kExitUsage;
      }
      head = stdin_text.substr(0, 4096);
    } else if (std::FILE* f = std::fopen(scene_path, "rb")) {
      char buf[4096];
      head.assign(buf, std::fread(buf, 1, sizeof buf, f));
      std::fclose(f);
    }
    if (scene_format == minrt::host::SceneFormat::kAuto)
      scene_format = minrt::host::detect_scene_format(scene_path != nullptr ? scene_path : "", head);
    if (scene_format == minrt::host::SceneFormat::kSld && scene_path == nullptr) {
      // The SLD reader streams from a FILE: give it the bytes already read.
      stdin_copy = stdin_text.empty() ? std::fopen("/dev/null", "rb")
                                      : fmemopen(stdin_text.data(), stdin_text.size(), "rb");
    }
  }
  if (scene_format == minrt::host::SceneFormat::kJaworski) {
    minrt::host::JaworskiCli j;
    j.scene_path = scene_path != nullptr ? scene_path : "-";
    j.scene_text = std::move(stdin_text);
    j.output_path = output_path;
    j.save = !no_save;
    j.write_through = write_through;
    j.durability = durability;
    j.variant = variant;
    j.show = show;
    j.threads = general.options.threads;
    return minrt::host::run_jaworski_cli(j);
  }
  if (scene_format == minrt::host::SceneFormat::kMinirt) {
    minrt::host::MinirtCli m;
    m.scene_path = scene_path != nullptr ? scene_path : "-";
    m.output_path = output_path;
    m.show = show;
    m.write_through = write_through;
    m.durability = durability;
    m.stats = general.stats;
    if (size_given) {
      m.width = options.width;
      m.height = options.height;
    }
    m.options = general.options;
    m.options.variant = variant;
    return minrt::host::run_minirt_cli(m);
  }
  if (scene_format == minrt::host::SceneFormat::kEastray) {
    minrt::host::EastrayCli e;
    e.scene_path = scene_path != nullptr ? scene_path : "-";
    e.scene_text = std::move(stdin_text);
    e.output_path = output_path;
    e.save = !no_save;
    e.quiet = quiet;
    e.write_through = write_through;
    e.allow_any_output = allow_any_output;
    e.durability = durability;
    e.variant = variant;
    e.show = show;
    return minrt::host::run_eastray_cli(e);
  }
  if (scene_format == minrt::host::SceneFormat::kCs418) {
    general.scene_path = scene_path != nullptr ? scene_path : "-";
    general.scene_text = std::move(stdin_text);
    general.output_path = output_path;
    general.write_through = write_through;
    general.allow_any_output = allow_any_output;
    general.durability = durability;
    general.quiet = quiet;
    general.options.variant = variant;
    general.show = show;
    return minrt::host::run_cs418_cli(general);
  }

  std::FILE* in = stdin_copy != nullptr ? stdin_copy : stdin;
  const char* display_name = scene_path != nullptr ? scene_path : "<stdin>";
  if (scene_path != nullptr) {
    in = std::fopen(scene_path, "rb");
    struct stat st {};
    if (in != nullptr && ::fstat(fileno(in), &st) == 0 && S_ISDIR(st.st_mode)) {
      std::fclose(in);
      in = nullptr;
      errno = EISDIR;
    }
    if (in == nullptr) {
      std::fprintf(stderr, "minrt: error: cannot read %s: %s\n", scene_path, std::strerror(errno));
      return kExitUsage;
    }
  }

  // With -o the image goes to a unique temporary file renamed into place
  // only once it is complete (output_file.hpp).
  minrt::host::AtomicOutput output(durability);
  std::FILE* out = stdout;
  if (output_path != nullptr) {
    std::string why;
    if (!output.open(output_path, write_through, why)) {
      if (in != stdin) std::fclose(in);
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitUsage;
    }
    out = output.file();
  }

  minrt::host::FileSource source{in};
  minrt::host::FileSink file_sink{out};
  // --show: the PPM bytes also go through a decoder that hands each row to
  // the window as soon as it is written.
  minrt::host::LiveWindow window;
  if (show) {
    std::string why;
    if (!window.open(std::string("minrt: ") + display_name, why))
      std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  }
  minrt::host::ImageStreamDecoder decoder(window);
  struct Tee {
    minrt::ByteSink file;
    minrt::host::ImageStreamDecoder* decoder;
    static void write_fn(void* ctx, const uint8_t* data, size_t size) {
      auto* t = static_cast<Tee*>(ctx);
      t->file.put(data, size);
      t->decoder->feed(data, size);
    }
  } tee{file_sink.sink(), &decoder};
  const minrt::ByteSink sink = window.is_open() ? minrt::ByteSink{&Tee::write_fn, &tee} : file_sink.sink();
  // Several threads hand the PPM writer each row once the rows above it are
  // done: the window takes them as they finish instead (a row given twice
  // keeps its first).
  struct WindowRows {
    minrt::host::LiveWindow* window;
    void begin(int, int) {}
    void row(int y, const uint8_t* rgb) { window->row_rgb(y, rgb); }
    void end() {}
  } window_rows{&window};
  window.begin(options.width, options.height);  // the size is --size's
  const minrt::RowSink to_window = minrt::row_sink_of(window_rows);
  WarningContext wctx{display_name};
  minrt::WarningSink warnings;
  if (!quiet) warnings = minrt::WarningSink{&print_warning, &wctx};
  minrt::Diagnostic error;
  const minrt::RenderStatus st =
      minrt::host::render_variant(variant, source.source(), sink, options, error, warnings,
                                  general.options.threads, window.is_open() ? &to_window : nullptr);
  const bool read_failed = std::ferror(in) != 0;
  if (in != stdin) std::fclose(in);
  const bool write_failed = file_sink.failed || std::fflush(out) != 0;

  auto discard = [&] { output.discard(); };
  if (source.read_errno != 0) {
    discard();
    std::fprintf(stderr, "minrt: error: cannot read %s: %s\n", display_name, std::strerror(source.read_errno));
    return kExitUsage;
  }
  if (st != minrt::RenderStatus::kOk) {
    discard();
    if (error.has_pos)
      std::fprintf(stderr, "%s:%d:%d: error: %s\n", display_name, error.pos.line, error.pos.col,
                   error.message);
    else
      std::fprintf(stderr, "%s: error: %s\n", display_name, error.message);
    return st == minrt::RenderStatus::kSceneError ? kExitSceneError : kExitIoError;
  }
  if (read_failed || write_failed) {
    discard();
    std::fprintf(stderr, "minrt: error: %s\n", read_failed ? "read error on the scene" : "write error on the image");
    return kExitIoError;
  }
  if (output_path != nullptr) {
    std::string why;
    if (!output.commit(why)) {
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitIoError;
    }
  }
  std::string why;
  if (window.is_open() && !window.finish_and_wait(why))
    std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return 0;
}
