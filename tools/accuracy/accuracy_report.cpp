// accuracy-report: renders one SLD scene in every math variant in-process and
// writes the images as P6, for bench/accuracy/make_report.py.
//
//   accuracy-report [--size WxH] [--out DIR] [--variant NAME]... [--stats] SCENE.sld
//
// Images go to DIR/STEM.TAG.ppm (TAG: double-libm, float-libm, float-portable,
// float-portable-fast, float-portable-fma). --variant restricts the run to the
// named variants (name or tag; repeatable), e.g. to count the instructions of
// one variant under callgrind. --stats prints, per variant, the differences
// from double/libm (which must then be among the variants).
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

int usage(const char* why) {
  if (why != nullptr) std::fprintf(stderr, "accuracy-report: %s\n", why);
  std::fprintf(stderr,
               "usage: accuracy-report [--size WxH] [--out DIR] [--variant NAME]... [--stats] "
               "SCENE.sld\nvariants:");
  for (const Variant& v : all_variants()) std::fprintf(stderr, " %s", v.name);
  std::fprintf(stderr, "\n");
  return 2;
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
    const bool has_value = i + 1 < argc;
    if (a == "--size" && has_value) {
      if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2) return usage("bad --size");
    } else if (a == "--out" && has_value) {
      out_dir = argv[++i];
    } else if (a == "--variant" && has_value) {
      const Variant* v = find_variant(argv[++i]);
      if (v == nullptr) return usage("unknown variant");
      chosen.push_back(v);
    } else if (a == "--stats") {
      stats = true;
    } else if (a == "-h" || a == "--help") {
      usage(nullptr);
      return 0;
    } else if (!a.empty() && a[0] != '-' && scene_path.empty()) {
      scene_path = a;
    } else {
      return usage(("unexpected argument " + a).c_str());
    }
  }
  if (scene_path.empty()) return usage("no scene");
  if (chosen.empty())
    for (const Variant& v : all_variants()) chosen.push_back(&v);

  std::ifstream in(scene_path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "accuracy-report: cannot read %s\n", scene_path.c_str());
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
      if (!minrt::host::write_file_atomically(path, r.image, false, why)) {
        std::fprintf(stderr, "accuracy-report: %s\n", why.c_str());
        status = 1;
      }
    }
    if (!stats) continue;
    if (std::strcmp(v->name, "double/libm") == 0) reference = r.image;
    if (reference.empty()) {
      std::fprintf(stderr, "accuracy-report: --stats needs double/libm first\n");
      return 2;
    }
    const ImageDiff d = diff_p6(reference, r.image);
    std::printf("%s\t%s\tmax=%d\tdiffering=%d\tover8=%d\tpixels=%d%s\n", stem_of(scene_path).c_str(),
                v->name, d.max_error, d.differing, d.over8, d.pixels, d.valid ? "" : "\tINVALID");
  }
  return status;
}
