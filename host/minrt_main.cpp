// minrt: the host renderer for every scene format. For SLD a drop-in for the
// original min-rt (scene on stdin or a file, PPM on stdout or -o FILE); for
// the other formats like each one's own program (render_driver.hpp).
// Installed as `miniRT` too, it follows the 42 subject's contract: one .rt
// argument, every failure "Error" and a line, never standard input.
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <new>
#include <string>

#include "core/base/text_numbers.hpp"
#include "format_sides/minirt_host.hpp"
#include "posix/command_line.hpp"
#include "posix/interrupt.hpp"
#include "render_driver.hpp"

namespace {

using minrt::cli::Option;
using minrt::formats::ErrorStyle;

const std::vector<Option>& options_table() {
  static const std::vector<Option> table = {
      {"scene-format", 0, "NAME",
       "the scene's format: sld, cs418, jaworski, minirt or\n"
       "eastray (default: from the extension, then the first\n"
       "word: 'png' means CS418, a header field such as\n"
       "imWidth Jaworski, an element such as 'sp' miniRT)"},
      {"size", 0, "WxH", "image size (SLD default 512x512, miniRT 800x600; the\nother formats take it from the scene)"},
      {"format", 0, "p3|p6", "SLD: PPM flavour (default p3, the original's text\nform)"},
      {"precision", 0, "double|float", "floating-point type (default double)"},
      {"shims", 0, "NAME",
       "math routines: libm (default), portable,\n"
       "portable-fast or portable-min: the add/sub/mul/div-\n"
       "only shims of the firmware (float only); -fast is\n"
       "cheaper, -min just meets the course's error rules"},
      {"output", 'o', "FILE",
       "write the image to FILE (complete or not at all; a\n"
       "FIFO, device or symbolic link is refused; - is\n"
       "stdout); its extension picks the kind: .png, .ppm,\n"
       ".bmp, .tif, else the format's own"},
      {"write-through", 0, nullptr, "write into a FIFO, device or link given to -o"},
      {"allow-any-output", 0, nullptr,
       "let a scene's own output name (CS418's png line,\n"
       "EASTRAY's output) leave the scene's and the working\n"
       "folder"},
      {"sync", 0, nullptr, "make the -o file durable (fsync) before exiting;\nwithout it the file is still replaced whole or not\nat all"},
      {"quiet", 'q', nullptr, "no warnings and no progress line on standard error\n(a render over about 2 s draws one on a terminal)"},
      {"no-save", 'n', nullptr, "render without saving the image"},
      {"show", 's', nullptr,
       "show the image in a window as it is rendered; it\n"
       "stays until closed (ESC, q or the close button);\n"
       "without a display a one-line warning, and the file\n"
       "is still written"},
      {"threads", 0, "N", "render rows on N threads (default: every core; the\nimage is the same for any N)"},
      {"seed", 0, "N", "random numbers for aa, dof, roughness, gi (default 1)"},
      {"all-features", 0, nullptr, "render on the path with every feature compiled in\n(for measuring what the specialised paths save)"},
      {"full-tree", 0, nullptr,
       "trace every reflected, refracted and GI ray; by\n"
       "default rays that can change a pixel by less than\n"
       "1/65536 of the brightest radiance are skipped"},
      {"stats", 0, nullptr, "say which format and path rendered the scene and how\nlong the parse, the BVH and the render took"},
      {"mandatory", 0, nullptr,
       "miniRT: the subject's mandatory part only: A, C, L,\n"
       "sp, pl, cy, one L (colour optional, white), ambient\n"
       "and diffuse"},
      {"cylinder-base", 0, nullptr, "miniRT: a cylinder's point is its base centre, not\nits centre"},
      {"help", 'h', nullptr, "this text"},
      {"version", 0, nullptr, "version"},
  };
  return table;
}

void print_help(std::FILE* f, const std::string& program) {
  if (program == "miniRT")
    std::fputs("Usage: miniRT [OPTIONS] SCENE.rt\n"
               "minrt under the 42 subject's name: exactly one .rt scene, shown in a window\n"
               "(or written with -o FILE.png); every failure prints 'Error' and a line.\n\n",
               f);
  std::fputs(
      "Usage: minrt [OPTIONS] [SCENE]\n"
      "Renders a scene in any of five formats, recognised by its extension and\n"
      "its first word (docs/architecture.md):\n"
      "  .sld  min-rt SLD: the PPM goes to standard output (or -o), byte for byte\n"
      "        the original program's with --precision double --shims libm;\n"
      "        the scene comes from SCENE or standard input\n"
      "  .txt  CS418 ('png W H NAME.png' first): the PNG goes to NAME.png\n"
      "  .txt  Jaworski (imWidth, ..., lights, objects): the BMP goes to the\n"
      "        scene's name with .bmp\n"
      "  .rt   42 miniRT: shown in a window (ESC or the close button quit), or\n"
      "        written with -o FILE.png; errors print 'Error' and a line, status 1\n"
      "  .ray  EASTRAY (#include and #define expanded first): the image goes to the\n"
      "        scene's output name (.tif is TIFF, else PNG), else SCENE.png\n"
      "\n",
      f);
  minrt::cli::print_options(f, options_table());
  std::fputs(
      "\n"
      "Errors are printed as FILE:LINE:COL: error: MESSAGE; exit status 2 (1 when\n"
      "the image cannot be written). Ctrl-C ends minrt with status 130 and leaves no\n"
      "file behind.\n",
      f);
}

bool is_minirt_program(const char* argv0) {
  const char* slash = std::strrchr(argv0, '/');
  return std::strcmp(slash != nullptr ? slash + 1 : argv0, "miniRT") == 0;
}

}  // namespace

