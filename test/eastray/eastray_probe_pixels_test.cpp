// EASTRAY probes: pixels whose colour follows by hand
// from the manual's statements and the formulas docs/eastray.md chose where
// the manual gives none (value x 255, clamped, truncated). Camera on +z
// looking at the origin, odd image sizes so the centre pixel looks straight
// down the view line.
#include "eastray_probe_support.hpp"

using namespace eprobe;

namespace {

const double kPi = 3.14159265358979323846;

// 41x31 from (0 0 10) toward the origin; sky black unless given.
std::string probe_scene(const std::string& settings, const std::string& colors, const std::string& objects,
                        const std::string& camera = "camera 0 0 10  0 0 0  0 10 0  20 0 ;\n") {
  return "display 41 31 0 0 40 30 1 1 1 ;\n" + camera + settings + "color [ " + colors + " ]\nobj [ " + objects + " ]\n";
}
const char* kMatte = "m 0.6 0.7 0.3  0 0 0  0 0 0  1 1  0  0 0 1 ;";  // diffuse only
const char* kBase = "condition 1 0.01 0.00001 0 ;\nsky 0 0 0 ;\n";

Rgb centre(const EastrayImage& im) { return px(im, im.width / 2, im.height / 2); }

void expect(Rgb got, double r, double g, double b) {
  INFO("got " << got.r << " " << got.g << " " << got.b << ", expected " << r * 255 << " " << g * 255 << " "
              << b * 255);
  CHECK(byte_is(got.r, r));
  CHECK(byte_is(got.g, g));
  CHECK(byte_is(got.b, b));
}

}  // namespace

