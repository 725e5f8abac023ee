// EASTRAY's statements about images (docs/eastray.md, "Output, stereo,
// background"): a window rendered into an existing file changes only the
// window (line 180), stereo pairs (rmode 1, line 57), 16-bit TIFF with and
// without dither (lines 152-164), the formats no library writes, input and
// back_mode (lines 187-230), and the :mtx warning printed once.
#include <algorithm>
#include <set>

#include "eastray_probe_support.hpp"
#include "png_io.hpp"
#include "eastray_stereo.hpp"
#include "tiff_io.hpp"

using namespace eprobe;

namespace {

std::string scenes() { return EASTRAY_SCENES_DIR; }

std::vector<uint8_t> read_rgb(const std::string& path, int& w, int& h) {
  std::vector<uint8_t> rgb;
  std::string why;
  if (path.size() > 4 && path.substr(path.size() - 4) == ".tif") {
    REQUIRE(minrt::host::read_tiff_rgb(path, w, h, rgb, why));
    return rgb;
  }
  minrt::host::RgbaImage img;
  INFO(path << ": " << why);
  REQUIRE(minrt::host::read_png(path, img, why));
  w = img.width, h = img.height;
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) rgb.insert(rgb.end(), img.rgba.begin() + i, img.rgba.begin() + i + 3);
  return rgb;
}

const std::string kBody =
    "condition 2 0.01 0.00001 0 ;\ncamera 0 1 10  0 0 0  0 10 0  20 0 ;\nsky 0.2 0.3 0.8 ;\nenv 0.2 0.2 0.2 ;\n"
    "e_light [ 1 2 3  1 1 1  0 0 ; ]\ncolor [ 0.9 0.2 0.2  0 0 0  0 0 0  1 0 0  0  0.5 20 ; 0.7 0.7 0.7  0 0 0  0 0 0  1 0 0  0  0 1 ; ]\n"
    "obj [ 2 0 1  0 0 0  1.5 ; 1 1 1  0 -1.5 0  0 1 0 ; ]\n";

std::string display(int x0, int y0, int x1, int y1) {
  return "display 64 48 " + std::to_string(x0) + " " + std::to_string(y0) + " " + std::to_string(x1) + " " +
         std::to_string(y1) + " 1 1 1 ;\n";
}

Run minrt_in(const std::string& dir, const std::string& args) { return run(std::string(MINRT_BIN) + " " + args, dir); }

}  // namespace

TEST_CASE("eastray output: a window rendered into an existing file changes only the window", "[eastray][output]") {
  for (const char* ext : {".png", ".tif"}) {
    INFO(ext);
    const std::string dir = temp_dir();
    const std::string out = std::string("pic") + ext;
    write(dir + "/full.ray", display(0, 0, 63, 47) + kBody);
    write(dir + "/left.ray", display(0, 0, 30, 47) + kBody);
    write(dir + "/right.ray", display(31, 0, 63, 47) + kBody);
    write(dir + "/mid.ray", display(10, 5, 40, 20) + kBody + "sky 1 0 1 ;\n");
    REQUIRE(minrt_in(dir, "-q full.ray -o whole" + std::string(ext)).status == 0);
    // Left window into a new file, then the right window into it: the whole image.
    REQUIRE(minrt_in(dir, "-q left.ray -o " + out).status == 0);
    int w = 0, h = 0;
    const auto left_only = read_rgb(dir + "/" + out, w, h);
    CHECK(left_only[(10 * 64 + 50) * 3 + 2] == 0);  // right of the window: black
    REQUIRE(minrt_in(dir, "-q right.ray -o " + out).status == 0);
    int w2 = 0, h2 = 0;
    CHECK(read_rgb(dir + "/" + out, w, h) == read_rgb(dir + "/whole" + ext, w2, h2));
    // A window with another sky changes only its own pixels.
    const auto before = read_rgb(dir + "/" + out, w, h);
    REQUIRE(minrt_in(dir, "-q mid.ray -o " + out).status == 0);
    const auto after = read_rgb(dir + "/" + out, w, h);
    int inside = 0, outside = 0;
    for (int y = 0; y < 48; ++y)
      for (int x = 0; x < 64; ++x) {
        const std::size_t i = (static_cast<std::size_t>(y) * 64 + x) * 3;
        const bool differs = !std::equal(before.begin() + i, before.begin() + i + 3, after.begin() + i);
        if (x >= 10 && x <= 40 && y >= 5 && y <= 20) inside += differs;
        else outside += differs;
      }
    CHECK(outside == 0);
    CHECK(inside > 100);
  }
  SECTION("another size: replaced, black outside the window, with a warning") {
    const std::string dir = temp_dir();
    write(dir + "/left.ray", display(0, 0, 30, 47) + kBody);
    write(dir + "/small.ray", "display 32 24 0 0 31 23 1 1 1 ;\n" + kBody);
    REQUIRE(minrt_in(dir, "-q small.ray -o pic.png").status == 0);
    const Run r = minrt_in(dir, "left.ray -o pic.png");
    CHECK(r.status == 0);
    CHECK(r.err.find("is 32x24, not 64x48") != std::string::npos);
    int w = 0, h = 0;
    const auto img = read_rgb(dir + "/pic.png", w, h);
    CHECK(w == 64);
    CHECK(img[(10 * 64 + 50) * 3 + 2] == 0);
  }
}

