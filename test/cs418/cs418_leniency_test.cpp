// minrt is as lenient as the course (docs/cs418.md): the assignment asks
// for no error checking, so what a course program would render, minrt
// renders, saying with a located warning what it ignored or took as odd
// input. Each case: status 0, the image written, exactly the warnings
// expected.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <string>

#include "png_io.hpp"
#include "test_support.hpp"

namespace {

struct Rendered {
  minrt::test::CommandRun run;
  minrt::host::RgbaImage image;
  bool written = false;
};

// Writes `scene` to scene.txt in a fresh folder, renders it to out.png.
Rendered render(const std::string& scene, const std::string& options = "") {
  const std::string dir = minrt::test::temp_dir("cs418-lenient");
  std::ofstream(dir + "/scene.txt") << scene;
  Rendered r;
  r.run = minrt::test::run_in_dir(dir, std::string(MINRT_BIN) + " " + options + " -o out.png scene.txt");
  std::string why;
  r.written = minrt::host::read_png(dir + "/out.png", r.image, why);
  std::system(("rm -rf '" + dir + "'").c_str());
  return r;
}

void check_renders(const Rendered& r, const std::string& warnings) {
  CHECK(r.run.status == 0);
  CHECK(r.written);
  CHECK(r.run.err == warnings);
}

bool any_lit(const minrt::host::RgbaImage& img) {
  for (std::size_t i = 0; i < img.rgba.size(); i += 4)
    if (img.rgba[i] != 0 || img.rgba[i + 1] != 0 || img.rgba[i + 2] != 0) return true;
  return false;
}

const std::string kBall = "sphere 0 0 -2 1\nsun 1 1 1\n";

}  // namespace

TEST_CASE("cs418 leniency: bounces beyond the stack's depth render with the depth the stack holds",
          "[cs418][cli][lenient]") {
  const auto deep = render("png 8 8 o.png\nbounces 1000\nshininess 0.5\n" + kBall);
  check_renders(deep, "scene.txt:2:9: warning: bounces 1000 is deeper than the stack holds: 64 used\n");
  const auto held = render("png 8 8 o.png\nbounces 64\nshininess 0.5\n" + kBall);
  check_renders(held, "");
  CHECK(deep.image.rgba == held.image.rgba);
}

TEST_CASE("cs418 leniency: a gi depth beyond the stack's renders with the depth the stack holds",
          "[cs418][cli][lenient]") {
  const auto deep = render("png 8 8 o.png\ngi 100\n" + kBall);
  check_renders(deep, "scene.txt:2:4: warning: gi depth 100 is deeper than the stack holds: 16 used\n");
  CHECK(deep.image.rgba == render("png 8 8 o.png\ngi 16\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: any number of aa samples", "[cs418][cli][lenient]") {
  // 2x2 pixels, 100,000 samples each: the alpha count is beyond 2^32 / 255.
  const auto r = render("png 2 2 o.png\naa 100000\nsphere 0 0 -2 3\n");
  check_renders(r, "");
  for (int i = 0; i < 4; ++i) CHECK(int(r.image.rgba[4 * i + 3]) == 255);
}

TEST_CASE("cs418 leniency: images as wide as the build's image limit", "[cs418][cli][lenient]") {
  const auto r = render("png 4096 2 o.png\nsphere 0 0 -2 1\n");
  check_renders(r, "");
  CHECK(r.image.width == 4096);
  CHECK(render("png 4097 2 o.png\n").run.status == 2);
}

TEST_CASE("cs418 leniency: extra fields are ignored with a warning", "[cs418][cli][lenient]") {
  const auto r = render("png 8 8 o.png extra\nsphere 0 0 -2 1 7 8\nsun 1 1 1 1\nshininess 0.5 0.5\n");
  check_renders(r,
                "scene.txt:1:15: warning: 1 extra field ignored\n"
                "scene.txt:2:17: warning: 2 extra fields ignored\n"
                "scene.txt:3:11: warning: 1 extra field ignored\n"
                "scene.txt:4:15: warning: 1 extra field ignored\n");
  CHECK(r.image.rgba == render("png 8 8 o.png\nsphere 0 0 -2 1\nsun 1 1 1\nshininess 0.5\n").image.rgba);
  // Past the words a line stores, too.
  std::string many = "png 8 8 o.png\ncolor 1 1 1";
  for (int i = 0; i < 30; ++i) many += " 9";
  const auto m = render(many + "\n" + kBall);
  check_renders(m, "scene.txt:2:13: warning: 30 extra fields ignored\n");
}

TEST_CASE("cs418 leniency: '#' comment lines are ignored with a warning", "[cs418][cli][lenient]") {
  const auto r = render("# a course scene\npng 8 8 o.png\n#sphere 0 0 -2 5\n" + kBall);
  check_renders(r,
                "scene.txt:1:1: warning: comment line ignored\n"
                "scene.txt:3:1: warning: comment line ignored\n");
  CHECK(r.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: a trailing '# comment' is ignored with a warning", "[cs418][cli][lenient]") {
  const auto r = render("png 8 8 o.png\nsphere 0 0 -2 1 # the ball, with more words than a line stores: a b c d e f g\n"
                        "sun 1 1 1\n");
  check_renders(r, "scene.txt:2:17: warning: comment ignored\n");
  CHECK(r.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: up parallel to forward keeps the camera's right vector", "[cs418][cli][lenient]") {
  // Looking straight down: forward parallel to the default up.
  const auto r = render("png 8 8 o.png\neye 0 3 -2\nforward 0 -1 0\n" + kBall);
  check_renders(r, "scene.txt:3:9: warning: forward is parallel to up: the camera keeps its right vector\n");
  CHECK(any_lit(r.image));
  const auto u = render("png 8 8 o.png\nforward 0 0 -1\nup 0 0 2\n" + kBall);
  check_renders(u, "scene.txt:3:4: warning: up is parallel to forward: the camera keeps its right vector\n");
  CHECK(u.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: a sun without direction is left out with a warning", "[cs418][cli][lenient]") {
  const auto r = render("png 8 8 o.png\nsphere 0 0 -2 1\nsun 0 0 0\nsun 1 1 1\n");
  check_renders(r, "scene.txt:3:5: warning: sun direction is zero: the sun is left out (it would light nothing)\n");
  CHECK(r.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: a light of zero colour is left out with a warning", "[cs418][cli][lenient]") {
  const auto r = render("png 8 8 o.png\nsphere 0 0 -2 1\nsun 1 1 1\ncolor 0 0 0\nbulb 0 0 0\nsun 0 1 0\n");
  check_renders(r,
                "scene.txt:5:1: warning: light colour is zero: the light is left out (it would add nothing)\n"
                "scene.txt:6:1: warning: light colour is zero: the light is left out (it would add nothing)\n");
  CHECK(r.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}

TEST_CASE("cs418 leniency: a negative radius draws the sphere of its absolute value", "[cs418][cli][lenient]") {
  const auto r = render("png 8 8 o.png\nsphere 0 0 -2 -1\nsun 1 1 1\n");
  check_renders(r, "scene.txt:2:15: warning: negative radius '-1': the sphere is drawn with its absolute value\n");
  CHECK(any_lit(r.image));
  CHECK(r.image.rgba == render("png 8 8 o.png\n" + kBall).image.rgba);
}
