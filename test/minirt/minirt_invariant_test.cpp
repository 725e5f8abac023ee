// miniRT has no reference images, so the renderer is checked against facts
// that hold for any correct one (SPEC.md 2.7): an ambient-only scene shows
// exactly the ambient colour of each object it hits; a sphere and a
// cylinder seen along their axes have the analytic circular silhouettes; a
// mirror-symmetric scene gives a mirror-symmetric image; a point in shadow
// gets only the ambient term; a cylinder's point is its centre; the camera
// puts +x on the right when looking along +z and turns smoothly near the
// vertical; --mandatory drops the specular term.
#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>

#include "formats/minirt/minirt_reader.hpp"
#include "render_driver.hpp"

namespace {

using minrt::host::RgbaImage;

RgbaImage render(const std::string& text, int w, int h, minrt::host::Variant variant = {},
                 minrt::minirt::ReaderOptions reader = {}) {
  minrt::host::DriverOptions options;
  options.mandatory = reader.mandatory;
  options.cylinder_base = reader.cylinder_point == minrt::minirt::CylinderPoint::kBase;
  options.variant = variant;
  options.threads = 2;
  options.width = w;
  options.height = h;
  minrt::host::RenderedScene result;
  std::string error;
  const minrt::host::SceneInput in{"test.rt", "test.rt", "", text};
  const bool ok = minrt::host::render_in_memory(minrt::formats::format_of(minrt::formats::FormatId::kMinirt), in,
                                                options, result, error);
  INFO(error);
  REQUIRE(ok);
  return result.image;
}

struct Rgb {
  int r, g, b;
  bool operator<(const Rgb& o) const { return r != o.r ? r < o.r : g != o.g ? g < o.g : b < o.b; }
  bool operator==(const Rgb& o) const { return r == o.r && g == o.g && b == o.b; }
};

Rgb at(const RgbaImage& img, int x, int y) {
  const uint8_t* p = img.rgba.data() + 4 * (static_cast<size_t>(y) * img.width + x);
  return {p[0], p[1], p[2]};
}

// floor(255 * clamp(c/255 * ratio * a/255)) in the renderer's order of operations.
// `complement`: the checker's other colour, 1 - c/255.
template <class T = double>
int ambient_byte(int c, T ratio, int a, bool complement = false) {
  const T k = T(1) / T(255);
  const T colour = complement ? T(1) - T(c) * k : T(c) * k;
  const T v = colour * ((T(a) * k) * ratio);
  return v >= 1 ? 255 : static_cast<int>(std::floor(v * T(255)));
}

// The direction of pixel (x, y) as SPEC.md 2.3 writes it, for a camera
// looking along -z with +y up.
void pixel_dir(int x, int y, int w, int h, double fov, double d[3]) {
  const double hw = std::tan(fov * M_PI / 360), hh = hw * h / w;
  const double sx = (2 * (x + 0.5) / w - 1) * hw, sy = (1 - 2 * (y + 0.5) / h) * hh;
  const double n = std::sqrt(sx * sx + sy * sy + 1);
  d[0] = sx / n;
  d[1] = sy / n;
  d[2] = -1 / n;
}

}  // namespace

TEST_CASE("miniRT invariant: an ambient-only scene shows exactly each object's ambient colour", "[minirt][invariant]") {
  const std::string scene =
      "A 0.6 200,150,255\nC 0,3,12 0,-0.2,-1 70\nL 0,10,5 0 255,255,255\n"
      "sp 0,2,0 4 255,100,50\ncy 4,0,-2 0,1,0 2 4 10,250,30\nco -4,0,-2 0,1,0 25 4 90,90,240\n"
      "plc 0,0,0 0,1,0 180,180,180\n";
  for (const auto variant : {minrt::host::Variant{},
                             minrt::host::Variant{minrt::host::Precision::kFloat, minrt::host::ShimSet::kPortable}}) {
    const RgbaImage img = render(scene, 160, 120, variant);
    const bool single = variant.precision == minrt::host::Precision::kFloat;
    auto one = [&](int c, int a, bool flip) {
      return single ? ambient_byte<float>(c, 0.6f, a, flip) : ambient_byte<double>(c, 0.6, a, flip);
    };
    auto amb = [&](int r, int g, int b, bool flip = false) {
      return Rgb{one(r, 200, flip), one(g, 150, flip), one(b, 255, flip)};
    };
    const std::set<Rgb> allowed = {Rgb{0, 0, 0},         amb(255, 100, 50), amb(10, 250, 30), amb(90, 90, 240),
                                   amb(180, 180, 180), amb(180, 180, 180, true)};  // the checker's two colours
    std::set<Rgb> seen;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const Rgb c = at(img, x, y);
        INFO("pixel " << x << "," << y << " = " << c.r << "," << c.g << "," << c.b);
        REQUIRE(allowed.count(c) == 1);
        seen.insert(c);
      }
    CHECK(seen.size() == allowed.size());  // every object, both checker squares and the sky
  }
}