TEST_CASE("eastray output: rmode 1 writes the right and left images", "[eastray][output][stereo]") {
  const std::string dir = temp_dir();
  const std::string text = minrt::test::read_file(scenes() + "/stereo_pair.ray");
  write(dir + "/s.ray", text);
  const Run r = minrt_in(dir, "s.ray");
  CHECK(r.status == 0);
  CHECK(exists(dir + "/stereo_r.png"));
  CHECK(exists(dir + "/stereo_l.png"));
  CHECK_FALSE(exists(dir + "/stereo.png"));
  // Each equals rmode 0 from its eye: 0.25 = 0.05 x 10 / 2 to the right
  // (+x here) or left, looking at the same point.
  for (const char* side : {"r", "l"}) {
    std::string mono = text;
    mono.replace(mono.find("rmode 1 ;"), 7, "rmode 0");
    const std::string eye = side[0] == 'r' ? "0.25" : "-0.25";
    mono.replace(mono.find("camera 0 0 10"), 13, "camera " + eye + " 0 10");
    mono.replace(mono.find("output stereo.png"), 17, std::string("output mono_") + side + ".png");
    write(dir + "/m.ray", mono);
    REQUIRE(minrt_in(dir, "-q m.ray").status == 0);
    int w = 0, h = 0, w2 = 0, h2 = 0;
    const auto a = read_rgb(dir + "/stereo_" + side + ".png", w, h);
    const auto b = read_rgb(dir + "/mono_" + side + ".png", w2, h2);
    int off = 0;
    for (std::size_t i = 0; i < a.size(); ++i) off += std::abs(int(a[i]) - int(b[i])) > 1;
    CHECK(off == 0);
  }
  // The two differ: the eyes are apart.
  int w = 0, h = 0;
  CHECK(read_rgb(dir + "/stereo_r.png", w, h) != read_rgb(dir + "/stereo_l.png", w, h));
  CHECK(minrt::host::eastray_stereo_name("a/b.c/pic.tif", 'l') == "a/b.c/pic_l.tif");
  CHECK(minrt::host::eastray_stereo_name("pic", 'r') == "pic_r");
}

TEST_CASE("eastray output: output_mode 16 gives 32K colours in a TIFF, dithered on request", "[eastray][output]") {
  const std::string dir = temp_dir();
  write(dir + "/24.ray", display(0, 0, 63, 47) + kBody);
  write(dir + "/16.ray", display(0, 0, 63, 47) + "output_mode 16 0 ;\n" + kBody);
  write(dir + "/16d.ray", display(0, 0, 63, 47) + "output_mode 16 1 ;\n" + kBody);
  for (const char* s : {"24", "16", "16d"}) REQUIRE(minrt_in(dir, std::string("-q ") + s + ".ray -o " + s + ".tif").status == 0);
  int w = 0, h = 0;
  const auto full = read_rgb(dir + "/24.tif", w, h);
  const auto plain = read_rgb(dir + "/16.tif", w, h);
  const auto dithered = read_rgb(dir + "/16d.tif", w, h);
  std::set<int> levels;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    // Every value is one of the 32 levels k x 255 / 31, the nearest to the
    // 24-bit value; dithered ones are within one level of it.
    const int k = (plain[i] * 31 + 127) / 255;
    CHECK(plain[i] == (k * 255 + 15) / 31);
    CHECK(std::abs(plain[i] * 31.0 / 255 - full[i] * 31.0 / 255) <= 0.5 + 1e-9);
    CHECK(std::abs(dithered[i] * 31.0 / 255 - full[i] * 31.0 / 255) < 1.0 + 1e-9);
    levels.insert(plain[i]);
  }
  CHECK(levels.size() > 8);
  CHECK(plain != dithered);
  // PNG is not a format whose depth varies (line 157): 24 bits.
  REQUIRE(minrt_in(dir, "-q 16.ray -o 16.png").status == 0);
  REQUIRE(minrt_in(dir, "-q 24.ray -o 24.png").status == 0);
  CHECK(read_rgb(dir + "/16.png", w, h) == read_rgb(dir + "/24.png", w, h));
  write(dir + "/bad.ray", display(0, 0, 63, 47) + "output_mode 15 0 ;\n" + kBody);
  const Run r = minrt_in(dir, "bad.ray -o x.tif");
  CHECK(r.status == 2);
  CHECK(r.err.find("bad.ray:2:13: error: output_mode bits must be 16 or 24") == 0);
}