TEST_CASE("eastray probe: a lit sphere's centre pixel under each light kind", "[eastray][eprobe]") {
  // Sphere radius 1 at the origin: the centre pixel sees (0 0 1), normal +z.
  const std::string sphere = "2 m 1  0 0 0  1 ;";
  const double dr = 0.6, dg = 0.7, db = 0.3;
  SECTION("e_light toward the eye: env + light, n.L = 1") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0.1 0.2 0.3 ;\ne_light [ 0 0 1  0.5 0.9 0.4  0 1 ; ]\n",
                                       kMatte, sphere));
    expect(centre(im), dr * (0.1 + 0.5), dg * (0.2 + 0.9), db * (0.3 + 0.4));
  }
  SECTION("e_light at 60 degrees: n.L = cos 60; an unnormalised vector") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ne_light [ 0 3 1.7320508075688772  1 1 1  0 1 ; ]\n",
                                       kMatte, sphere));
    expect(centre(im), dr * 0.5, dg * 0.5, db * 0.5);
  }
  SECTION("e_light from behind: only env") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0.3 0.3 0.3 ;\ne_light [ 0 0 -1  1 1 1  0 1 ; ]\n",
                                       kMatte, sphere));
    expect(centre(im), dr * 0.3, dg * 0.3, db * 0.3);
  }
  SECTION("p_light 3 away with half distance 3, 6 and none") {
    for (double half : {3.0, 6.0, 0.0}) {
      INFO("half " << half);
      const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\np_light [ 0 0 4  1 1 1  " + num(half) + " ; ]\n",
                                         kMatte, sphere));
      const double k = half > 0 ? std::pow(2.0, -3.0 / half) : 1.0;
      expect(centre(im), dr * k, dg * k, db * k);
    }
  }
  SECTION("p_light off the axis: n.L from its position, fall-off from its distance") {
    // light at (0 4 1): 4 above the point (0 0 1): n.L = 0, so only env.
    // light at (0 3 4): d = sqrt(9 + 9), n.L = 3 / d.
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\np_light [ 0 3 4  1 1 1  5 ; ]\n", kMatte, sphere));
    const double d = std::sqrt(18.0), k = std::pow(2.0, -d / 5) * 3 / d;
    expect(centre(im), dr * k, dg * k, db * k);
  }
  SECTION("s_light on its axis = p_light; off its axis cos^spread") {
    // Aimed at the sphere's centre from (0 0 4): the centre pixel is on the axis.
    const auto on = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ns_light [ 0 0 4  0 0 0  1 1 1  8 3 ; ]\n", kMatte, sphere));
    expect(centre(on), dr * 0.5, dg * 0.5, db * 0.5);
    // Aimed at (0 3 1) from (0 0 4): the beam axis is (0 3 -3)/|..|, the
    // light->point direction (0 0 -1): cos alpha = 1/sqrt 2; spread 4: 1/4.
    const auto off = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ns_light [ 0 0 4  0 3 1  1 1 1  4 0 ; ]\n", kMatte, sphere));
    expect(centre(off), dr * 0.25, dg * 0.25, db * 0.25);
    // Aimed away (more than 90 degrees): dark.
    const auto away = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ns_light [ 0 0 4  0 0 8  1 1 1  1 0 ; ]\n", kMatte, sphere));
    expect(centre(away), 0, 0, 0);
  }
  SECTION("the spot on a wall: cos^(spread+1) of the angle, column by column") {
    // Wall z = 0 facing +z, spot at (0 0 5) aimed at the origin, no
    // fall-off: a point x along the wall gets cos^spread (beam) x cos (n.L)
    // with cos = 5/sqrt(x^2+25). Column c looks at x = 10 (2(c+0.5)/41 - 1) tan 20.
    const std::string colors = "w 1 1 1  0 0 0  0 0 0  1 1  0  0 0 1 ;";
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ns_light [ 0 0 5  0 0 0  1 1 1  6 0 ; ]\n", colors,
                                       "1 w 1  0 0 0  0 0 1 ;"));
    for (int col : {20, 26, 33, 40}) {
      const double x = 10 * (2 * (col + 0.5) / 41 - 1) * std::tan(20 * kPi / 180);
      const double cs = 5 / std::sqrt(x * x + 25);
      INFO("column " << col);
      expect(px(im, col, 15), std::pow(cs, 7), std::pow(cs, 7), std::pow(cs, 7));
    }
  }
  SECTION("object lights: -2 moved onto the axis = p_light there") {
    // :rx 90 takes (0 -2 0) to (0 0 -2) (right-handed, line 8); :mz 6 then to (0 0 4).
    const auto at = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\n", kMatte,
                                       "[ :mz 6 :rx 90  -2  0 -2 0  1 1 1  3 ; ] " + sphere));
    expect(centre(at), dr * 0.5, dg * 0.5, db * 0.5);
  }
}

