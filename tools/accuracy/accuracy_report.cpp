// accuracy-report: renders one SLD scene in every math variant in-process and
// writes the images as P6, for bench/accuracy/make_report.py.
//
//   accuracy-report [--size WxH] [--out DIR] [--variant NAME]... [--stats] SCENE.sld
//   (see --help)
//
// Images go to DIR/STEM.TAG.ppm (TAG: double-libm, float-libm, float-portable,
// float-portable-fast, float-portable-fma). --variant restricts the run to the
// named variants (name or tag; repeatable), e.g. to count the instructions of
// one variant under callgrind. --stats prints, per variant, the differences
// from double/libm (which must then be among the variants).
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "image_diff.hpp"
#include "posix/command_line.hpp"
#include "posix/output_file.hpp"
#include "variants.hpp"

namespace {

using namespace minrt_accuracy;

const minrt::cli::Tool& tool() {
  static const minrt::cli::Tool t = [] {
    std::string variants = "\nvariants (name, tag):\n";
    for (const Variant& v : all_variants()) {
      char line[128];
      std::snprintf(line, sizeof line, "  %-22s %s\n", v.name, v.tag);
      variants += line;
    }
    return minrt::cli::Tool{
        "accuracy-report",
        R"(Usage: accuracy-report [OPTIONS] SCENE.sld
Renders one SLD scene in every math variant of the renderer, in-process, for
the accuracy report (bench/accuracy/run.sh, docs/accuracy.md).

)",
        {
            {"size", 0, "WxH", "image size (default 128x128)"},
            {"out", 0, "DIR", "write each image as DIR/STEM.TAG.ppm (P6); DIR must exist"},
            {"variant", 0, "NAME", "render only this variant (name or tag; may be given again)"},
            {"stats", 0, nullptr, "print, per variant, the differences from double/libm\n(which must then be among the variants)"},
        },
        variants + "\nexit status: 0 ok, 1 a render or a write failed, 2 usage error or unreadable scene.\n",
        1,
        1,
        "scene file"};
  }();
  return t;
}

// The output folder is checked once, before any render, with the reason.
bool check_out_dir(const std::string& dir, std::string& why) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) {
    why = "cannot write to " + dir + ": " + std::strerror(errno);
    return false;
  }
  if (!S_ISDIR(st.st_mode)) {
    why = "cannot write to " + dir + ": " + std::strerror(ENOTDIR);
    return false;
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    why = "cannot write to " + dir + ": " + std::strerror(errno);
    return false;
  }
  return true;
}

std::string stem_of(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const size_t dot = base.rfind('.');
  return dot == std::string::npos ? base : base.substr(0, dot);
}

}  // namespace

int main(int argc, char** argv) {
  int width = 128, height = 128;
  std::string out_dir;
  std::vector<std::string> scenes;
  std::vector<const Variant*> chosen;
  bool stats = false;
  int status = 0;
  const bool go_on = minrt::cli::parse_tool(
      argc, argv, tool(), MINRT_VERSION,
      [&](const minrt::cli::Option* o, const std::string& v) -> std::string {
        const std::string name = o->name;
        if (name == "stats") stats = true;
        else if (name == "out") out_dir = v;
        else if (name == "size") {
          char tail = 0;
          if (std::sscanf(v.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 1 || height < 1 ||
              width > 4096 || height > 4096)
            return "bad --size '" + v + "': expected WxH, each 1..4096";
        } else if (name == "variant") {
          const Variant* chosen_one = find_variant(v);
          if (chosen_one == nullptr) return "unknown variant '" + v + "'";
          chosen.push_back(chosen_one);
        }
        return "";
      },
      status, &scenes);
  if (!go_on) return status;
  const std::string scene_path = scenes[0];
  if (chosen.empty())
    for (const Variant& v : all_variants()) chosen.push_back(&v);
  std::string why;
  if (!out_dir.empty() && !check_out_dir(out_dir, why)) {
    std::fprintf(stderr, "accuracy-report: error: %s\n", why.c_str());
    return 2;
  }

  std::ifstream in(scene_path, std::ios::binary);
  struct stat scene_st {};
  if (!in || (::stat(scene_path.c_str(), &scene_st) == 0 && S_ISDIR(scene_st.st_mode))) {
    const int e = !in ? errno : EISDIR;
    std::fprintf(stderr, "accuracy-report: error: cannot read %s: %s\n", scene_path.c_str(), std::strerror(e));
    return 2;
  }
  std::ostringstream text;
  text << in.rdbuf();
  const std::string sld = text.str();

  status = 0;
  std::string reference;
  for (const Variant* v : chosen) {
    const Rendered r = v->render(sld, width, height);
    for (const std::string& w : r.warnings)
      std::fprintf(stderr, "%s: %s: warning: %s\n", scene_path.c_str(), v->name, w.c_str());
    if (!r.ok) {
      std::fprintf(stderr, "%s: %s: error: %s\n", scene_path.c_str(), v->name, r.error.c_str());
      status = 1;
      continue;
    }
    if (!out_dir.empty()) {
      // Whole or not at all, never onto a FIFO, device or link (posix/output_file.hpp).
      const std::string path = out_dir + "/" + stem_of(scene_path) + "." + v->tag + ".ppm";
      std::string why;
      if (!minrt::host::write_file_atomically(path, r.image, false, minrt::host::Durability::kSynced, why)) {
        std::fprintf(stderr, "accuracy-report: error: %s\n", why.c_str());
        status = 1;  // the other variants' images are still written
      }
    }
    if (!stats) continue;
    if (std::strcmp(v->name, "double/libm") == 0) reference = r.image;
    if (reference.empty()) {
      std::fprintf(stderr, "accuracy-report: error: --stats needs double/libm first\n");
      return 2;
    }
    const ImageDiff d = diff_p6(reference, r.image);
    std::printf("%s\t%s\tmax=%d\tdiffering=%d\tover8=%d\tpixels=%d%s\n", stem_of(scene_path).c_str(),
                v->name, d.max_error, d.differing, d.over8, d.pixels, d.valid ? "" : "\tINVALID");
  }
  return status;
}
