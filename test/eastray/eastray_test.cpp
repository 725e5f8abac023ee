// EASTRAY scenes: every shared scene renders and shows what its README says
// (probes at named pixels); the same geometry written two ways gives the
// same image (equivalence pairs); invalid scenes get a located one-line
// error, status 2 and no file; the preprocessor's includes and macros.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "eastray_preprocess.hpp"
#include "eastray_probe_support.hpp"
#include "test_support.hpp"

namespace {

using minrt::test::EastrayImage;

struct Rgb {
  int r, g, b;
  int sum() const { return r + g + b; }
};

std::string ea_dir() { return minrt::test::shared_dir() + "/formats/eastray/"; }
bool have_shared() {
  struct stat st {};
  return ::stat(ea_dir().c_str(), &st) == 0;
}

EastrayImage render_file(const std::string& path, minrt::host::Variant v = {}) {
  EastrayImage img;
  std::string error;
  const std::string text = minrt::test::read_file(path);
  INFO(path);
  const bool ok = minrt::test::render_eastray(path, text, v, img, error);
  INFO(error);
  REQUIRE(ok);
  return img;
}

EastrayImage render_text(const std::string& text, minrt::host::Variant v = {}) {
  EastrayImage img;
  std::string error;
  const bool ok = minrt::test::render_eastray("scene.ray", text, v, img, error);
  INFO(error);
  REQUIRE(ok);
  return img;
}

Rgb px(const EastrayImage& im, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * im.width + x) * 3;
  return Rgb{im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}
bool is_sky(Rgb c) { return c.r == 51 && c.g == 102 && c.b == 204; }
bool reddish(Rgb c) { return c.r > 80 && c.r > 2 * c.g && c.r > 2 * c.b; }
bool greenish(Rgb c) { return c.g > 60 && c.g > 2 * c.r && c.g > 2 * c.b; }
bool bluish(Rgb c) { return c.b > 60 && c.b > 2 * c.r && c.b > c.g + 40; }
bool yellowish(Rgb c) { return c.r > 80 && c.g > 0.7 * c.r && c.b < 0.4 * c.r; }
bool magentaish(Rgb c) { return c.r > 60 && c.b > 60 && c.g < 0.5 * c.r && c.g < 0.5 * c.b; }
bool cyanish(Rgb c) { return c.g > 60 && c.b > 60 && c.r < 0.5 * c.g; }
bool same(Rgb a, Rgb b) { return a.r == b.r && a.g == b.g && a.b == b.b; }

template <class F>
bool any_in(const EastrayImage& im, int x0, int y0, int x1, int y1, F f) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (f(px(im, x, y))) return true;
  return false;
}

using eprobe::differing;

const char* kHeader =
    "display 96 72 0 0 95 71 1 1 1 ;\n"
    "condition 4 0.01 0.00001 0 ;\n"
    "camera 0 2.5 9  0 1 0  0 10 0  25 0 ;\n"
    "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\n"
    "e_light [ -1 1 1  1 1 1  0 1 ; ]\n"
    "color [\n grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
    " red 0.9 0.1 0.1  0 0 0  0 0 0  1 1  0  0 0.5 20 ;\n"
    " blue 0.1 0.2 0.9  0 0 0  0 0 0  1 1  0  0 0.5 20 ;\n]\n";

std::string scene(const std::string& objects) {
  return std::string(kHeader) + "obj [\n 1 grey 1  0 0 0  0 1 0 ;\n" + objects + "\n]\n";
}

// Same image within float rounding: at most `edge` silhouette pixels differ.
void check_pair(const std::string& a, const std::string& b, int edge = 6) {
  const EastrayImage ia = render_text(a), ib = render_text(b);
  const int n = differing(ia, ib);
  INFO("differing pixels: " << n);
  CHECK(n <= edge);
}

using Run = minrt::test::CommandRun;

Run run_minrt(const std::string& args, const std::string& cwd) {
  return minrt::test::run_in_dir(cwd, std::string(MINRT_BIN) + " " + args);
}

std::string temp_dir() { return minrt::test::temp_dir("ea"); }