TEST_CASE("eastray probe: ambient, sky, mist, specular, Fresnel, mirror", "[eastray][eprobe]") {
  SECTION("sky at every missed pixel, env x diffuse on the object, nothing else") {
    const auto im = render(probe_scene("condition 1 0.01 0.00001 0 ;\nsky 0.3 0.5 0.7 ;\nenv 0.9 0.6 0.3 ;\n", kMatte,
                                       "2 m 1  0 0 0  1 ;"));
    expect(px(im, 0, 0), 0.3, 0.5, 0.7);
    expect(px(im, 40, 30), 0.3, 0.5, 0.7);
    expect(centre(im), 0.6 * 0.9, 0.7 * 0.6, 0.3 * 0.3);
    expect(px(im, 20 + 3, 15 - 2), 0.6 * 0.9, 0.7 * 0.6, 0.3 * 0.3);  // flat: no light, no shading
  }
  SECTION("mist without and with the sky: sphere front 9 away, half 3 -> 1/8") {
    const std::string white = "w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";  // constant 1
    const auto dim = render(probe_scene("condition 1 0.01 0.00001 0 ;\nsky 0.4 0.2 0.8 ;\nenv 0 0 0 ;\nmist 3 0 ;\n", white,
                                        "2 w 1  0 0 0  1 ;"));
    expect(centre(dim), 0.125, 0.125, 0.125);
    expect(px(dim, 0, 0), 0.4, 0.2, 0.8);  // missed rays: the sky unchanged
    const auto fog = render(probe_scene("condition 1 0.01 0.00001 0 ;\nsky 0.4 0.2 0.8 ;\nenv 0 0 0 ;\nmist 3 1 ;\n", white,
                                        "2 w 1  0 0 0  1 ;"));
    expect(centre(fog), 0.125 + 0.4 * 0.875, 0.125 + 0.2 * 0.875, 0.125 + 0.8 * 0.875);
  }
  SECTION("mist counts the air only, not the inside of a clear body") {
    // Eye at z 10, a slab of ior 1 from z 0.5 to -0.5, a constant white
    // wall at z -5: 9.5 + 4.5 = 14 of air, half 7: 1/4 (1 inside the slab
    // would make it 2^(-15/7)). Transparency 0 (no absorption) and 1e6.
    for (const char* transparency : {"0", "1000000"}) {
      INFO("transparency " << transparency);
      const std::string colors = std::string("g 0 0 0  1 1 1  1 1 1  1 ") + transparency +
                                 "  0  0 0 1 ;  w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
      const auto im = render(probe_scene("condition 4 0 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\nmist 7 0 ;\n", colors,
                                         "16 g 1  0 0 0  5 5 0.5 ;  1 w 1  0 0 -5  0 0 1 ;"));
      expect(centre(im), 0.25, 0.25, 0.25);
    }
  }
  SECTION("Blinn (model 0) with light and eye on the axis: intensity x 1^n, white") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ne_light [ 0 0 1  1 1 1  0 1 ; ]\n",
                                       "s 0.2 0.3 0.1  0 0 0  0 0 0  1 1  0  0 0.35 30 ;", "2 s 1  0 0 0  1 ;"));
    expect(centre(im), 0.2 + 0.35, 0.3 + 0.35, 0.1 + 0.35);
  }
  SECTION("Blinn-Gaussian (model 1) at h = n: D = G = 1, F = the Fresnel constant, n.v = 1") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ne_light [ 0 0 1  1 1 1  0 1 ; ]\n",
                                       "s 0.2 0.2 0.2  0 0 0  0 0 0  1 1  0  1 0.5 0.4 0.3  8 0.6 ;", "2 s 1  0 0 0  1 ;"));
    expect(centre(im), 0.2 + 0.5 * 0.6, 0.2 + 0.4 * 0.6, 0.2 + 0.3 * 0.6);
  }
  SECTION("Cook-Torrance (model 4) at h = n: F = rgb, Beckmann D = spread^2 / pi, G = 1, / 4") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\ne_light [ 0 0 1  1 1 1  0 1 ; ]\n",
                                       "s 0.2 0.2 0.2  0 0 0  0 0 0  1 1  0  4 0.5 0.3 0.2  0.5 1 2 ;", "2 s 1  0 0 0  1 ;"));
    const double k = (0.5 * 1 + 0.5 * 4) / kPi / 4;
    expect(centre(im), 0.2 + 0.5 * k, 0.2 + 0.3 * k, 0.2 + 0.2 * k);
  }
  SECTION("constant shading (model 5): color1 at the centre whatever the light") {
    const auto im = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\n",
                                       "c 0 0 0  0 0 0  0 0 0  1 1  0  5 0.9 0.5 0.1  0.1 0.2 0.3  2 ;", "2 c 1  0 0 0  1 ;"));
    expect(centre(im), 0.9, 0.5, 0.1);
  }
  SECTION("a pure mirror (transmit 0) facing the eye shows what is behind the eye, times reflect") {
    // Mirror plane z = 0; a constant white wall at z = 20 facing -z, behind
    // the eye, which primary rays never reach.
    const std::string colors =
        "mir 0 0 0  0.65 0.45 0.25  0 0 0  1 1  0  0 0 1 ;  w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
    const auto im = render(probe_scene("condition 2 0.01 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\n", colors,
                                       "1 mir 1  0 0 0  0 0 1 ;  1 w 1  0 0 20  0 0 -1 ;"));
    expect(centre(im), 0.65, 0.45, 0.25);
    expect(px(im, 3, 4), 0.65, 0.45, 0.25);
  }
  SECTION("an opaque colour's index of refraction is not used (line 554): 0 = 1") {
    const std::string lights = std::string(kBase) + "env 0.2 0.2 0.2 ;\ne_light [ 1 1 1  1 1 1  0 1 ; ]\n";
    CHECK(render(probe_scene(lights, "m 0.6 0.7 0.3  0.3 0.3 0.3  0 0 0  0 1  0  0 0.5 9 ;", "2 m 1  0 0 0  1 ;")).rgb ==
          render(probe_scene(lights, "m 0.6 0.7 0.3  0.3 0.3 0.3  0 0 0  1 1  0  0 0.5 9 ;", "2 m 1  0 0 0  1 ;")).rgb);
  }
  SECTION("Fresnel at normal incidence: R = ((n-1)/(n+1))^2 for glass") {
    // A slab of ior 1.5 (R = 0.04) facing the eye: white wall behind the eye
    // reflected (0.04), black behind the slab, no internal branching.
    const std::string colors =
        "g 0 0 0  1 1 1  1 1 1  1.5 0  0  0 0 1 ;  w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
    const auto im = render(probe_scene("condition 4 0 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\n", colors,
                                       "16 g 1  0 0 0  5 5 0.5 ;  1 w 1  0 0 20  0 0 -1 ;"));
    expect(centre(im), 0.04, 0.04, 0.04);
    // ior 2: R = 1/9. Now a white wall behind the slab too: the light that
    // crosses both faces is (1 - R)^2 more.
    const std::string colors2 =
        "g 0 0 0  1 1 1  1 1 1  2 0  0  0 0 1 ;  w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
    const auto im2 = render(probe_scene("condition 4 0 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\n", colors2,
                                        "16 g 1  0 0 0  5 5 0.5 ;  1 w 1  0 0 20  0 0 -1 ;  1 w 1  0 0 -5  0 0 1 ;"));
    const double r = 1.0 / 9;
    expect(centre(im2), r + (1 - r) * (1 - r), r + (1 - r) * (1 - r), r + (1 - r) * (1 - r));
  }
}