TEST_CASE("miniRT invariant: sphere and cylinder silhouettes along the axis are the analytic circles", "[minirt][invariant]") {
  const int w = 200, h = 150;
  const double fov = 60, D = 10;
  // White where hit (ambient 1, colour 255), black sky.
  const std::string head = "A 1 255,255,255\nC 0,0,10 0,0,-1 60\nL 0,0,20 0 255,255,255\n";
  SECTION("sphere of radius 2 at the origin") {
    const RgbaImage img = render(head + "sp 0,0,0 4 255,255,255\n", w, h);
    int checked = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double d[3];
        pixel_dir(x, y, w, h, fov, d);
        // Distance from the centre (0,0,0) to the ray from (0,0,D).
        const double t = -D * d[2];
        const double px = t * d[0], py = t * d[1], pz = D + t * d[2];
        const double dist = std::sqrt(px * px + py * py + pz * pz);
        if (std::fabs(dist - 2) < 1e-3) continue;  // grazing: either answer is right
        INFO("pixel " << x << "," << y);
        CHECK((at(img, x, y).r == 255) == (dist < 2));
        ++checked;
      }
    CHECK(checked > w * h * 99 / 100);
  }
  SECTION("cylinder of radius 1.5 on the axis: its near cap is the silhouette") {
    // Centre at z = -0.5, height 5: the near cap is the disc of radius 1.5 at z = 2.
    const RgbaImage img = render(head + "cy 0,0,-0.5 0,0,1 3 5 255,255,255\n", w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        double d[3];
        pixel_dir(x, y, w, h, fov, d);
        const double t = (2 - D) / d[2];
        const double r = std::hypot(t * d[0], t * d[1]);
        if (std::fabs(r - 1.5) < 1e-3) continue;
        INFO("pixel " << x << "," << y);
        CHECK((at(img, x, y).r == 255) == (r < 1.5));
      }
  }
}

TEST_CASE("miniRT invariant: a mirror-symmetric scene gives a mirror-symmetric image", "[minirt][invariant]") {
  const std::string scene =
      "A 0.15 255,255,255\nC 0,4,14 0,-0.25,-1 70\nL 0,12,4 0.9 255,240,220\n"
      "sp -3,1.5,0 3 200,60,60\nsp 3,1.5,0 3 200,60,60\ncy 0,0,-3 0,1,0 2 5 60,200,60\n"
      "co -5,0,-2 0,1,0 20 4 60,60,220\nco 5,0,-2 0,1,0 20 4 60,60,220\npl 0,0,0 0,1,0 150,150,150\n";
  const int w = 240, h = 160;
  const RgbaImage img = render(scene, w, h);
  int off = 0, lit = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w / 2; ++x) {
      const Rgb a = at(img, x, y), b = at(img, w - 1 - x, y);
      if (std::abs(a.r - b.r) > 1 || std::abs(a.g - b.g) > 1 || std::abs(a.b - b.b) > 1) ++off;
      if (a.r > 0) ++lit;
    }
  // Rounding differs between the two halves' rays: only pixels at edges may flip.
  CHECK(off <= w * h / 1000);
  CHECK(lit > w * h / 4);
}