TEST_CASE("eastray output: .fal, .ipr and .hpi are refused with the formats written", "[eastray][output]") {
  const std::string dir = temp_dir();
  for (const char* ext : {"fal", "ipr", "hpi", "HPI"}) {
    write(dir + "/s.ray", display(0, 0, 63, 47) + "output pic." + ext + " ;\n" + kBody);
    const Run r = minrt_in(dir, "s.ray");
    CHECK(r.status == 2);
    CHECK(r.err.find("error: cannot write pic.") != std::string::npos);
    CHECK(r.err.find(".tif or .tiff (TIFF)") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(dir + "/pic." + std::string(ext)));
    CHECK_FALSE(exists(dir + "/pic.png"));
  }
}

TEST_CASE("eastray output: input and back_mode", "[eastray][output][background]") {
  const std::string text = minrt::test::read_file(scenes() + "/back_input.ray");
  const auto one = render(text, scenes() + "/back_input.ray");
  CHECK((px(one, 5, 5).r == 255 && px(one, 5, 5).g == 255 && px(one, 5, 5).b == 0));    // upper half: yellow
  CHECK((px(one, 5, 55).r == 255 && px(one, 5, 55).g == 0 && px(one, 5, 55).b == 255));  // lower: magenta
  // Row 30 of 61 is the middle: its centre at 30.5 / 61 of the height, the
  // backdrop's lower row. Back_mode 2 shows the disc there, 1 does not.
  std::string two = text;
  two.replace(two.find("back_mode 1 0"), 11, "back_mode 2");
  const auto disc = render(two, scenes() + "/back_input.ray");
  const Rgb d1 = px(one, 68, 30), d2 = px(disc, 68, 30);
  CHECK((d1.r == 255 && d1.g == 0 && d1.b == 255));
  CHECK((d2.g > 200));
  std::string zero = text;
  zero.replace(zero.find("back_mode 1 0"), 11, "back_mode 0");
  const auto sky = render(zero, scenes() + "/back_input.ray");
  CHECK((px(sky, 5, 5).r == 0 && px(sky, 5, 5).b == 255));  // the sky, not the image
  // The sphere is the same in all three.
  CHECK((px(one, 40, 30).r == px(sky, 40, 30).r));
  SECTION("a missing input file is an error") {
    const std::string dir = temp_dir();
    std::string missing = text;
    missing.replace(missing.find("input backdrop.ppm") + 6, 12, "nowhere.tif");
    write(dir + "/m.ray", missing);
    Run r = minrt_in(dir, "m.ray -o x.png");
    CHECK(r.status == 2);
    CHECK(r.err.find("m.ray:7:7: error: input nowhere.tif: no such file") == 0);
    CHECK_FALSE(exists(dir + "/x.png"));
  }
}

TEST_CASE("eastray output: a non-affine :mtx warns once", "[eastray][output]") {
  const std::string dir = temp_dir();
  write(dir + "/m.ray", display(0, 0, 63, 47) + kBody.substr(0, kBody.find("obj [")) +
                            "obj p [ 2 0 1  0 0 0  1 ; ]\nobj [ :mtx 1 0 0 0  0 1 0 0  0 0 1 0  0 0 0.5 1  p ; p ; ]\n");
  const Run r = minrt_in(dir, "m.ray -o x.png");
  CHECK(r.status == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find(":mtx bottom row") != std::string::npos);
}