TEST_CASE("eastray probe: the camera's FOV is the horizontal half angle", "[eastray][eprobe]") {
  // A wall z = 0 (10 from the eye), red left of x = X, blue right of it.
  // With half angle f, column c's centre looks at x = 10 (2(c+0.5)/W - 1) tan f;
  // X between the centres of columns 0 and 1 makes column 0 red, 1 blue.
  const int w = 41, h = 31;
  for (double fov : {15.0, 30.0, 50.0}) {
    DYNAMIC_SECTION("fov " << fov) {
      const double t = std::tan(fov * kPi / 180);
      const double x_edge = 10 * (2 * 1.0 / w - 1) * t;  // the border of columns 0 and 1
      const double tv = t * h / w;                        // vertical half angle's tangent
      const double y_edge = 10 * (1 - 2 * 1.0 / h) * tv;  // the border of rows 0 and 1
      const std::string colors =
          "r 0 0 0  0 0 0  0 0 0  1 1  0  5 1 0 0  1 0 0  0 ;  b 0 0 0  0 0 0  0 0 0  1 1  0  5 0 0 1  0 0 1  0 ;"
          "  g 0 0 0  0 0 0  0 0 0  1 1  0  5 0 1 0  0 1 0  0 ;";
      const std::string objs = "{ 1 r 1  0 0 0  0 0 1 ;  1 r 1  " + num(x_edge) + " 0 0  1 0 0 ; }"
                               "  { 1 b 1  0 0 0  0 0 1 ;  1 b 1  " + num(x_edge) + " 0 0  -1 0 0 ;  1 b 1  0 " +
                               num(y_edge) + " 0  0 1 0 ; }"
                               "  { 1 g 1  0 0 0  0 0 1 ;  1 g 1  " + num(x_edge) + " 0 0  -1 0 0 ;  1 g 1  0 " +
                               num(y_edge) + " 0  0 -1 0 ; }";
      const auto im = render("display 41 31 0 0 40 30 1 1 1 ;\ncamera 0 0 10  0 0 0  0 10 0  " + num(fov) + " 0 ;\n" +
                             kBase + "env 0 0 0 ;\ncolor [ " + colors + " ]\nobj [ " + objs + " ]\n");
      for (int y : {5, 15, 25}) {
        INFO("row " << y);
        expect(px(im, 0, y), 1, 0, 0);
        expect(px(im, 1, y), 0, 0, 1);
      }
      expect(px(im, 20, 0), 0, 1, 0);   // row 0 above y_edge: green
      expect(px(im, 20, 1), 0, 0, 1);   // row 1 below: blue
      expect(px(im, 40, 30), 0, 0, 1);
    }
  }
  SECTION("dot aspect 2: dots twice as tall, so the vertical field is twice the tangent") {
    const double tv = std::tan(25 * kPi / 180) * 31 / 41 * 2;
    const double y_edge = 10 * (1 - 2 * 1.0 / 31) * tv;  // the border of rows 0 and 1
    const std::string colors =
        "b 0 0 0  0 0 0  0 0 0  1 1  0  5 0 0 1  0 0 1  0 ;  g 0 0 0  0 0 0  0 0 0  1 1  0  5 0 1 0  0 1 0  0 ;";
    const auto im = render("display 41 31 0 0 40 30 1 1 2 ;\ncamera 0 0 10  0 0 0  0 10 0  25 0 ;\n" + std::string(kBase) +
                           "env 0 0 0 ;\ncolor [ " + colors + " ]\nobj [ { 1 g 1  0 0 0  0 0 1 ;  1 g 1  0 " + num(y_edge) +
                           " 0  0 -1 0 ; }  { 1 b 1  0 0 0  0 0 1 ;  1 b 1  0 " + num(y_edge) + " 0  0 1 0 ; } ]\n");
    expect(px(im, 20, 0), 0, 1, 0);
    expect(px(im, 20, 1), 0, 0, 1);
    expect(px(im, 20, 30), 0, 0, 1);
  }
  SECTION("symmetric: the right edge with the wall mirrored") {
    const double t = std::tan(25 * kPi / 180);
    const double x_edge = 10 * (1 - 2 * 1.0 / 41) * t;  // between columns 39 and 40
    const std::string colors =
        "r 0 0 0  0 0 0  0 0 0  1 1  0  5 1 0 0  1 0 0  0 ;  b 0 0 0  0 0 0  0 0 0  1 1  0  5 0 0 1  0 0 1  0 ;";
    const auto im = render("display 41 31 0 0 40 30 1 1 1 ;\ncamera 0 0 10  0 0 0  0 10 0  25 0 ;\n" + std::string(kBase) +
                           "env 0 0 0 ;\ncolor [ " + colors + " ]\nobj [ { 1 r 1  0 0 0  0 0 1 ;  1 r 1  " + num(x_edge) +
                           " 0 0  -1 0 0 ; }  { 1 b 1  0 0 0  0 0 1 ;  1 b 1  " + num(x_edge) + " 0 0  1 0 0 ; } ]\n");
    expect(px(im, 40, 15), 1, 0, 0);
    expect(px(im, 39, 15), 0, 0, 1);
  }
  SECTION("the sub-look-at point sets up; it need not be perpendicular (line 115)") {
    // Up toward -x: the image turns a quarter; a red ball at +x is at the bottom.
    const auto im = render(probe_scene(std::string(kBase) + "env 1 1 1 ;\n", "r 1 0 0  0 0 0  0 0 0  1 1  0  0 0 1 ;",
                                       "2 r 1  2.5 0 0  0.6 ;", "camera 0 0 10  0 0 0  -3 0 4  20 0 ;\n"));
    CHECK(px(im, 20, 27).r > 200);
    CHECK(px(im, 20, 3).r == 0);
    CHECK(px(im, 33, 15).r == 0);
  }
}

