// The hard scenes of sld/hard in every variant (tools/accuracy/variants.hpp).
// Each scene must be read without warnings, render completely in every
// variant and stay within the per-scene bounds listed in sld/hard/README.md.
#include <catch2/catch.hpp>

#include <algorithm>
#include <dirent.h>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "image_diff.hpp"
#include "test_support.hpp"
#include "variants.hpp"

namespace {

using minrt_accuracy::all_variants;
using minrt_accuracy::ImageDiff;
using minrt_accuracy::Rendered;

constexpr int kSize = 48;

std::string hard_dir() { return std::string(MINRT_SOURCE_DIR) + "/sld/hard"; }

std::vector<std::string> hard_scenes() {
  std::vector<std::string> names;
  if (DIR* d = opendir(hard_dir().c_str())) {
    while (const dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".sld") == 0) names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Bounds {
  int max_error = 0;
  int differing = 0;
  int over8 = 0;
};

// Rows "| NAME.sld | measured | MAX | DIFFERING | OVER8 |" of the README.
// Rows under a heading "... Bounds for VARIANT" (e.g. "### Bounds for
// float/portable-min") apply to that variant only, in place of the common
// row; the common rows are under any other heading.
using BoundsTable = std::map<std::string, Bounds>;
std::map<std::string, BoundsTable> read_variant_bounds() {
  std::map<std::string, BoundsTable> tables;  // "" = every variant
  std::string variant;
  std::istringstream in(minrt::test::read_file(hard_dir() + "/README.md"));
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') {
      const std::string key = "Bounds for ";
      const size_t at = line.find(key);
      variant = at == std::string::npos ? "" : line.substr(at + key.size());
      while (!variant.empty() && (variant.back() == ' ' || variant.back() == '\r'))
        variant.pop_back();
      continue;
    }
    std::vector<std::string> cells;
    std::istringstream row(line);
    std::string cell;
    while (std::getline(row, cell, '|')) {
      const size_t a = cell.find_first_not_of(' ');
      const size_t b = cell.find_last_not_of(' ');
      cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
    }
    // cells[0] is the text before the first '|'.
    if (cells.size() != 6 || cells[1].size() < 5 ||
        cells[1].compare(cells[1].size() - 4, 4, ".sld") != 0 ||
        cells[2].find('/') == std::string::npos)
      continue;
    tables[variant][cells[1]] =
        Bounds{std::stoi(cells[3]), std::stoi(cells[4]), std::stoi(cells[5])};
  }
  return tables;
}

BoundsTable read_bounds() { return read_variant_bounds()[""]; }

// The bound of one scene for one variant: its own row if it has one.
Bounds bounds_for(const std::map<std::string, BoundsTable>& tables, const std::string& variant,
                  const std::string& scene) {
  const auto own = tables.find(variant);
  if (own != tables.end() && own->second.count(scene) == 1) return own->second.at(scene);
  return tables.at("").at(scene);
}

Rendered render_scene(const minrt_accuracy::Variant& v, const std::string& scene) {
  return v.render(minrt::test::read_file(hard_dir() + "/" + scene), kSize, kSize);
}

}  // namespace

TEST_CASE("there are hard scenes and each has bounds in the README", "[hard]") {
  const auto scenes = hard_scenes();
  REQUIRE(scenes.size() >= 12);
  const auto bounds = read_bounds();
  for (const std::string& s : scenes) {
    INFO(s);
    CHECK(bounds.count(s) == 1);
  }
  CHECK(bounds.size() == scenes.size());
}

TEST_CASE("every hard scene is read without warnings", "[hard]") {
  for (const std::string& s : hard_scenes()) {
    const Rendered r = render_scene(all_variants().front(), s);
    INFO(s << ": " << r.error);
    REQUIRE(r.ok);
    for (const std::string& w : r.warnings) FAIL_CHECK("warning: " << w);
  }
}

TEST_CASE("the variant-specific hard-scene bounds name real variants and scenes", "[hard]") {
  const auto tables = read_variant_bounds();
  const auto scenes = hard_scenes();
  for (const auto& [variant, table] : tables) {
    if (variant.empty()) continue;
    INFO(variant);
    CHECK(minrt_accuracy::find_variant(variant) != nullptr);
    for (const auto& [scene, b] : table) CHECK(std::count(scenes.begin(), scenes.end(), scene) == 1);
  }
}

TEST_CASE("every hard scene renders completely in every variant, within its bounds", "[hard]") {
  const auto tables = read_variant_bounds();
  for (const std::string& s : hard_scenes()) {
    const Rendered reference = render_scene(all_variants().front(), s);
    REQUIRE(reference.ok);
    for (const auto& v : all_variants()) {
      const Bounds b = bounds_for(tables, v.name, s);
      INFO(s << " in " << v.name);
      const Rendered r = &v == &all_variants().front() ? reference : render_scene(v, s);
      REQUIRE(r.ok);
      CHECK(r.warnings.empty());
      int w = 0, h = 0;
      size_t offset = 0;
      REQUIRE(minrt_accuracy::parse_p6(r.image, w, h, offset));
      CHECK(w == kSize);
      CHECK(h == kSize);
      const ImageDiff d = minrt_accuracy::diff_p6(reference.image, r.image);
      REQUIRE(d.valid);
      INFO("max error " << d.max_error << ", differing " << d.differing << ", over 8 "
                        << d.over8);
      CHECK(d.max_error <= b.max_error);
      CHECK(d.differing <= b.differing);
      CHECK(d.over8 <= b.over8);
    }
  }
}

TEST_CASE("rendering a hard scene twice gives the same bytes", "[hard]") {
  for (const auto& v : all_variants()) {
    INFO(v.name);
    CHECK(render_scene(v, "grazing-box.sld").image == render_scene(v, "grazing-box.sld").image);
  }
}

TEST_CASE("float/portable+fma really differs from float/portable", "[hard][fma]") {
  // If the compiler did not fuse anything, the two would be identical.
  REQUIRE(minrt_accuracy::fma_variant_available());
  const auto* plain = minrt_accuracy::find_variant("float/portable");
  const auto* fused = minrt_accuracy::find_variant("float/portable+fma");
  REQUIRE(plain != nullptr);
  REQUIRE(fused != nullptr);
  int scenes_differing = 0;
  for (const std::string& s : hard_scenes()) {
    const ImageDiff d =
        minrt_accuracy::diff_p6(render_scene(*plain, s).image, render_scene(*fused, s).image);
    REQUIRE(d.valid);
    if (d.differing > 0) ++scenes_differing;
  }
  CHECK(scenes_differing > 0);
}