namespace {

bool is(Rgb c, int r, int g, int b) { return c.r == r && c.g == g && c.b == b; }

std::string with_back_mode(std::string text, const std::string& mode) {
  const std::size_t at = text.find("back_mode 1 1 1 0");
  REQUIRE(at != std::string::npos);
  return text.replace(at, 17, "back_mode " + mode);
}

}  // namespace

TEST_CASE("eastray output: back_mode's reflection and transmission switches", "[eastray][output][background]") {
  const std::string path = scenes() + "/back_switches.ray";
  const std::string text = minrt::test::read_file(path);
  // Rows 25 and 36 lie above and below the middle (the backdrop's two rows);
  // columns 18 and 62 are the spheres' centres.
  const auto both = render(text, path);
  CHECK(is(px(both, 18, 25), 255, 127, 0));  // mirror: yellow x (1 0.5 0.5)
  CHECK(is(px(both, 18, 36), 255, 0, 127));  // magenta x (1 0.5 0.5)
  CHECK(is(px(both, 62, 25), 63, 255, 0));  // clear: yellow x (0.5 1 1) at two surfaces
  CHECK(is(px(both, 62, 36), 63, 0, 255));
  CHECK(is(px(both, 40, 25), 255, 255, 0));  // between them the backdrop itself
  const auto none = render(with_back_mode(text, "1 0 0 0"), path);
  CHECK(is(px(none, 18, 25), 0, 0, 127));  // the sky x (1 0.5 0.5)
  CHECK(is(px(none, 18, 36), 0, 0, 127));
  CHECK(is(px(none, 62, 25), 0, 0, 255));
  CHECK(is(px(none, 62, 36), 0, 0, 255));
  // Each switch acts on its own rays only.
  const auto reflect = render(with_back_mode(text, "1 1 0 0"), path);
  const auto transmit = render(with_back_mode(text, "1 0 1 0"), path);
  CHECK(is(px(reflect, 18, 25), 255, 127, 0));
  CHECK(is(px(reflect, 62, 25), 0, 0, 255));
  CHECK(is(px(transmit, 18, 25), 0, 0, 127));
  CHECK(is(px(transmit, 62, 36), 63, 0, 255));
  // back_mode 2 shows the same (no e_light: no disc to add).
  CHECK(render(with_back_mode(text, "2 1 1 0"), path).rgb == both.rgb);
  // Under back_mode 0 the background is the sky: the switches change nothing.
  const auto sky = render(with_back_mode(text, "0 0 0 0"), path);
  CHECK(render(with_back_mode(text, "0 1 1 0"), path).rgb == sky.rgb);
  CHECK(is(px(sky, 18, 25), 0, 0, 127));
  CHECK(is(px(sky, 40, 25), 0, 0, 255));
  // A clear sphere that passes everything, under both switches, vanishes
  // into the backdrop: the scene without it, but for rim pixels (a
  // condition deep enough for the mirror's rays through it too, which
  // leave it as transmitted rays).
  std::string clear = text;
  clear.replace(clear.find("0.5 1 1  1 0 0"), 14, "1 1 1  1 0 0");
  clear.replace(clear.find("condition 4"), 11, "condition 6");
  std::string without = text;
  without.replace(without.find("condition 4"), 11, "condition 6");
  without.replace(without.find(" 2 clear 1  2 0 0  1.2 ;"), 24, "");
  const auto a = render(clear, path), b = render(without, path);
  CHECK(differing(a, b, 2) <= 4);
  CHECK(covered(b, Rgb{255, 255, 0}) > 1000);  // the backdrop's magenta half and the mirror are there
}