TEST_CASE("eastray probe: display, condition, anti and shadow statements", "[eastray][eprobe]") {
  const std::string lit = "condition 1 0.01 0.00001 0 ;\nsky 0 0 0 ;\nenv 0.2 0.2 0.2 ;\ne_light [ 0 1 0  1 1 1  0 1 ; ]\n";
  const std::string floor_ball = "1 m 1  0 -1 0  0 1 0 ;  2 m 1  0 0.5 0  0.8 ;";
  const std::string cam = "camera 0 6 8  0 -1 0  0 10 0  25 0 ;\n";
  SECTION("shadow 1: the floor under the ball gets env only; shadow 0: full light") {
    const auto on = render(probe_scene(lit + "shadow 1 ;\n", kMatte, floor_ball, cam));
    const auto off = render(probe_scene(lit + "shadow 0 ;\n", kMatte, floor_ball, cam));
    // The floor right below the ball: find a pixel there by its values.
    int shadowed = 0;
    for (int y = 0; y < 31; ++y)
      for (int x = 0; x < 41; ++x) {
        const Rgb a = px(on, x, y), b = px(off, x, y);
        if (a.r != b.r) {
          ++shadowed;
          INFO("pixel " << x << " " << y);
          expect(a, 0.6 * 0.2, 0.7 * 0.2, 0.3 * 0.2);
          expect(b, 0.6 * 1.2, 0.7 * 1.2, 0.3 * 1.2);
        }
      }
    CHECK(shadowed > 10);
  }
  SECTION("a transparent ball's shadow: the light times transmit at each of its two surfaces") {
    const std::string colors = std::string(kMatte) + "  g 0 0 0  0 0 0  0.5 0.8 0.9  1 0  0  0 0 1 ;";
    const std::string balls = "1 m 1  0 -1 0  0 1 0 ;  2 g 1  0 0.5 0  0.8 ;";
    const auto on = render(probe_scene(lit + "shadow 1 ;\n", colors, balls, cam));
    const auto off = render(probe_scene(lit + "shadow 0 ;\n", colors, balls, cam));
    int shadowed = 0;
    for (int y = 0; y < 31; ++y)
      for (int x = 0; x < 41; ++x) {
        const Rgb a = px(on, x, y), b = px(off, x, y);
        if (a.r == b.r && a.g == b.g && a.b == b.b) continue;
        ++shadowed;
        INFO("pixel " << x << " " << y);
        expect(a, 0.6 * (0.2 + 0.25), 0.7 * (0.2 + 0.64), 0.3 * (0.2 + 0.81));
      }
    CHECK(shadowed > 10);
  }
  SECTION("display window outside the image: nothing would be computed (line 78), an error at the statement") {
    for (const char* d : {"display 41 31 0 0 41 30 1 1 1 ;\n", "display 41 31 5 0 4 30 1 1 1 ;\n",
                          "display 41 31 0 -1 40 30 1 1 1 ;\n"}) {
      INFO(d);
      EastrayImage im;
      std::string error;
      CHECK_FALSE(render_eastray("w.ray", d + cam + lit + "color [ " + kMatte + " ]\nobj [ " + floor_ball + " ]\n", {},
                                 im, error));
      CHECK(error.find("w.ray:1:") == 0);
      CHECK(error.find("display window") != std::string::npos);
    }
  }
  SECTION("steps that do not divide the image: 3x4 blocks, cut at the window") {
    const std::string text = "display 41 31 2 1 38 29 3 4 1 ;\n" + cam + lit + "color [ " + kMatte + " ]\nobj [ " +
                             floor_ball + " ]\n";
    const auto im = render(text);
    const auto full = render("display 41 31 0 0 40 30 1 1 1 ;\n" + cam + lit + "color [ " + kMatte + " ]\nobj [ " +
                             floor_ball + " ]\n");
    for (int y = 0; y < 31; ++y)
      for (int x = 0; x < 41; ++x) {
        const bool inside = x >= 2 && x <= 38 && y >= 1 && y <= 29;
        const Rgb c = px(im, x, y);
        INFO("pixel " << x << " " << y);
        if (!inside) {
          REQUIRE(c.r + c.g + c.b == 0);
          continue;
        }
        // the block's first pixel is traced (at its centre) and fills the block
        const int bx = 2 + (x - 2) / 3 * 3, by = 1 + (y - 1) / 4 * 4;
        const Rgb o = px(full, bx, by);
        REQUIRE((c.r == o.r && c.g == o.g && c.b == o.b));
      }
  }
  SECTION("anti on a picture with no edges changes nothing; on edges only near them") {
    const std::string flat_colors = "c 0 0 0  0 0 0  0 0 0  1 1  0  5 0.3 0.6 0.9  0.3 0.6 0.9  0 ;";
    const std::string wall = "1 c 1  0 0 0  0 0 1 ;";
    const auto plain = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\n", flat_colors, wall));
    for (const char* a : {"anti 3 1 ;\n", "anti -1 1 ;\n", "anti 0 0 ;\n"}) {
      INFO(a);
      const auto aa = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\n" + a, flat_colors, wall));
      CHECK(aa.rgb == plain.rgb);
    }
    // a level above every neighbour difference: no pixel is refined
    const std::string ball = "2 c 1  0 0 0  2 ;";
    const auto b0 = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\n", flat_colors, ball));
    const auto b1 = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\nanti 4 256 ;\n", flat_colors, ball));
    const auto b2 = render(probe_scene(std::string(kBase) + "env 0 0 0 ;\nanti 4 10 ;\n", flat_colors, ball));
    CHECK(b1.rgb == b0.rgb);
    CHECK(b2.rgb != b0.rgb);
    expect(centre(b2), 0.3, 0.6, 0.9);
  }
  SECTION("condition minweight: a reflection weaker than it is not traced") {
    const std::string colors =
        "mir 0 0 0  0.3 0.3 0.3  0 0 0  1 1  0  0 0 1 ;  w 0 0 0  0 0 0  0 0 0  1 1  0  5 1 1 1  1 1 1  0 ;";
    const std::string objs = "1 mir 1  0 0 0  0 0 1 ;  1 w 1  0 0 20  0 0 -1 ;";
    expect(centre(render(probe_scene("condition 2 0.2 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\n", colors, objs))), 0.3, 0.3, 0.3);
    expect(centre(render(probe_scene("condition 2 0.4 0.00001 0 ;\nsky 0 0 0 ;\nenv 0 0 0 ;\n", colors, objs))), 0, 0, 0);
  }
}

