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
#include "posix/output_file.hpp"
#include "variants.hpp"

namespace {

using namespace minrt_accuracy;

#ifndef MINRT_VERSION
#define MINRT_VERSION "0"
#endif

void print_help() {
  std::fputs(
      "Usage: accuracy-report [OPTIONS] SCENE.sld\n"
      "Renders one SLD scene in every math variant of the renderer, in-process, for\n"
      "the accuracy report (bench/accuracy/run.sh, docs/accuracy.md).\n"
      "\n"
      "  --size WxH        image size (default 128x128)\n"
      "  --out DIR         write each image as DIR/STEM.TAG.ppm (P6); DIR must exist\n"
      "  --variant NAME    render only this variant (name or tag; repeatable)\n"
      "  --stats           print, per variant, the differences from double/libm\n"
      "                    (which must then be among the variants)\n"
      "  -h, --help        this text\n"
      "  --version         version\n"
      "\n"
      "variants (name, tag):\n",
      stdout);
  for (const Variant& v : all_variants()) std::printf("  %-22s %s\n", v.name, v.tag);
  std::fputs("\nexit status: 0 ok, 1 a render or a write failed, 2 usage error or unreadable scene.\n", stdout);
}

int usage(const std::string& why) {
  std::fprintf(stderr, "accuracy-report: error: %s (see accuracy-report --help)\n", why.c_str());
  return 2;
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
  std::string out_dir, scene_path;
  std::vector<const Variant*> chosen;
  bool stats = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool takes_value = a == "--size" || a == "--out" || a == "--variant";
    if (takes_value && i + 1 >= argc) return usage(a + " needs a value");
    if (a == "--size") {
      const std::string v = argv[++i];
      char tail = 0;
      if (std::sscanf(v.c_str(), "%dx%d%c", &width, &height, &tail) != 2 || width < 1 || height < 1 ||
          width > 4096 || height > 4096)
        return usage("bad --size '" + v + "': expected WxH, each 1..4096");
    } else if (a == "--out") {
      out_dir = argv[++i];
    } else if (a == "--variant") {
      const Variant* v = find_variant(argv[++i]);
      if (v == nullptr) return usage(std::string("unknown variant '") + argv[i] + "'");
      chosen.push_back(v);
    } else if (a == "--stats") {
      stats = true;
    } else if (a == "-h" || a == "--help") {
      print_help();
      return 0;
    } else if (a == "--version") {
      std::printf("accuracy-report %s\n", MINRT_VERSION);
      return 0;
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option '" + a + "'");
    } else if (!scene_path.empty()) {
      return usage("more than one scene file given");
    } else {
      scene_path = a;
    }
  }
  if (scene_path.empty()) return usage("no scene file given");
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

  int status = 0;
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