TEST_CASE("eastray output: back_mode 1 and 2 without input: the sky behind, one warning, the disc as the mode says",
          "[eastray][output][background]") {
  // Lines 212-216 with nothing to composite: the sky stands in for the
  // image; mode 1 hides the e_light's disc, 2 shows it, as 0 does.
  const std::string path = scenes() + "/back_sky_disc.ray";
  const std::string text = minrt::test::read_file(path);
  REQUIRE(text.find("\ninput ") == std::string::npos);  // no input statement
  const std::string dir = temp_dir();
  write(dir + "/b1.ray", text);
  const Run r = minrt_in(dir, "b1.ray -o b1.png");
  CHECK(r.status == 0);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find("b1.ray:6:1: warning: back_mode 1 and 2 composite the input image, and the scene names none") == 0);
  CHECK(exists(dir + "/b1.png"));
  const auto mode = [&](const char* m) {
    std::string t = text;
    t.replace(t.find("back_mode 1 0 0 0"), 17, std::string("back_mode ") + m);
    return render(t, path);
  };
  const auto one = render(text, path), zero = mode("0 0 0 0"), two = mode("2 0 0 0");
  CHECK(two.rgb == zero.rgb);                     // the discs seen, the sky behind: mode 0's image
  CHECK(mode("1 1 1 0").rgb == one.rgb);          // the switches send missed rays to that same sky
  CHECK(is(px(one, 5, 5), 0, 0, 255));            // the sky, not black
  CHECK(px(one, 40, 30).r == px(zero, 40, 30).r);  // the sphere
  // The disc: the pixels whose ray lies within 3 degrees of the light
  // (0.25 0 -1) are white under mode 0 and sky under mode 1; every other
  // pixel is the same in both. The camera of docs/eastray.md: forward -z,
  // right +x, tan 20 degrees across, the height's share of it up.
  const double kPi = 3.14159265358979323846, th = std::tan(20 * kPi / 180), tv = th * 61 / 81;
  const double ln = std::sqrt(0.25 * 0.25 + 1);
  int in_disc = 0;
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 81; ++x) {
      const double sx = (2 * (x + 0.5) / 81 - 1) * th, sy = (1 - 2 * (y + 0.5) / 61) * tv;
      const double cs = (0.25 * sx + 1.0) / ln / std::sqrt(sx * sx + sy * sy + 1);
      const double angle = std::acos(std::fmin(1.0, cs)) * 180 / kPi;
      INFO("pixel " << x << " " << y << " at " << angle << " degrees from the light");
      if (angle < 2.95) {
        ++in_disc;
        CHECK(is(px(zero, x, y), 255, 255, 255));
        CHECK(is(px(one, x, y), 0, 0, 255));
      } else if (angle > 3.05) {
        CHECK(is(px(zero, x, y), px(one, x, y).r, px(one, x, y).g, px(one, x, y).b));
      }
    }
  CHECK(in_disc > 50);
}

TEST_CASE("eastray output: the tallest image renders, and the deepest condition", "[eastray][output]") {
  // Line 72 sets no height limit; ours is 16384 (docs/eastray.md): a
  // column of that height renders, the sphere in its middle (the field
  // is 20 degrees across, nearly 90 up and down).
  const std::string body = "camera 0 0 10  0 0 0  0 10 0  20 0 ;\nsky 0 0 1 ;\nenv 1 1 1 ;\n"
                           "color [ 1 0 0  0 0 0  0 0 0  1 0 0  0  0 1 ; ]\nobj [ 2 0 1  0 0 0  5 ; ]\n";
  const auto tall = render("display 2 16384 0 0 1 16383 1 1 1 ;\ncondition 16 0.01 0.00001 0 ;\n" + body);
  CHECK(tall.width == 2);
  CHECK(tall.height == 16384);
  CHECK(is(px(tall, 0, 0), 0, 0, 255));
  CHECK(is(px(tall, 1, 8192), 255, 0, 0));
}

TEST_CASE("eastray output: back_mode's alpha mode shapes only .hpi images", "[eastray][output][background]") {
  // Lines 227-230: the alpha channel of .hpi (line 182), which is not
  // written: 1 warns once, and the image is alpha 0's.
  const std::string dir = temp_dir();
  const std::string text = minrt::test::read_file(scenes() + "/back_switches.ray");
  write(dir + "/a0.ray", text);
  write(dir + "/a1.ray", with_back_mode(text, "1 1 1 1"));
  write(dir + "/backdrop.ppm", minrt::test::read_file(scenes() + "/backdrop.ppm"));
  const Run r0 = minrt_in(dir, "a0.ray -o a0.png");
  const Run r1 = minrt_in(dir, "a1.ray -o a1.png");
  CHECK(r0.status == 0);
  CHECK(r0.err.empty());
  CHECK(r1.status == 0);
  CHECK(std::count(r1.err.begin(), r1.err.end(), '\n') == 1);
  CHECK(r1.err.find("a1.ray:15:17: warning: back_mode alpha mode 1 applies to the alpha channel of .hpi images") == 0);
  int w = 0, h = 0;
  CHECK(read_rgb(dir + "/a0.png", w, h) == read_rgb(dir + "/a1.png", w, h));
}