TEST_CASE("miniRT invariant: a point in shadow gets only the ambient term", "[minirt][invariant]") {
  // The camera's centre ray (odd image size) meets the floor at the origin,
  // right under a sphere that hides the light above it.
  const std::string lit_scene =
      "A 0.25 255,255,255\nC 0,5,10 0,-0.5,-1 60\nL 0,10,0 0.9 255,255,255\npl 0,0,0 0,1,0 120,200,80\n";
  const std::string shadowed = lit_scene + "sp 0,2,0 2 255,255,255\n";
  const int n = 101;
  const Rgb ambient{ambient_byte(120, 0.25, 255), ambient_byte(200, 0.25, 255), ambient_byte(80, 0.25, 255)};
  const RgbaImage dark = render(shadowed, n, n);
  CHECK(at(dark, 50, 50) == ambient);
  // Without the sphere the same point is lit: ambient plus diffuse.
  const RgbaImage bright = render(lit_scene, n, n);
  const Rgb c = at(bright, 50, 50);
  CHECK(c.g > ambient.g + 100);
  // Outside the shadow, the shadowed image is lit too.
  CHECK(at(dark, 50, 95).g > ambient.g + 50);
}

TEST_CASE("miniRT invariant: a cylinder's point is its centre", "[minirt][invariant]") {
  // cy 0,0,0 0,1,0 2 4 spans y = -2..2 (the subject's "center of the
  // cylinder"). Horizontal rays at y = 1.5 and -1.5 hit it, at y = 3 miss;
  // with --cylinder-base it spans 0..4 instead.
  const std::string tail = "cy 0,0,0 0,1,0 2 4 255,255,255\n";
  const std::string head = "A 1 255,255,255\nL 0,0,20 0 255,255,255\n";
  auto hit_at = [&](const char* y, minrt::minirt::ReaderOptions reader) {
    const RgbaImage img = render(head + "C 0," + y + ",10 0,0,-1 30\n" + tail, 31, 31, {}, reader);
    return at(img, 15, 15).r == 255;
  };
  minrt::minirt::ReaderOptions base;
  base.cylinder_point = minrt::minirt::CylinderPoint::kBase;
  CHECK(hit_at("1.5", {}));
  CHECK(hit_at("-1.5", {}));
  CHECK_FALSE(hit_at("3", {}));
  CHECK(hit_at("3", base));
  CHECK_FALSE(hit_at("-1.5", base));
}

TEST_CASE("miniRT invariant: two cylinders through one centre cross", "[minirt][invariant]") {
  // Along x and along y, both centred at the origin, seen along +z: a plus
  // sign, all four arms present (base-centred, they would draw an L).
  const std::string scene =
      "A 1 255,255,255\nC 0,0,-20 0,0,1 40\nL 0,0,-20 0 255,255,255\n"
      "cy 0,0,0 1,0,0 1 8 255,255,255\ncy 0,0,0 0,1,0 1 8 255,255,255\n";
  const int n = 201;
  const RgbaImage img = render(scene, n, n);
  // World (x, y, 0) is at pixel centre + (x, -y) * n / (2 * 20 * tan 20deg)
  // up to the handedness, which the probes do not depend on: each arm is
  // probed on both sides.
  const double scale = n / (2 * 20 * std::tan(20 * 3.14159265358979 / 180));
  const int c = n / 2, arm = static_cast<int>(3 * scale);
  for (const auto& [dx, dy] : {std::pair{arm, 0}, std::pair{-arm, 0}, std::pair{0, arm}, std::pair{0, -arm}}) {
    INFO("probe " << dx << "," << dy);
    CHECK(at(img, c + dx, c + dy).r == 255);
  }
  CHECK(at(img, c + arm, c + arm).r == 0);  // between the arms: sky
}

TEST_CASE("miniRT invariant: looking along +z, +x is on the right", "[minirt][invariant]") {
  const std::string scene =
      "A 1 255,255,255\nC 0,0,-20 0,0,1 60\nL 0,0,-20 0 255,255,255\nsp 5,0,0 4 255,255,255\n";
  const int w = 160, h = 120;
  const RgbaImage img = render(scene, w, h);
  int left = 0, right = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (at(img, x, y).r == 255) ++(x < w / 2 ? left : right);
  CHECK(left == 0);
  CHECK(right > 100);
  // Above the sphere (y = +5) is the top half.
  const RgbaImage up = render(
      "A 1 255,255,255\nC 0,0,-20 0,0,1 60\nL 0,0,-20 0 255,255,255\nsp 0,5,0 4 255,255,255\n", w, h);
  CHECK(at(up, w / 2, h / 4).r == 255);
  CHECK(at(up, w / 2, 3 * h / 4).r == 0);
}

