// The hard cases of the text formats (test/hard/scenes/<format>): every
// scene is set up by minrt's own format side in every math variant and must
// render completely; the BVH walks (binary, 16-byte and widest wide walk;
// EASTRAY's object hierarchy against the plain CSG walk) give the same
// bytes; the float variants' bad pixels against double/libm (off by more
// than 8 where double's image is flat, docs/accuracy.md "Hard cases") stay
// within the bounds of test/hard/scenes/README.md; and each file of a bad/
// folder is refused with one located line (bad/EXPECTED.tsv).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <dirent.h>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "format_sides/general_scene.hpp"
#include "format_sides/host_formats.hpp"
#include "math_policy_dispatch.hpp"
#include "test_support.hpp"

namespace {

using namespace minrt;
using host::Precision;
using host::ShimSet;
using host::Variant;

const std::string kScenes = std::string(MINRT_SOURCE_DIR) + "/test/hard/scenes";

struct FormatDir {
  const char* folder;
  const char* ext;
  formats::FormatId id;
  int width, height;  // 0: the scene's own size
};
constexpr FormatDir kFormats[] = {
    {"cs418", ".txt", formats::FormatId::kCs418, 0, 0},
    {"jaworski", ".txt", formats::FormatId::kJaworski, 0, 0},
    {"minirt", ".rt", formats::FormatId::kMinirt, 64, 48},
    {"eastray", ".ray", formats::FormatId::kEastray, 0, 0},
};

struct NamedVariant {
  const char* name;
  Variant v;
};
const NamedVariant kVariants[] = {
    {"double/libm", {Precision::kDouble, ShimSet::kLibm}},
    {"float/libm", {Precision::kFloat, ShimSet::kLibm}},
    {"float/portable", {Precision::kFloat, ShimSet::kPortable}},
    {"float/portable-fast", {Precision::kFloat, ShimSet::kPortableFast}},
    {"float/portable-min", {Precision::kFloat, ShimSet::kPortableMin}},
};

std::vector<std::string> files_in(const std::string& dir, const std::string& ext) {
  std::vector<std::string> names;
  if (DIR* d = opendir(dir.c_str())) {
    while (const dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0) names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

std::unique_ptr<host::PreparedScene> prepare(const FormatDir& f, const std::string& dir, const std::string& name,
                                             Variant v, std::string& error) {
  const host::SceneInput in{dir + "/" + name, name, dir + "/", test::read_file(dir + "/" + name)};
  host::DriverOptions o;
  o.format = &formats::format_of(f.id);
  o.variant = v;
  o.threads = 1;
  o.quiet = true;
  o.width = f.width;
  o.height = f.height;
  return host::host_format(f.id).prepare(in, o, WarningSink{}, error);
}

using Image = std::vector<uint8_t>;

Image render(const host::PreparedScene& s) {
  Image rgba(static_cast<size_t>(s.width) * s.height * 4);
  for (int y = 0; y < s.height; ++y) s.render_row(y, rgba.data() + static_cast<size_t>(y) * s.width * 4);
  return rgba;
}

// The walks of a general scene give the image `full` gave.
template <class M>
void check_walks(host::PreparedScene& prepared, const Image& full, const std::string& what) {
  auto* g = dynamic_cast<host::GeneralScene<M>*>(&prepared);
  if (g == nullptr) return;  // Jaworski: one walk
  auto& r = g->renderer();
  INFO(what);
  if (r.wide_walk()) {
    r.use_16_byte_vectors();
    CHECK(render(prepared) == full);
    r.drop_wide_bvh();
    CHECK(render(prepared) == full);
  }
  if (r.objects().nodes != nullptr) {
    r.drop_object_bvh();
    CHECK(render(prepared) == full);
  }
}

// SPEC.md 1.6's premultiplied channel (CS418 has alpha; the others are opaque).
int channel(const Image& img, size_t i, int c) {
  return (img[i * 4 + c] * img[i * 4 + 3] + 127) / 255;
}
int pixel_error(const Image& a, const Image& b, size_t i) {
  int e = 0;
  for (int c = 0; c < 4; ++c) e = std::max(e, std::abs(channel(a, i, c) - channel(b, i, c)));
  return e;
}

constexpr int kBadError = 8;

// Pixels of `img` off by more than kBadError from `ref` where `ref` is flat:
// outside its edge mask (a pixel with a 3x3 neighbour more than kBadError
// away) dilated by one pixel. bench/accuracy/hard_cases.py counts the same.
long bad_pixels(const Image& img, const Image& ref, int w, int h) {
  std::vector<uint8_t> edge(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
          const size_t i = static_cast<size_t>(y) * w + x, n = static_cast<size_t>(ny) * w + nx;
          int e = 0;
          for (int c = 0; c < 4; ++c) e = std::max(e, std::abs(channel(ref, i, c) - channel(ref, n, c)));
          if (e > kBadError) edge[i] = 1;
        }
  long bad = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool near_edge = false;
      for (int dy = -1; dy <= 1 && !near_edge; ++dy)
        for (int dx = -1; dx <= 1 && !near_edge; ++dx)
          near_edge = edge[static_cast<size_t>(std::clamp(y + dy, 0, h - 1)) * w + std::clamp(x + dx, 0, w - 1)];
      if (!near_edge && pixel_error(img, ref, static_cast<size_t>(y) * w + x) > kBadError) ++bad;
    }
  return bad;
}

// "| folder/scene | N |" rows of the README: the bad pixels each float
// variant may have on that scene.
std::map<std::string, long> read_bounds() {
  std::map<std::string, long> bounds;
  std::istringstream in(test::read_file(kScenes + "/README.md"));
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::istringstream row(line);
    std::string cell;
    while (std::getline(row, cell, '|')) {
      const size_t a = cell.find_first_not_of(' '), b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    if (cells.size() < 4 || cells[1].find('/') == std::string::npos || cells[2].empty() ||
        cells[2].find_first_not_of("0123456789") != std::string::npos)
      continue;
    bounds[cells[1]] = std::stol(cells[2]);
  }
  return bounds;
}

}  // namespace

TEST_CASE("hard cases render in every variant, walks agree, bad pixels within bounds", "[hard]") {
  const auto bounds = read_bounds();
  for (const FormatDir& f : kFormats) {
    const std::string dir = kScenes + "/" + f.folder;
    const auto names = files_in(dir, f.ext);
    REQUIRE(names.size() >= 8);
    for (const std::string& name : names) {
      const std::string key = std::string(f.folder) + "/" + name;
      DYNAMIC_SECTION(key) {
        const auto bound = bounds.find(key);
        REQUIRE(bound != bounds.end());  // every scene has its row in the README
        Image reference;
        int w = 0, h = 0;
        for (const NamedVariant& nv : kVariants) {
          INFO(key << " in " << nv.name);
          std::string error;
          auto s = prepare(f, dir, name, nv.v, error);
          INFO(error);
          REQUIRE(s != nullptr);
          REQUIRE(s->width > 0);
          REQUIRE(s->height > 0);
          const Image img = render(*s);
          host::with_math_policy(nv.v, [&]<class M>() { check_walks<M>(*s, img, key + " " + nv.name); });
          if (reference.empty()) {
            reference = img, w = s->width, h = s->height;
            continue;
          }
          REQUIRE(s->width == w);
          REQUIRE(s->height == h);
          CHECK(bad_pixels(img, reference, w, h) <= bound->second);
        }
      }
    }
  }
}

TEST_CASE("hard cases a reader must refuse give one located line", "[hard][errors]") {
  for (const FormatDir& f : kFormats) {
    const std::string dir = kScenes + "/" + f.folder + "/bad";
    std::istringstream in(test::read_file(dir + "/EXPECTED.tsv"));
    std::string line;
    int rows = 0;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream row(line);
      std::string name, variants, message;
      std::getline(row, name, '\t');
      std::getline(row, variants, '\t');
      std::getline(row, message);
      ++rows;
      for (const NamedVariant& nv : kVariants) {
        const bool refused = variants == "all" || (variants == "float" && nv.v.precision == Precision::kFloat);
        INFO(f.folder << "/bad/" << name << " in " << nv.name);
        std::string error;
        auto s = prepare(f, dir, name, nv.v, error);
        if (!refused) {
          CHECK(s != nullptr);
          continue;
        }
        CHECK(s == nullptr);
        CHECK(error.find('\n') == std::string::npos);
        CHECK(error.rfind(name + ":", 0) == 0);  // FILE:LINE[:COL]: ...
        CHECK(error.find(message) != std::string::npos);
        INFO(error);
      }
    }
    CHECK(rows == static_cast<int>(files_in(dir, f.ext).size()));
  }
}