TEST_CASE("eastray probe: the e_light's disc seen in the sky (back_mode 0)", "[eastray][eprobe]") {
  // Looking straight at the light: sky + colour x cos(0)^conc; outside the
  // disc's angular radius only the sky; half way: cos(45 degrees)^conc.
  const auto im = render("display 41 31 0 0 40 30 1 1 1 ;\ncamera 0 0 0  0 0 -1  0 1 0  20 0 ;\n" + std::string(kBase) +
                         "env 0 0 0 ;\nsky 0.1 0.1 0.1 ;\ne_light [ 0 0 1  0.3 0.2 0.1  1 1 ;  0 0 -1  0.5 0.4 0.3  10 2 ; ]\n"
                         "color [ " + kMatte + " ]\nobj [ ]\n");
  expect(centre(im), 0.1 + 0.5, 0.1 + 0.4, 0.1 + 0.3);
  expect(px(im, 0, 0), 0.1, 0.1, 0.1);
  // column c's angle from the view line: atan((2(c+0.5)/41 - 1) tan 20)
  for (int col : {22, 25, 28}) {
    const double a = std::atan((2 * (col + 0.5) / 41 - 1) * std::tan(20 * kPi / 180)) * 180 / kPi;
    const double k = a < 10 ? std::pow(std::cos(a / 10 * kPi / 2), 2) : 0;
    INFO("column " << col << " angle " << a);
    expect(px(im, col, 15), 0.1 + 0.5 * k, 0.1 + 0.4 * k, 0.1 + 0.3 * k);
  }
}