void write(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

// ------------------------------------------------------------------ probes

TEST_CASE("eastray: every shared scene renders and shows what its README says", "[eastray]") {
  if (!have_shared()) {
    WARN("../shared/formats/eastray missing: skipped");
    return;
  }
  SECTION("basic_sphere_floor_elight") {
    const auto im = render_file(ea_dir() + "basic_sphere_floor_elight.ray");
    CHECK(im.width == 160);
    CHECK(im.height == 120);
    CHECK(is_sky(px(im, 80, 5)));          // sky in the top fifth
    CHECK(!is_sky(px(im, 80, 30)));
    CHECK(reddish(px(im, 80, 58)));        // red sphere, centred, a little below the centre
    CHECK(reddish(px(im, 72, 52)));
    CHECK(px(im, 72, 50).sum() > px(im, 88, 66).sum());  // lit from the upper left
    CHECK(px(im, 100, 72).sum() < px(im, 40, 72).sum() - 60);  // shadow to the right
  }
  SECTION("preview_window_step_shadow_off") {
    const auto im = render_file(ea_dir() + "preview_window_step_shadow_off.ray");
    CHECK(px(im, 5, 5).sum() == 0);       // outside the window: black
    CHECK(px(im, 39, 60).sum() == 0);
    CHECK(px(im, 120, 60).sum() == 0);
    CHECK(px(im, 80, 29).sum() == 0);
    CHECK(px(im, 80, 90).sum() == 0);
    CHECK(px(im, 40, 30).sum() > 0);
    CHECK(!is_sky(px(im, 60, 31)));       // the horizon lies above the window
    CHECK(reddish(px(im, 80, 58)));
    for (int y = 30; y < 90; y += 2)        // 2x2 blocks
      for (int x = 40; x < 120; x += 2) {
        REQUIRE(same(px(im, x, y), px(im, x + 1, y)));
        REQUIRE(same(px(im, x, y), px(im, x, y + 1)));
      }
    CHECK(same(px(im, 100, 72), px(im, 44, 72)));  // no shadow on the floor
  }
  SECTION("camera_fov_halfangle") {
    const auto im = render_file(ea_dir() + "camera_fov_halfangle.ray");
    CHECK(greenish(px(im, 151, 60)));
    CHECK(bluish(px(im, 9, 60)));
    CHECK(!is_sky(px(im, 9, 60)));
    CHECK(reddish(px(im, 80, 10)));
    CHECK(!is_sky(px(im, 80, 60)));
    CHECK(!is_sky(px(im, 80 + 12, 60)));  // about 28 dots across
    CHECK(is_sky(px(im, 80 + 17, 60)));
    CHECK(is_sky(px(im, 80 - 17, 60)));
  }
  SECTION("lights_point_spot") {
    const auto im = render_file(ea_dir() + "lights_point_spot.ray");
    CHECK(px(im, 15, 110).sum() > px(im, 80, 35).sum() + 60);  // brightest near the point light
    const Rgb pool = px(im, 110, 67);
    CHECK(pool.r > pool.b + 40);            // warm-yellow pool under the spot
    CHECK(pool.sum() > px(im, 140, 40).sum() + 60);
    CHECK(px(im, 50, 50).sum() > px(im, 62, 64).sum());  // big sphere lit from the upper left
    const Rgb small_top = px(im, 112, 41);
    CHECK(small_top.r > small_top.b + 30);  // small sphere lit yellow on top
    CHECK(px(im, 116, 60).sum() > px(im, 62, 72).sum());  // no spot shadow in the pool (r 2.5)
  }
  SECTION("noshadow_n_flags") {
    const auto im = render_file(ea_dir() + "noshadow_n_flags.ray");
    CHECK(px(im, 58, 72).sum() < px(im, 58, 95).sum() - 60);  // left sphere's shadow
    CHECK(same(px(im, 20, 66), px(im, 20, 100)));            // nothing casts to the left
    CHECK(same(px(im, 130, 100), px(im, 20, 100)));
    CHECK(reddish(px(im, 95, 37)));                          // the thin red bar
  }
  SECTION("material_constant_shading") {
    const auto im = render_file(ea_dir() + "material_constant_shading.ray");
    CHECK(yellowish(px(im, 28, 60)));
    CHECK(same(px(im, 28, 60), px(im, 38, 60)));   // k 0: one flat colour
    CHECK(same(px(im, 28, 60), px(im, 28, 48)));
    const Rgb wr = px(im, 63, 60), wr_rim = px(im, 77, 60);
    CHECK((wr.r > 200 && wr.g > 200 && wr.b > 200));
    CHECK(reddish(wr_rim));
    CHECK(bluish(px(im, 97 + 9, 60)));
    const Rgb lambert = px(im, 130, 60);
    CHECK(lambert.sum() < 200);             // light behind: dark but for a crescent
    CHECK(any_in(im, 130, 48, 140, 60, [&](Rgb c) { return c.sum() > lambert.sum() + 90; }));
  }
  SECTION("kinds_0_3_6_quadric_ellipsoid_spheroid") {
    const auto im = render_file(ea_dir() + "kinds_0_3_6_quadric_ellipsoid_spheroid.ray");
    const Rgb o = px(im, 30, 67);
    CHECK((o.r > 100 && o.g > 0.3 * o.r && o.g < 0.8 * o.r && o.b < 0.4 * o.r));
    CHECK(greenish(px(im, 72, 47)));        // spindle leaning left: top left of bottom
    CHECK(greenish(px(im, 85, 66)));
    CHECK(!greenish(px(im, 88, 47)));
    CHECK(magentaish(px(im, 135, 52)));     // cigar leaning right
    CHECK(magentaish(px(im, 117, 70)));
    CHECK(!magentaish(px(im, 117, 52)));
  }
  SECTION("kinds_4_5_infinite_cone_cylinder") {
    const auto im = render_file(ea_dir() + "kinds_4_5_infinite_cone_cylinder.ray");
    CHECK(yellowish(px(im, 80, 2)));        // the upper cone reaches the top edge
    CHECK(yellowish(px(im, 80, 72)));       // the lower cone on the floor
    CHECK(is_sky(px(im, 80 + 25, 2)));
    CHECK(bluish(px(im, 10, 27)));          // the pipe crosses the width
    const Rgb right = px(im, 150, 27);
    CHECK(right.b > right.r);
    CHECK(right.sum() < px(im, 10, 27).sum() * 0.7);  // its right half in the cone's shadow
    CHECK(px(im, 150, 62).sum() < px(im, 20, 62).sum() - 60);  // wedge of shadow on the floor
  }
  SECTION("kinds_15_16_capped_cylinder_box_faces") {
    const auto im = render_file(ea_dir() + "kinds_15_16_capped_cylinder_box_faces.ray");
    CHECK(yellowish(px(im, 55, 36)));       // t = the +axis cap
    CHECK(bluish(px(im, 55, 55)));
    CHECK(greenish(px(im, 100, 50)));       // +y
    CHECK(bluish(px(im, 95, 65)));          // +z
    CHECK(reddish(px(im, 118, 65)));        // +x
    CHECK(!any_in(im, 85, 45, 125, 85, [](Rgb c) { return cyanish(c) || magentaish(c) || yellowish(c); }));
  }
  SECTION("kinds_20_polygon_mesh") {
    const auto im = render_file(ea_dir() + "kinds_20_polygon_mesh.ray");
    CHECK(reddish(px(im, 45, 65)));         // 'c red' front face
    CHECK(same(px(im, 42, 68), px(im, 48, 68)));  // flat shaded
    const Rgb side = px(im, 56, 70);
    CHECK((side.r > 2 * side.b && side.g > 0.3 * side.r));  // orange right face
    CHECK(any_in(im, 95, 45, 120, 70, [](Rgb c) { return c.b > 120 && c.b > c.r + 20; }));  // light blue octahedron
  }
  SECTION("moves_order_mtx") {
    const auto im = render_file(ea_dir() + "moves_order_mtx.ray");
    CHECK(cyanish(px(im, 55, 68)));         // B: cyan front after :ry 90
    CHECK(greenish(px(im, 55, 62)));        // green top
    CHECK(bluish(px(im, 61, 66)));          // blue right side
    const Rgb c = px(im, 80, 62);
    CHECK((c.r > 150 && c.g > 70 && c.b < 60));  // C: orange ellipsoid
    CHECK(greenish(px(im, 80, 50)));        // F: the post behind it
    CHECK(magentaish(px(im, 104, 62)));     // D: purple, tall and thin
    CHECK(magentaish(px(im, 104, 56)));
    CHECK(!magentaish(px(im, 110, 62)));
    // A and E: white bars high at the edges, same height, rising to the right
    auto white = [](Rgb w) { return w.r > 150 && w.g > 150 && w.b > 150; };
    CHECK(white(px(im, 30, 44)));
    CHECK(white(px(im, 130, 44)));
    CHECK(white(px(im, 25, 46)));   // left end low, right end high: /
    CHECK(white(px(im, 35, 42)));
    CHECK_FALSE(white(px(im, 25, 41)));
    CHECK_FALSE(white(px(im, 35, 47)));
    CHECK(white(px(im, 125, 46)));
    CHECK(white(px(im, 135, 42)));
    CHECK_FALSE(white(px(im, 125, 41)));
    CHECK_FALSE(white(px(im, 135, 47)));
  }
  SECTION("csg_or_and_diff_range") {
    const auto im = render_file(ea_dir() + "csg_or_and_diff_range.ray");
    CHECK(any_in(im, 25, 45, 55, 75, bluish));       // flat blue faces
    CHECK(any_in(im, 25, 45, 55, 75, reddish));      // rounded red corners
    CHECK(greenish(px(im, 70, 65)));                 // plate
    CHECK(!greenish(px(im, 79, 58)));                // the hole shows the floor
    CHECK(any_in(im, 75, 50, 95, 65, yellowish));    // the hole's inner wall
    CHECK(magentaish(px(im, 130, 65)));
    CHECK(magentaish(px(im, 125, 52)));              // the top sphere
  }
  SECTION("parts_named_calls") {
    const auto im = render_file(ea_dir() + "parts_named_calls.ray");
    auto brown = [](Rgb c) { return c.r > 80 && c.g > 0.35 * c.r && c.g < 0.8 * c.r && c.b < 0.5 * c.g; };
    CHECK(any_in(im, 35, 48, 70, 58, brown));        // left table top
    CHECK(any_in(im, 95, 48, 130, 58, brown));       // right table top
    CHECK(!any_in(im, 0, 0, 159, 119, [](Rgb c) { return c.r > 120 && c.g < 50 && c.b < 50; }));  // no red sphere
  }
  SECTION("material_mirror_condition") {
    const auto im = render_file(ea_dir() + "material_mirror_condition.ray");
    CHECK(reddish(px(im, 37, 72)));
    CHECK(bluish(px(im, 125, 72)));
    CHECK(any_in(im, 65, 45, 79, 65, reddish));      // the red sphere in the chrome
  }
  SECTION("material_glass_ior") {
    const auto im = render_file(ea_dir() + "material_glass_ior.ray");
    CHECK(bluish(px(im, 55, 65)));                   // sky seen in the lower part (inverted)
    const Rgb up = px(im, 58, 46);
    CHECK(!is_sky(up));
    const Rgb g = px(im, 118, 62);                   // green-tinted right sphere
    CHECK(g.g > g.r + 20);
    CHECK(g.g > g.b + 20);
  }
  SECTION("preproc_define_include") {
    const auto im = render_file(ea_dir() + "preproc_define_include.ray");
    CHECK(greenish(px(im, 60, 62)));
    const Rgb o = px(im, 100, 66);
    CHECK((o.r > 150 && o.g > 60 && o.b < 60));
  }
}

TEST_CASE("eastray: float build gives the same picture as double", "[eastray]") {
  if (!have_shared()) return;
  minrt::host::Variant f;
  f.precision = minrt::host::Precision::kFloat;
  f.shims = minrt::host::ShimSet::kPortable;
  for (const char* name : {"csg_or_and_diff_range.ray", "kinds_15_16_capped_cylinder_box_faces.ray",
                           "moves_order_mtx.ray", "material_glass_ior.ray"}) {
    const auto d = render_file(ea_dir() + name), p = render_file(ea_dir() + name, f);
    INFO(name);
    CHECK(differing(d, p, 3) <= 40);
  }
}

// -------------------------------------------------------------- equivalences

TEST_CASE("eastray: equivalent geometry gives the same image", "[eastray]") {
  SECTION("sphere = ellipsoid = quadric = spheroid") {
    const std::string sphere = scene("2 red 1  0.3 1 0  1 ;");
    check_pair(sphere, scene("3 red 1  0.3 1 0  1 1 1 ;"));
    // (x-0.3)^2 + (y-1)^2 + z^2 - 1
    check_pair(sphere, scene("0 red 1  1 1 1  0 0 0  -0.6 -2 0  0.09 ;"));
    check_pair(sphere, scene("0 red 1  0.3 1 0  1 1 1  0 0 0  0 0 0  -1 ;"));
    check_pair(sphere, scene("6 red 1  0.3 1 0  1 2 0.5  1 1 ;"));
  }
  SECTION("capped cylinder = AND of an infinite cylinder and two planes") {
    check_pair(scene("15 red 1  0 1 0  0 1 0  0.6 0.8 ;"),
               scene("{ 5 red 1  0 1 0  0 1 0  0.6 ;  1 red 1  0 1.8 0  0 1 0 ;  1 red 1  0 0.2 0  0 -1 0 ; }"));
  }
  SECTION("box = AND of six planes") {
    check_pair(scene("16 :ry 30 red 1  0 1 0  0.8 0.6 0.5 ;"),
               scene("{ :ry 30 1 red 1  0.8 1 0  1 0 0 ; 1 red 1  -0.8 1 0  -1 0 0 ; 1 red 1  0 1.6 0  0 1 0 ;"
                     "  1 red 1  0 0.4 0  0 -1 0 ; 1 red 1  0 1 0.5  0 0 1 ; 1 red 1  0 1 -0.5  0 0 -1 ; }"));
  }
  SECTION("RANGE on = off") {
    check_pair(scene("2 red 1  -1 0.5 0  0.5 ; 2 blue 1  0 0.5 0  0.5 ; 2 red 1  1 0.5 0  0.5 ;"),
               scene("( 5  0 0.5 0  1 0 0  0.8 ; 2 red 1  -1 0.5 0  0.5 ; 2 blue 1  0 0.5 0  0.5 ;"
                     "  2 red 1  1 0.5 0  0.5 ; )"),
               0);
    check_pair(scene("{ 2 red 1  0 1 0  1 ; 16 blue 1  0 1 0  0.75 0.75 0.75 ; }"),
               scene("{ ( 2  0 1 0  1.5 ; 2 red 1  0 1 0  1 ; ) 16 blue 1  0 1 0  0.75 0.75 0.75 ; }"), 0);
  }
  SECTION(":mtx = the same chain of moves") {
    // :mx 0.5 :my 1 :rz 90 :sx 2 : x -> (0.5 - y, 1 + 2x, z)
    check_pair(scene("[ :mx 0.5 :my 1 :rz 90 :sx 2  3 red 1  0 0 0  0.5 0.3 0.4 ; ]"),
               scene("[ :mtx 0 -1 0 0.5  2 0 0 1  0 0 1 0  0 0 0 1  3 red 1  0 0 0  0.5 0.3 0.4 ; ]"));
  }
  SECTION("sign -1 inside AND = a difference") {
    check_pair(scene("{ 16 red 1  0 1 0  0.8 0.8 0.8 ; 2 blue -1  0.5 1.5 0.5  0.6 ; }"),
               scene("{ 16 red 1  0 1 0  0.8 0.8 0.8 ; { 2 blue -1  0.5 1.5 0.5  0.6 ; } }"), 0);
  }
  SECTION("named part = its objects inline, with the caller's moves") {
    const std::string inline_objs = scene("[ :mx 0.5 :ry 40  2 red 1  0 1 0  0.5 ; 16 blue 1  1 0.5 0  0.3 0.5 0.3 ; ]");
    std::string with_part = scene(":mx 0.5 :ry 40  thing ;");
    with_part += "obj thing [ 2 red 1  0 1 0  0.5 ; 16 blue 1  1 0.5 0  0.3 0.5 0.3 ; ]\n";
    check_pair(inline_objs, with_part, 0);
  }
  SECTION("#define = its expansion") {
    check_pair(scene("2 red 1  0.3 1 0  1 ;"),
               "#define CENTRE 0.3 1 0\n#define R 1\n" + scene("2 red 1  CENTRE R ;"), 0);
  }
  SECTION("object light = the same light as a statement at the moved place") {
    std::string a = scene("[ :mx 1 :my 2  -2  0 0 0  1 0.8 0.5  3 ; ] 2 red 1  0 1 0  0.6 ;");
    std::string b = scene("2 red 1  0 1 0  0.6 ;");
    b += "p_light [ 1 2 0  1 0.8 0.5  3 ; ]\n";
    check_pair(a, b, 0);
  }
}

TEST_CASE("eastray: #include = the inlined text, <file> from EASTRAY", "[eastray]") {
  const std::string dir = temp_dir();
  write(dir + "/sub.h", "#define R 0.8\n2 red 1  0 1 0  R ;\n");
  mkdir((dir + "/sys").c_str(), 0755);
  write(dir + "/sys/colors.h", "color [ red 0.9 0.1 0.1  0 0 0  0 0 0  1 1  0  0 0.5 20 ;\n"
                               " grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\n");
  const std::string head =
      "display 64 48 0 0 63 47 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\ncamera 0 2.5 9  0 1 0  0 10 0  25 0 ;\n"
      "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\ne_light [ -1 1 1  1 1 1  0 1 ; ]\n";
  write(dir + "/inc.ray", head + "#include <colors.h>\nobj [ 1 grey 1  0 0 0  0 1 0 ;\n#include \"sub.h\"\n]\n");
  write(dir + "/flat.ray", head + "color [ red 0.9 0.1 0.1  0 0 0  0 0 0  1 1  0  0 0.5 20 ;\n"
                                  " grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\n"
                                  "obj [ 1 grey 1  0 0 0  0 1 0 ;\n2 red 1  0 1 0  0.8 ;\n]\n");
  setenv("EASTRAY", (dir + "/sys").c_str(), 1);
  const auto a = render_file(dir + "/inc.ray"), b = render_file(dir + "/flat.ray");
  CHECK(a.rgb == b.rgb);
  // Nested includes and a cycle.
  write(dir + "/a.h", "#include \"b.h\"\n");
  write(dir + "/b.h", "#include \"a.h\"\n");
  minrt::host::ExpandedEastray x;
  std::string error;
  CHECK_FALSE(minrt::host::preprocess_eastray(dir + "/top.ray", "top.ray", "#include \"a.h\"\n", x, error));
  CHECK(error.find("cycle") != std::string::npos);
  CHECK(error.find("b.h:1:") != std::string::npos);
  // Macros expand whole names only and are not expanded inside comments.
  CHECK(minrt::host::preprocess_eastray(dir + "/m.ray", "m.ray", "#define A 1 2\nA AB /* A */ xA\n", x, error));
  CHECK(x.text == "\n1 2 AB         xA\n");
  CHECK(x.where(2) == "m.ray:2");
  unsetenv("EASTRAY");
}

// ---------------------------------------------------------- invalid scenes

TEST_CASE("eastray: invalid scenes get a located one-line error, status 2, no file", "[eastray]") {
  const std::string dir = temp_dir();
  const std::string head =
      "display 32 24 0 0 31 23 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\ncamera 0 2 9  0 1 0  0 10 0  25 0 ;\n"
      "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\n"
      "color [ grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\n";  // 7 lines
  struct Case {
    const char* name;
    std::string text;
    const char* where;    // FILE:LINE:COL expected at the start
    const char* message;  // a part of the message
  };
  const std::vector<Case> cases = {
      {"no-main", head + "obj part [ 2 0 1  0 1 0  1 ; ]\n", "no-main.ray:9:1:", "no main object"},
      {"recursive", head + "obj [ a ; ]\nobj a [ b ; ]\nobj b [ 2 0 1 0 1 0 1 ; a ; ]\n", "recursive.ray:10:", "recursive call"},
      {"self-call", head + "obj [ a ; ]\nobj a [ a ; ]\n", "self-call.ray:9:9:", "recursive call"},
      {"range-kind", head + "obj [ ( 15  0 1 0  0 1 0  1 1 ; 2 0 1  0 1 0  0.5 ; ) ]\n", "range-kind.ray:8:9:", "kind 0 to 8"},
      {"undefined-vertex", head + "obj [ 20 0 1 < p 1 0 0 0  p 2 1 0 0  p 3 0 1 0  P 1 2 4 ; > ; ]\n",
       "undefined-vertex.ray:8:55:", "undefined vertex 4"},
      {"unterminated", head + "obj [ 2 0 1  0 1 0  1 ;\n  { 2 0 1  0 1 0  1 ;\n", "unterminated.ray:9:3:", "unterminated block"},
      {"unknown-statement", head + "lamp [ 1 2 3 ] ;\nobj [ ]\n", "unknown-statement.ray:8:1:", "unknown statement 'lamp'"},
      {"missing-include", head + "#include \"nothere.h\"\nobj [ ]\n", "missing-include.ray:8:10:", "nothere.h"},
      {"bad-number", head + "obj [ 2 0 1  0 1x 0  1 ; ]\n", "bad-number.ray:8:16:", "expected a number"},
      {"undefined-colour", head + "obj [ 2 gold 1  0 1 0  1 ; ]\n", "undefined-colour.ray:8:9:", "undefined colour 'gold'"},
      {"undefined-part", head + "obj [ table ; ]\n", "undefined-part.ray:8:7:", "undefined part 'table'"},
      {"duplicate-vertex", head + "obj [ 20 0 1 < p 1 0 0 0  p 2 1 0 0\n  p 1 0 1 0  P 1 2 1 ; > ; ]\n",
       "duplicate-vertex.ray:9:5:", "defined twice: 1"},
      {"short-face", head + "obj [ 20 0 1 < p 1 0 0 0  p 2 1 0 0  P 1 2 ; > ; ]\n", "short-face.ray:8:", "at least 3 vertices"},
      {"unterminated-comment", head + "/* open\nobj [ ]\n", "unterminated-comment.ray:8:1:", "unterminated comment"},
      {"missing-semicolon", "display 32 24 0 0 31 23 1 1 1\ncondition 4 0.01 0.00001 0 ;\n", "missing-semicolon.ray:2:1:", "expected ';'"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string path = dir + "/" + c.name + ".ray";
    write(path, c.text);
    const std::string out = dir + "/" + c.name + ".png";
    const Run r = run_minrt("-o " + out + " " + c.name + ".ray", dir);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind(c.where, 0) == 0);
    CHECK(r.err.find(c.message) != std::string::npos);
    CHECK(r.err.find(": error: ") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(out));
  }
}

TEST_CASE("eastray: output names: -o, the output statement, .tif through libtiff, .fal refused", "[eastray]") {
  if (!have_shared()) return;
  const std::string dir = temp_dir();
  std::string text = minrt::test::read_file(ea_dir() + "basic_sphere_floor_elight.ray");
  write(dir + "/t.ray", text + "\noutput pic.tif ;\n");
  write(dir + "/f.ray", text + "\noutput old.fal ;\n");
  CHECK(run_minrt("t.ray", dir).status == 0);
  const std::string tif = minrt::test::read_file(dir + "/pic.tif");
  REQUIRE(tif.size() > 160 * 120 * 3);
  CHECK((tif.compare(0, 4, "II*\0", 4) == 0 || tif.compare(0, 4, "MM\0*", 4) == 0));
  // .fal, .ipr, .hpi: no library writes them; an error names the formats written.
  const Run f = run_minrt("f.ray", dir);
  CHECK(f.status == 2);
  CHECK(f.err.find("error: cannot write old.fal") != std::string::npos);
  CHECK(f.err.find(".tif") != std::string::npos);
  CHECK_FALSE(exists(dir + "/old.png"));
  CHECK_FALSE(exists(dir + "/old.fal"));
  CHECK(run_minrt("-o mine.png t.ray", dir).status == 0);
  CHECK(exists(dir + "/mine.png"));
  bool tiff = false;
  std::string warning;
  CHECK(minrt::host::eastray_output_name("", "", "dir/scene.ray", tiff, warning) == "dir/scene.png");
  CHECK_FALSE(tiff);
}

// ------------------------------------------------------ the finite kinds

TEST_CASE("eastray: finite kinds 10-15 = AND of the infinite surface and the cut planes", "[eastray]") {
  // Axis (1 2 0.5) through (0 1 0): not along any world axis, with caps.
  const std::string c = "0 1 0  1 2 0.5  ";
  auto planes = [](double lo, double hi) {
    // centre + h * unit axis; unit axis = (1 2 0.5) / 2.2913...
    const double n = std::sqrt(1.0 + 4.0 + 0.25);
    auto pt = [&](double h) {
      char b[96];
      std::snprintf(b, sizeof b, "%.17g %.17g %.17g", h / n, 1.0 + 2.0 * h / n, 0.5 * h / n);
      return std::string(b);
    };
    return "1 red 1  " + pt(hi) + "  1 2 0.5 ;  1 red 1  " + pt(lo) + "  -1 -2 -0.5 ;";
  };
  SECTION("kind 11 (both nappes, cut at +-h)") {
    check_pair(scene("11 red 1  " + c + "0.5 0.9 ;"), scene("{ 4 red 1  " + c + "0.5 ; " + planes(-0.9, 0.9) + " }"));
  }
  SECTION("kind 10 (one nappe on the vector side)") {
    check_pair(scene("10 red 1  " + c + "0.5 0.9 ;"), scene("{ 4 red 1  " + c + "0.5 ; " + planes(0.0, 0.9) + " }"));
  }
  SECTION("kind 14 (one-sheet hyperboloid, length 2h)") {
    check_pair(scene("14 red 1  " + c + "0.5 0.3 0.8 ;"),
               scene("{ 7 red 1  " + c + "0.5 0.3 ; " + planes(-0.8, 0.8) + " }"));
  }
  SECTION("kind 13 (both sheets cut at +-h)") {
    check_pair(scene("13 red 1  " + c + "0.8 0.3 0.9 ;"),
               scene("{ 8 red 1  " + c + "0.8 0.3 ; " + planes(-0.9, 0.9) + " }"));
  }
  SECTION("kind 12 (the sheet on the vector side)") {
    check_pair(scene("12 red 1  " + c + "0.8 0.3 0.9 ;"),
               scene("{ 8 red 1  " + c + "0.8 0.3 ; " + planes(0.0, 0.9) + " }"));
  }
  SECTION("kind 15 with a tilted axis") {
    check_pair(scene("15 red 1  " + c + "0.4 0.7 ;"), scene("{ 5 red 1  " + c + "0.4 ; " + planes(-0.7, 0.7) + " }"));
  }
  SECTION("face colours: r side, t at +h, b at -h") {
    const auto im = render_text(scene("15 grey 1  0 1 0  0 1 0  0.8 0.5  r red  t blue  b red ;"));
    CHECK(bluish(px(im, 48, 30)));  // the top cap, seen from above
    CHECK(reddish(px(im, 48, 38)));
  }
}

// ------------------------------------------------------- analytic checks

namespace {
std::string lit(const std::string& settings, const std::string& lights, const std::string& colors,
                const std::string& objects) {
  return "display 64 48 0 0 63 47 1 1 1 ;\ncamera 0 0 10  0 0 0  0 10 0  20 0 ;\nsky 0 0 0 ;\n" + settings +
         lights + "color [ " + colors + " ]\nobj [ " + objects + " ]\n";
}
}  // namespace

TEST_CASE("eastray: shading laws", "[eastray]") {
  const std::string matte = "m 0.8 0.5 0.25  0 0 0  0 0 0  1 1  0  0 0 1 ;";
  SECTION("env only: pixel = env x diffuse") {
    const auto im = render_text(lit("condition 4 0.01 0.00001 0 ;\nenv 0.5 0.5 1 ;\n", "", matte, "2 m 1  0 0 0  2 ;"));
    const Rgb c = px(im, 32, 24);
    CHECK(c.r == static_cast<int>(0.8 * 0.5 * 255));
    CHECK(c.g == static_cast<int>(0.5 * 0.5 * 255));
    CHECK(c.b == static_cast<int>(0.25 * 255));
  }
  SECTION("point light: half the light one half distance farther") {
    // A wall facing the light head on: intensity 2^(-d/h) times cos = 1.
    auto wall_at = [&](double d) {
      const std::string lights = "p_light [ 0 0 " + std::to_string(d) + "  1 1 1  2 ; ]\n";
      return px(render_text(lit("condition 1 0.01 0.00001 0 ;\nenv 0 0 0 ;\n", lights,
                                "w 1 1 1  0 0 0  0 0 0  1 1  0  0 0 1 ;", "1 w 1  0 0 0  0 0 1 ;")),
                32, 24);
    };
    const Rgb near = wall_at(1), far = wall_at(3);
    CHECK(std::abs(near.r - static_cast<int>(255 * 0.70710678)) <= 1);  // 2^(-1/2)
    CHECK(std::abs(far.r - static_cast<int>(255 * 0.35355339)) <= 1);   // 2^(-3/2)
  }
  SECTION("mist: half the colour at the half distance, toward the sky with sw 1") {
    const std::string wall = "1 w 1  0 0 0  0 0 1 ;";  // 10 away from the eye
    const std::string white = "w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";  // constant 1
    const auto dim = render_text(lit("condition 1 0.01 0.00001 0 ;\nenv 0 0 0 ;\nmist 10 0 ;\n", "", white, wall));
    CHECK(px(dim, 32, 24).r == 127);
    const auto fog = render_text(
        "display 64 48 0 0 63 47 1 1 1 ;\ncamera 0 0 10  0 0 0  0 10 0  20 0 ;\nsky 0 0 1 ;\ncondition 1 0.01 0.00001 0 ;\n"
        "env 0 0 0 ;\nmist 10 1 ;\ncolor [ " + white + " ]\nobj [ " + wall + " ]\n");
    const Rgb f = px(fog, 32, 24);
    CHECK(f.r == 127);
    CHECK(f.b == 255);
  }
  SECTION("transparency: light inside a body halves every half distance") {
    // A clear slab 1 thick (ior 1: no bending, no Fresnel loss) in front of
    // a constant white wall: half distance 1 gives half the white, 0.5 a
    // quarter.
    auto through = [&](const char* half) {
      const std::string colors = std::string("slab 0 0 0  0 0 0  1 1 1  1 ") + half +
                                 "  0  0 0 1 ;  white 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
      return px(render_text(lit("condition 4 0 0.00001 0 ;\nenv 0 0 0 ;\n", "", colors,
                                "16 slab 1  0 0 0  3 3 0.5 ;  1 white 1  0 0 -3  0 0 1 ;")),
                32, 24);
    };
    CHECK(std::abs(through("1").r - 127) <= 1);
    CHECK(std::abs(through("0.5").r - 63) <= 1);
  }
  SECTION("condition 0 and 1: no reflection; 2: one") {
    const std::string colors = "mirror 0 0 0  1 1 1  0 0 0  1 1  0  0 0 1 ;  red 1 0 0  0 0 0  0 0 0  1 1  0  0 0 1 ;";
    // A mirror at 45 degrees sends the centre ray up to a red ball out of view.
    const std::string objs = "1 mirror 1  0 0 0  0 1 1 ;  2 red 1  0 5 0  1 ;";
    auto centre = [&](int depth) {
      return px(render_text(lit("condition " + std::to_string(depth) + " 0.01 0.00001 0 ;\nenv 1 1 1 ;\n", "", colors, objs)),
                32, 24);
    };
    CHECK(centre(0).sum() == 0);
    CHECK(centre(1).sum() == 0);
    CHECK(reddish(centre(2)));
  }
  SECTION("transmit 0 is a pure mirror; Fresnel splits otherwise") {
    // The 45-degree plane of the previous section, as a mirror and as glass:
    // glass reflects only the Fresnel share (about 5 % at 45 degrees, ior 1.5).
    auto centre = [&](const std::string& plane) {
      const std::string colors = plane + "  red 1 0 0  0 0 0  0 0 0  1 1  0  0 0 1 ;";
      return px(render_text(lit("condition 3 0 0.00001 0 ;\nenv 1 1 1 ;\n", "", colors,
                                "1 g 1  0 0 0  0 1 1 ;  2 red 1  0 5 0  1 ;")),
                32, 24);
    };
    const Rgb mirror = centre("g 0 0 0  1 1 1  0 0 0  1.5 1  0  0 0 1 ;");
    const Rgb glass = centre("g 0 0 0  1 1 1  1 1 1  1.5 1  0  0 0 1 ;");
    CHECK(mirror.r == 255);
    CHECK(glass.r > 5);
    CHECK(glass.r < 30);
  }
  SECTION("antialiasing blends edge pixels only") {
    const std::string base = "condition 1 0.01 0.00001 0 ;\nenv 1 1 1 ;\n";
    const std::string colors = "w 1 1 1  0 0 0  0 0 0  1 1  0  0 0 1 ;";
    const auto plain = render_text(lit(base, "", colors, "2 w 1  0 0 0  1.7 ;"));
    const auto aa = render_text(lit(base + "anti 4 16 ;\n", "", colors, "2 w 1  0 0 0  1.7 ;"));
    const auto st = render_text(lit(base + "anti -1 16 ;\n", "", colors, "2 w 1  0 0 0  1.7 ;"));
    int grey_plain = 0, grey_aa = 0, grey_st = 0;
    for (std::size_t i = 0; i < plain.rgb.size(); i += 3) {
      grey_plain += plain.rgb[i] != 0 && plain.rgb[i] != 255;
      grey_aa += aa.rgb[i] != 0 && aa.rgb[i] != 255;
      grey_st += st.rgb[i] != 0 && st.rgb[i] != 255;
    }
    CHECK(grey_plain == 0);
    CHECK(grey_aa > 20);
    CHECK(grey_st > 20);
    CHECK(px(aa, 32, 24).r == 255);  // interior untouched
    CHECK(px(aa, 2, 2).r == 0);
  }
  SECTION("specular models 1 and 4 put a highlight where the half vector is the normal") {
    // Light and eye both on +z: the highlight sits at the sphere's centre.
    for (const char* spec : {"0 1 40", "1 1 1 1  8 0.9", "4 1 1 1  0.5 8 3"}) {
      INFO(spec);
      const std::string colors = std::string("s 0.2 0.2 0.2  0 0 0  0 0 0  1 1  0  ") + spec + " ;";
      const auto im = render_text(lit("condition 1 0.01 0.00001 0 ;\nenv 0 0 0 ;\n", "e_light [ 0 0 1  1 1 1  0 1 ; ]\n",
                                      colors, "2 s 1  0 0 0  2 ;"));
      const Rgb mid = px(im, 32, 24), side = px(im, 32 + 12, 24);
      CHECK(mid.r > 200);
      CHECK(side.r < mid.r - 60);
    }
  }
}

// The files of test/eastray/eastray_bad (also sent to the board by the
// firmware tests): each names its expected message in its header comment.
TEST_CASE("eastray: the invalid scene files are refused by minrt and by host-send before sending", "[eastray]") {
  const std::string dir = EASTRAY_BAD_DIR;
  const char* names[] = {"bad-number", "missing-semicolon", "no-main", "range-kind", "recursive-part",
                         "short-face", "undefined-colour", "undefined-vertex", "unknown-statement", "unterminated-block"};
  const std::string out_dir = temp_dir();
  for (const char* n : names) {
    INFO(n);
    const std::string file = std::string(n) + ".ray";
    const std::string text = minrt::test::read_file(dir + "/" + file);
    const std::size_t e = text.find("expect: ");
    REQUIRE(e != std::string::npos);
    const std::string expect = text.substr(e + 8, text.find(" */", e) - e - 8);
    const std::string out = out_dir + "/" + n + ".png";
    const Run r = run_minrt("-o " + out + " " + file, dir);
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK(r.err.rfind(file + ":" + expect, 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(out));
    // host-send checks the scene with the board's reader before it starts
    // a link, whatever the protocol: the same located message, no image.
    char errf[] = "/tmp/minrt-ea-send-XXXXXX";
    const int fd = mkstemp(errf);
    REQUIRE(fd >= 0);
    close(fd);
    for (const char* protocol : {"raw", "course", "framed"}) {
      INFO(protocol);
      const int rc = std::system(("cd '" + dir + "' && " + std::string(MINRT_SEND_BIN) + " --sim --protocol " + protocol +
                                  " " + file + " -o " + out + " 2>" + errf + " </dev/null >/dev/null").c_str());
      const std::string err = minrt::test::read_file(errf);
      INFO(err);
      CHECK((WIFEXITED(rc) && WEXITSTATUS(rc) != 0));
      CHECK(err.find("scene rejected before sending: " + file + ":" + expect) != std::string::npos);
      CHECK_FALSE(exists(out));
    }
    std::remove(errf);
  }
}

TEST_CASE("eastray: a closed polygon cube = the box, also as glass and mirrored", "[eastray]") {
  const std::string mesh =
      "< p 0 -0.5 0.5 -0.5  p 1 0.5 0.5 -0.5  p 2 0.5 1.5 -0.5  p 3 -0.5 1.5 -0.5"
      "  p 4 -0.5 0.5 0.5  p 5 0.5 0.5 0.5  p 6 0.5 1.5 0.5  p 7 -0.5 1.5 0.5"
      "  P 4 5 6 7 ;  P 1 0 3 2 ;  P 5 1 2 6 ;  P 0 4 7 3 ;  P 7 6 2 3 ;  P 0 1 5 4 ; > ;";
  SECTION("opaque") {
    check_pair(scene("16 :ry 25 red 1  0 1 0  0.5 0.5 0.5 ;"), scene("20 :ry 25 red 1 " + mesh), 8);
  }
  SECTION("glass: refraction through a closed mesh") {
    const std::string glass =
        "color [ glass 0 0 0  1 1 1  1 1 1  1.5 2  0  0 0 1 ; ]\n";
    const std::string deep = "condition 6 0 0.00001 1 ;\n";
    check_pair(deep + glass + scene("2 blue 1  0.3 0.6 -2  0.6 ; 16 :ry 25 glass 1  0 1 0  0.5 0.5 0.5 ;"),
               deep + glass + scene("2 blue 1  0.3 0.6 -2  0.6 ; 20 :ry 25 glass 1 " + mesh), 12);
    // The same cube through a mirroring move (winding turns clockwise).
    check_pair(deep + glass + scene("2 blue 1  0.3 0.6 -2  0.6 ; 20 :ry 25 glass 1 " + mesh),
               deep + glass + scene("2 blue 1  0.3 0.6 -2  0.6 ; 20 :ry 25 :sx -1 glass 1 " + mesh), 12);
  }
}
