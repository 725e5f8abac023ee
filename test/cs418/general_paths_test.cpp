// The specialised paths (render/general/features.hpp): a scene is rendered
// on the smallest path that has its features, and that path gives the same
// bytes as the path with every feature compiled in.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "format_sides/general_scene.hpp"
#include "cs418_render.hpp"
#include "render/general/render.hpp"
#include "test_support.hpp"

namespace {

using minrt::test::render_cs418;

minrt::host::RenderedScene render_text(const std::string& text, bool full, minrt::host::Variant v = {}) {
  minrt::host::DriverOptions o;
  o.variant = v;
  o.force_full = full;
  o.threads = 2;
  minrt::host::RenderedScene r;
  std::string error;
  const std::string dir = minrt::test::shared_dir() + "/formats/cs418/";
  const bool ok = render_cs418(text, "scene.txt", dir, o, r, error);
  INFO(error);
  REQUIRE(ok);
  return r;
}

}  // namespace

TEST_CASE("general paths: each scene takes the smallest path with its features", "[general][paths]") {
  const std::string spheres = "png 40 30 x.png\nsphere 0 0 -2 1\ncolor 1 0 0\nsphere 1 0 -3 1\nsun 1 1 1\n";
  const std::string tri = "png 40 30 x.png\nxyz 0 0 -2\nxyz 1 0 -2\nxyz 0 1 -2\ntri 1 2 3\nsun 0 0 1\n";
  const std::string shiny = "png 40 30 x.png\nshininess 0.5\nsphere 0 0 -2 1\nsun 1 1 1\n";
  CHECK(render_text(spheres, false).path == minrt::host::general_path_name(minrt::general::kPathBasic));
  CHECK(render_text(tri, false).path == minrt::host::general_path_name(minrt::general::kPathDirect));
  CHECK(render_text(shiny, false).path == minrt::host::general_path_name(minrt::general::kPathFull));
  CHECK(render_text(spheres, true).path == minrt::host::general_path_name(minrt::general::kPathFull));
}

TEST_CASE("general paths: the specialised path gives the bytes of the full one", "[general][paths]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const minrt::host::Variant portable{minrt::host::Precision::kFloat, minrt::host::ShimSet::kPortable};
  for (const char* name : {"sphere", "suns", "shadow-basic", "tri", "plane", "bulb", "fisheye", "panorama",
                           "expose2", "many"}) {
    DYNAMIC_SECTION(name) {
      const std::string text =
          minrt::test::read_file(minrt::test::shared_dir() + "/formats/cs418/ray-" + name + ".txt");
      const auto fast = render_text(text, false);
      CHECK(std::string(fast.path) != minrt::host::general_path_name(minrt::general::kPathFull));
      CHECK(fast.image.rgba == render_text(text, true).image.rgba);
      CHECK(render_text(text, false, portable).image.rgba == render_text(text, true, portable).image.rgba);
    }
  }
}

TEST_CASE("general: the weight cut-off leaves the course's reflection and refraction tests unchanged",
          "[general][cutoff]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  for (const char* name : {"shine1", "shine3", "bounces", "trans1", "trans3", "ior"}) {
    DYNAMIC_SECTION(name) {
      const std::string text =
          minrt::test::read_file(minrt::test::shared_dir() + "/formats/cs418/ray-" + name + ".txt");
      minrt::host::DriverOptions o;
      o.threads = 2;
      minrt::host::RenderedScene cut, full;
      std::string error;
      const std::string dir = minrt::test::shared_dir() + "/formats/cs418/";
      REQUIRE(render_cs418(text, name, dir, o, cut, error));
      o.full_tree = true;
      REQUIRE(render_cs418(text, name, dir, o, full, error));
      CHECK(cut.image.rgba == full.image.rgba);
    }
  }
}

TEST_CASE("general: a skipped branch changes no other random number", "[general][cutoff]") {
  // Glass and rough mirrors with 16 bounces: the cut-off skips deep
  // branches; the rough reflections' noise must stay the same, so the two
  // images differ by at most one level per channel.
  const std::string scene =
      "png 48 32 x.png\nbounces 16\naa 4\nsun 1 1 1\ncolor 0.9 0.9 0.9\nshininess 0.1\ntransparency 0.9\n"
      "sphere -0.6 0 -3 0.5\nsphere 0.6 0 -3 0.5\ntransparency 0\nshininess 0.6\nroughness 0.1\n"
      "sphere 0 0.8 -3.5 0.5\nsphere 0 -0.8 -3.5 0.5\n";
  minrt::host::DriverOptions o;
  minrt::host::RenderedScene cut, full;
  std::string error;
  REQUIRE(render_cs418(scene, "s.txt", "", o, cut, error));
  o.full_tree = true;
  REQUIRE(render_cs418(scene, "s.txt", "", o, full, error));
  int worst = 0;
  for (std::size_t i = 0; i < cut.image.rgba.size(); ++i)
    worst = std::max(worst, std::abs(int(cut.image.rgba[i]) - int(full.image.rgba[i])));
  CHECK(worst <= 1);
}