TEST_CASE("eastray probe: every pixel of a lit sphere by hand (camera, normals, Lambert, Blinn)", "[eastray][eprobe]") {
  // The camera of docs/eastray.md: pixel (x, y) looks along
  // forward + sx right + sy up, sx = (2(x+1/2)/W - 1) tan f,
  // sy = (1 - 2(y+1/2)/H) tan f H/W; a sphere of radius 2 at the origin,
  // an e_light from the upper right front, Blinn n = 12.
  const int w = 41, h = 31;
  const double f = 20 * kPi / 180, tv = std::tan(f) * h / w;
  const Vec3 eye{0, 0, 10}, L0{1, 2, 2};
  const double ln = std::sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
  const Vec3 L{L0[0] / ln, L0[1] / ln, L0[2] / ln};
  const double d[3] = {0.6, 0.7, 0.3}, env = 0.1, spec = 0.3, shin = 12;
  const auto im = render(probe_scene(std::string(kBase) + "env 0.1 0.1 0.1 ;\ne_light [ 1 2 2  1 1 1  0 1 ; ]\n",
                                     "m 0.6 0.7 0.3  0 0 0  0 0 0  1 1  0  0 0.3 12 ;", "2 m 1  0 0 0  2 ;"));
  int hits = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Vec3 dir{(2 * (x + 0.5) / w - 1) * std::tan(f), (1 - 2 * (y + 0.5) / h) * tv, -1};
      const double dl = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
      for (double& c : dir) c /= dl;
      // |eye + t dir|^2 = 4
      const double b = eye[2] * dir[2], cc = 100 - 4, disc = b * b - cc;
      const Rgb got = px(im, x, y);
      INFO("pixel " << x << " " << y << " got " << got.r << " " << got.g << " " << got.b);
      if (disc < 0.05) {  // clear misses only; the rim is left to rounding
        if (disc < -0.05) CHECK(got.r + got.g + got.b == 0);
        continue;
      }
      const double t = -b - std::sqrt(disc);
      const Vec3 p{eye[0] + t * dir[0], eye[1] + t * dir[1], eye[2] + t * dir[2]};
      const Vec3 n{p[0] / 2, p[1] / 2, p[2] / 2};
      const double ndl = n[0] * L[0] + n[1] * L[1] + n[2] * L[2];
      Vec3 hv{L[0] - dir[0], L[1] - dir[1], L[2] - dir[2]};
      const double hl = std::sqrt(hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]);
      const double ndh = (n[0] * hv[0] + n[1] * hv[1] + n[2] * hv[2]) / hl;
      const double lit = ndl > 0 ? 1 : 0;
      const double s = lit * spec * std::pow(std::max(0.0, ndh), shin);
      const int want[3] = {int(std::min(255.0, (d[0] * (env + lit * ndl) + s) * 255)),
                           int(std::min(255.0, (d[1] * (env + lit * ndl) + s) * 255)),
                           int(std::min(255.0, (d[2] * (env + lit * ndl) + s) * 255))};
      CHECK(std::abs(got.r - want[0]) <= 1);
      CHECK(std::abs(got.g - want[1]) <= 1);
      CHECK(std::abs(got.b - want[2]) <= 1);
      ++hits;
    }
  CHECK(hits > 300);
}