int run(int argc, char** argv) {
  namespace host = minrt::host;
  host::DriverOptions o;
  const bool minirt_program = is_minirt_program(argv[0]);
  // The subject wants every misconfiguration, the command line's too,
  // reported as "Error" and a line: as miniRT, or when an argument names a
  // .rt file.
  bool minirt_command = minirt_program;
  for (int i = 1; i < argc; ++i) minirt_command = minirt_command || host::has_rt_extension(argv[i]);
  const ErrorStyle style = minirt_command ? ErrorStyle::kMinirtError : ErrorStyle::kLocated;
  const std::string program = minirt_program ? "miniRT" : "minrt";
  auto usage_error = [&](const std::string& msg) {
    host::print_error(style, minirt_command ? program + ": " + msg + " (see " + program + " --help)"
                                             : "minrt: error: " + msg + " (see minrt --help)");
    return minirt_command ? host::kExitMinirtError : host::kExitSceneError;
  };

  std::vector<std::string> scenes;
  bool help = false, version = false, sync = false;
  std::string error;
  const bool parsed = minrt::cli::parse(
      argc, argv, options_table(),
      [&](const Option* opt, const std::string& v) -> std::string {
        if (opt == nullptr) {
          scenes.push_back(v);
          return "";
        }
        const std::string name = opt->name;
        if (name == "help") help = true;
        else if (name == "version") version = true;
        else if (name == "size") {
          if (!minrt::parse_size(v.c_str(), o.width, o.height)) return "bad --size '" + v + "': expected WxH, each 1..4096";
        } else if (name == "format") {
          if (v == "p3" || v == "P3") o.p6 = false;
          else if (v == "p6" || v == "P6") o.p6 = true;
          else return "bad --format '" + v + "': expected p3 or p6";
        } else if (name == "precision") {
          if (v == "double") o.variant.precision = host::Precision::kDouble;
          else if (v == "float") o.variant.precision = host::Precision::kFloat;
          else return "bad --precision '" + v + "': expected double or float";
        } else if (name == "shims") {
          if (v == "libm") o.variant.shims = host::ShimSet::kLibm;
          else if (v == "portable") o.variant.shims = host::ShimSet::kPortable;
          else if (v == "portable-fast") o.variant.shims = host::ShimSet::kPortableFast;
          else if (v == "portable-min") o.variant.shims = host::ShimSet::kPortableMin;
          else return "bad --shims '" + v + "': expected libm, portable, portable-fast or portable-min";
        } else if (name == "output") {
          // An empty name would mean "no -o" (standard output) further on.
          if (v.empty()) return "bad -o '': expected a file name, or - for standard output";
          o.output_path = v;
        }
        else if (name == "write-through") o.write_through = true;
        else if (name == "allow-any-output") o.allow_any_output = true;
        else if (name == "sync") sync = true;
        else if (name == "scene-format") {
          o.format = minrt::formats::format_named(v.c_str());
          if (o.format == nullptr) return "bad --scene-format '" + v + "': expected sld, cs418, jaworski, minirt or eastray";
        } else if (name == "threads") {
          const char* rest = v.c_str();
          uint32_t n = 0;
          if (!minrt::parse_decimal(rest, 0, 1024, n) || n == 0 || *rest != 0) return "bad --threads '" + v + "': expected 1..1024";
          o.threads = static_cast<int>(n);
        } else if (name == "seed") {
          const char* rest = v.c_str();
          uint32_t n = 0;
          if (!minrt::parse_decimal(rest, 0, 0xffffffffu, n) || *rest != 0) return "bad --seed '" + v + "': expected 0..4294967295";
          o.seed = n;
        } else if (name == "show") o.show = true;
        else if (name == "no-save") o.save = false;
        else if (name == "all-features") o.force_full = true;
        else if (name == "full-tree") o.full_tree = true;
        else if (name == "stats") o.stats = true;
        else if (name == "quiet") o.quiet = true;
        else if (name == "mandatory") o.mandatory = true;
        else if (name == "cylinder-base") o.cylinder_base = true;
        if (name == "mandatory" || name == "cylinder-base") o.format_options.push_back(name);
        return "";
      },
      error);
  if (!parsed) return usage_error(error);
  if (help) {
    print_help(stdout, program);
    return 0;
  }
  if (version) {
    std::printf("%s %s\n", program.c_str(), MINRT_VERSION);
    return 0;
  }
  if (minirt_program) {
    // The subject: exactly one argument, a .rt file.
    if (scenes.size() != 1) {
      host::print_error(ErrorStyle::kMinirtError,
                        scenes.empty() ? "miniRT: no scene given (usage: miniRT SCENE.rt)"
                                       : "miniRT: expected one scene file, got " + std::to_string(scenes.size()) +
                                             " (usage: miniRT SCENE.rt)");
      return host::kExitMinirtError;
    }
    o.format = &minrt::formats::format_of(minrt::formats::FormatId::kMinirt);
  }
  if (scenes.size() > 1) {
    if (minirt_command) {
      host::print_error(ErrorStyle::kMinirtError, "minrt: expected one scene file, got '" + scenes[0] + "' and '" +
                                                      scenes[1] + "' (usage: minrt SCENE.rt)");
      return host::kExitMinirtError;
    }
    return usage_error("more than one scene file given");
  }
  if (!scenes.empty()) o.scene_path = scenes[0];
  if (host::variant_name(o.variant) == nullptr)
    return usage_error("this combination of --precision and --shims is not built (portable shims are float only)");
  o.progress = !o.quiet && ::isatty(STDERR_FILENO) != 0;
  // An image is cheap to render again, and syncing took a tenth of a small
  // render's run: atomic replacement by default, durability on request.
  o.durability = sync ? host::Durability::kSynced : host::Durability::kRenameOnly;
  return host::run_driver(o);
}

int main(int argc, char** argv) {
  // Memory is taken from the scene's content (host/format_sides/scene_memory.hpp);
  // what the system still refuses ends the run with a line, never an abort.
  // Ctrl-C and the other ending signals leave no temporary file behind and
  // end minrt with the signal's status (130 for Ctrl-C): posix/interrupt.hpp.
  minrt::host::install_signal_cleanup();
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "minrt: error: out of memory\n");
    return 2;
  }
}