TEST_CASE("miniRT invariant: near the vertical the image turns a little, never by 90 degrees", "[minirt][invariant]") {
  // Looking down from y = 10, tilted toward +x by 2.3 and 2.9 degrees: the
  // same picture a fraction of a degree apart. A red sphere at +x and a blue
  // one at +z mark the orientation.
  auto scene = [](const char* dir) {
    return std::string("A 1 255,255,255\nC 0,10,0 ") + dir + " 60\nL 0,20,0 0 255,255,255\n" +
           "pl 0,0,0 0,1,0 90,90,90\nsp 3,0.5,0 2 255,0,0\nsp 0,0.5,3 2 0,0,255\n";
  };
  const int n = 120;
  const RgbaImage a = render(scene("0.04,-1,0"), n, n);
  const RgbaImage b = render(scene("0.05,-1,0"), n, n);
  int off = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Rgb p = at(a, x, y), q = at(b, x, y);
      if (std::abs(p.r - q.r) > 8 || std::abs(p.g - q.g) > 8 || std::abs(p.b - q.b) > 8) ++off;
    }
  // A 0.6 degree turn moves the spheres' edges by a pixel or two: measured
  // 0.7 % of the pixels; the first image rolled by 90 degrees differs from
  // itself in 9.2 %.
  CHECK(off < n * n / 25);
  // Where the red sphere is: the same quadrant in both.
  auto centroid = [&](const RgbaImage& img, bool red, double& cx, double& cy) {
    int count = 0;
    cx = cy = 0;
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Rgb p = at(img, x, y);
        if (red ? (p.r == 255 && p.b == 0) : (p.b == 255 && p.r == 0)) cx += x, cy += y, ++count;
      }
    REQUIRE(count > 20);
    cx /= count, cy /= count;
  };
  double ax, ay, bx, by;
  centroid(a, true, ax, ay);
  centroid(b, true, bx, by);
  CHECK(std::hypot(ax - bx, ay - by) < 3);
  centroid(a, false, ax, ay);
  centroid(b, false, bx, by);
  CHECK(std::hypot(ax - bx, ay - by) < 3);
  // Straight down has no heading: it is the limit of a tilt from +z, so
  // +x is on the right and +z at the top, as with 0,-1,0.01.
  const RgbaImage down = render(scene("0,-1,0"), n, n);
  const RgbaImage near = render(scene("0,-1,0.01"), n, n);
  centroid(down, true, ax, ay);
  centroid(near, true, bx, by);
  CHECK(ax > n / 2 + 10);
  CHECK(std::hypot(ax - bx, ay - by) < 3);
  centroid(down, false, ax, ay);
  centroid(near, false, bx, by);
  CHECK(ay < n / 2 - 10);
  CHECK(std::hypot(ax - bx, ay - by) < 3);
}

TEST_CASE("miniRT invariant: --mandatory shades with ambient and diffuse only, the light white", "[minirt][invariant]") {
  // A sphere lit head-on by a red light: the bonus shading has a white-ish
  // specular highlight tinted red; the mandatory one is ambient + diffuse
  // with a white light, at most colour * (ambient + brightness).
  const std::string scene =
      "A 0.1 255,255,255\nC 0,0,10 0,0,-1 40\nL 0,0,10 0.6 255,0,0\nsp 0,0,0 4 100,100,200\n";
  minrt::minirt::ReaderOptions mandatory;
  mandatory.mandatory = true;
  const int n = 51;
  const Rgb bonus = at(render(scene, n, n), 25, 25);
  const Rgb plain = at(render(scene, n, n, {}, mandatory), 25, 25);
  // Facing the light: n.l = 1, so c = colour * (0.1 + 0.6), floored.
  // (within 1: the two terms are added before the floor)
  CHECK(std::abs(plain.r - static_cast<int>(100 * 0.7)) <= 1);
  CHECK(std::abs(plain.g - static_cast<int>(100 * 0.7)) <= 1);
  CHECK(std::abs(plain.b - static_cast<int>(200 * 0.7)) <= 1);
  CHECK(bonus.g < plain.g);  // the red light adds no green in bonus mode
  CHECK(bonus.r > plain.r + 50);  // red diffuse + the specular highlight (0.5 * 0.6 at its peak)
}
