// EASTRAY mapping, bump, colour-number mapping and the anisotropic models
// (docs/eastray.md, "Mapping"): the scenes of test/eastray/scenes probed
// where their README says what a correct image shows, and pairs whose two
// images must agree (a map of one colour is that colour; a scale, a sum;
// every TIFF kind of line 390 read alike; a bumped plate of constant height
// is flat; scratches turned 90 degrees turn the highlight).
#include <tiffio.h>

#include <algorithm>
#include <cstring>
#include <functional>

#include "eastray_probe_support.hpp"
#include "render/general/eastray_mapping.hpp"

using namespace eprobe;

namespace {

std::string scenes() { return EASTRAY_SCENES_DIR; }

EastrayImage render_file(const std::string& name, minrt::host::Variant v = {}) {
  return render(minrt::test::read_file(scenes() + "/" + name), scenes() + "/" + name, v);
}

void expect_px(const EastrayImage& im, int x, int y, Rgb want, int tol = 0) {
  const Rgb got = px(im, x, y);
  INFO("pixel " << x << "," << y << ": got " << got.r << " " << got.g << " " << got.b << ", expected " << want.r
                << " " << want.g << " " << want.b);
  CHECK(std::abs(got.r - want.r) <= tol);
  CHECK(std::abs(got.g - want.g) <= tol);
  CHECK(std::abs(got.b - want.b) <= tol);
}

// A plate facing the camera, 81 x 61, lit by env 1 only: a pixel is the
// diffuse colour. `diffuse` is the colour's first field, mapping included.
// `rest`: bump, algorithm and its parameters.
std::string plate_scene(const std::string& maps, const std::string& diffuse, const std::string& rest = "0  0  0 0") {
  return "display 81 61 0 0 80 60 1 1 1 ;\ncondition 1 0.01 0.00001 0 ;\ncamera 0 0 10  0 0 0  0 10 0  20 0 ;\n"
         "sky 0 0 0 ;\nenv 1 1 1 ;\n" + maps + "color [ p " + diffuse + "  0 0 0  0 0 0  1 0  " + rest +
         " ; ]\nobj [ 16 p 1  0 0 0  2 2 0.1 ; ]\n";
}

// The four quadrant probes of a 4 x 4 plate at the origin seen from (0 0 10).
const int kLeft = 29, kRight = 51, kTop = 19, kBottom = 41;
const Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kWhite{255, 255, 255}, kGrey{127, 127, 127};

// Writes a TIFF of w x h with `spp` samples of `bits` bits through libtiff;
// `fill(x, y, sample)` gives each sample, `palette` (bits <= 8, spp 1)
// gives colours.
void write_tiff(const std::string& path, int w, int h, int spp, int bits, int compression,
                const std::function<int(int, int, int)>& fill, const std::vector<Rgb>& palette = {}) {
  TIFF* t = TIFFOpen(path.c_str(), "w");
  REQUIRE(t != nullptr);
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, w);
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, h);
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, spp);
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, bits);
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_COMPRESSION, compression);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, h);
  if (!palette.empty()) {
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_PALETTE);
    std::vector<uint16_t> r(1u << bits), g(1u << bits), b(1u << bits);
    for (std::size_t i = 0; i < palette.size(); ++i)
      r[i] = static_cast<uint16_t>(palette[i].r * 257), g[i] = static_cast<uint16_t>(palette[i].g * 257),
      b[i] = static_cast<uint16_t>(palette[i].b * 257);
    TIFFSetField(t, TIFFTAG_COLORMAP, r.data(), g.data(), b.data());
  } else {
    TIFFSetField(t, TIFFTAG_PHOTOMETRIC, spp == 3 ? PHOTOMETRIC_RGB : PHOTOMETRIC_MINISBLACK);
  }
  const std::size_t row_bytes = (static_cast<std::size_t>(w) * spp * bits + 7) / 8;
  std::vector<uint8_t> row(row_bytes);
  for (int y = 0; y < h; ++y) {
    std::fill(row.begin(), row.end(), 0);
    for (int x = 0; x < w; ++x)
      for (int s = 0; s < spp; ++s) {
        const int v = fill(x, y, s);
        const std::size_t bit = (static_cast<std::size_t>(x) * spp + s) * bits;
        if (bits == 16) {
          const uint16_t v16 = static_cast<uint16_t>(v);
          std::memcpy(&row[bit / 8], &v16, 2);
        } else if (bits == 8) {
          row[bit / 8] = static_cast<uint8_t>(v);
        } else {
          row[bit / 8] |= static_cast<uint8_t>(v << (8 - bits - bit % 8));
        }
      }
    REQUIRE(TIFFWriteScanline(t, row.data(), static_cast<uint32_t>(y), 0) >= 0);
  }
  TIFFClose(t);
}

}  // namespace

TEST_CASE("eastray mapping: planar mapping puts the image's corners where the manual says", "[eastray][mapping]") {
  const auto im = render_file("map_plane_quad.ray");
  expect_px(im, kLeft, kTop, kRed);
  expect_px(im, kRight, kTop, kGreen);
  expect_px(im, kLeft, kBottom, kBlue);
  expect_px(im, kRight, kBottom, kWhite);
  expect_px(im, 2, 2, Rgb{0, 0, 0});  // the sky beside the plate
  SECTION("swapping (u1 v1) and (u2 v2) turns the image over (line 657)") {
    const auto flip = render(plate_scene("map_data [ quad.ppm 0 ; ]\n", "0.5 0.5 0.5 < 0 1 1  2 -2 -2 2  -2 -2 2 2 >"),
                             scenes() + "/flip.ray");
    expect_px(flip, kLeft, kTop, kWhite);
    expect_px(flip, kRight, kTop, kBlue);
    expect_px(flip, kLeft, kBottom, kGreen);
    expect_px(flip, kRight, kBottom, kRed);
  }
  SECTION("the tile repeats over the range: a 2 x 2 tile of a 4 x 4 range") {
    const auto tiled = render(plate_scene("map_data [ quad.ppm 0 ; ]\n", "0.5 0.5 0.5 < 0 1 1  0 2 2 0  -2 -2 2 2 >"),
                              scenes() + "/tiled.ray");
    // The image repeats every 2 units: x = -1.51 and x = 0.44 (a period
    // apart, up to a pixel) both fall in its left column; y = 0.98 is
    // t = 0.51 from v1 = 2 down to v2 = 0, its bottom row: blue.
    expect_px(tiled, 23, kTop, kBlue);
    expect_px(tiled, 45, kTop, kBlue);
    expect_px(tiled, kLeft, kTop, kWhite);  // x = -0.98: the right column
  }
  SECTION("outside the range the colour's own value (line 670)") {
    const auto half = render(plate_scene("map_data [ quad.ppm 0 ; ]\n", "0.5 0.5 0.5 < 0 1 1  -2 2 2 -2  -2 -2 0 2 >"),
                             scenes() + "/half.ray");
    expect_px(half, kLeft, kTop, kRed);
    expect_px(half, kRight, kTop, kGrey);
    expect_px(half, kRight, kBottom, kGrey);
  }
}

TEST_CASE("eastray mapping: a map of one colour is that colour, in every mode", "[eastray][mapping]") {
  const std::string maps = "map_data [ flat const.ppm 1 ; ]\n";
  const auto plain = render(plate_scene("", "0.2 0.4 0.8"), scenes() + "/plain.ray");
  REQUIRE(covered(plain, Rgb{0, 0, 0}) > 1000);
  for (const char* mode : {"0 0.5", "1  -2 2 2 -2  -3 -3 3 3", "2  -1 1 1 -1  -1 -1 1 1", "3  -1 0 1 3  -1 0 1 3",
                           "4  -1 1 1 -1  -1 -1 1 1", "10 0.5", "11  -2 2 2 -2  -3 -3 3 3", "12  -1 1 1 -1  -1 -1 1 1",
                           "13  -1 0 1 3  -1 0 1 3", "14  -1 1 1 -1  -1 -1 1 1"}) {
    INFO("mode " << mode);
    const auto mapped = render(plate_scene(maps, std::string("0.9 0.9 0.9 < flat 1 ") + mode + " >"),
                               scenes() + "/const.ray");
    CHECK(differing(plain, mapped, 0) == 0);
  }
  SECTION("the scale multiplies (line 668); overlapping entries add (line 671)") {
    const auto grey = render(plate_scene("", "0.2 0.2 0.2"), scenes() + "/plain.ray");
    const std::string g = "map_data [ grey.ppm 0 ; ]\n";
    CHECK(differing(grey, render(plate_scene(g, "1 1 1 < 0 0.5 1  -2 2 2 -2  -3 -3 3 3 >"), scenes() + "/s.ray"), 0) ==
          0);
    const auto sum = render(plate_scene(g, "1 1 1 < 0 0.25 1  -2 2 2 -2  -3 -3 3 3  :mx 1 0 0.25 2  -1 1 1 -1  -1 -1 1 1 >"),
                            scenes() + "/s.ray");
    CHECK(differing(grey, sum, 0) == 0);
  }
}

TEST_CASE("eastray mapping: spherical, cylindrical and ring mapping", "[eastray][mapping]") {
  const auto im = render_file("map_modes.ray");
  // Column of x at distance d: (x / d / tan 20 + 1) 161 / 2 - 0.5: the globe
  // (x -4.5 at 18.5) 26, the can 80, the ring (x 4.5 at 19.9) 130; rows
  // about 0.75 above and below the middle.
  expect_px(im, 26, 22, kRed);    // globe, north
  expect_px(im, 26, 38, kBlue);   // globe, south
  expect_px(im, 80, 22, kRed);    // can, above its middle
  expect_px(im, 80, 38, kBlue);   // can, below
  expect_px(im, 130, 30, kRed);   // ring: centre
  expect_px(im, 146, 30, kBlue);  // radius 1.5
  expect_px(im, 153, 30, kGrey);  // radius 2.08: beyond the range
}

TEST_CASE("eastray mapping: all-directions mapping projects along the normal's axis", "[eastray][mapping]") {
  const auto im = render_file("map_all_directions.ray");
  expect_px(im, kRight, kTop, kRed);
  expect_px(im, kLeft, kTop, kGreen);
  expect_px(im, kRight, kBottom, kBlue);
  expect_px(im, kLeft, kBottom, kWhite);
}

TEST_CASE("eastray mapping: modes 10-14 blend neighbouring texels", "[eastray][mapping]") {
  // halves.ppm is red | green: the plate's middle column (x = 0) lies
  // between the two texel centres, half of each.
  const auto im = render(plate_scene("map_data [ halves.ppm 1 ; ]\n", "0 0 0 < 0 1 11  -2 2 2 -2  -2 -2 2 2 >"),
                         scenes() + "/f.ray");
  expect_px(im, 40, 30, Rgb{127, 127, 0}, 1);
  // Column 30 sees x = (30.5 / 40.5 - 1) tan 20 9.9, s = (x + 2) / 4 across
  // the image, 2s - 0.5 of the way from the red texel's centre to the green's.
  const double x = (30.5 / 40.5 - 1) * std::tan(20 * 3.14159265358979323846 / 180) * 9.9;
  const double w = 2 * (x + 2) / 4 - 0.5;
  CHECK(byte_is(px(im, 30, 30).r, 1 - w));
  CHECK(byte_is(px(im, 30, 30).g, w));
  const auto sharp = render(plate_scene("map_data [ halves.ppm 1 ; ]\n", "0 0 0 < 0 1 1  -2 2 2 -2  -2 -2 2 2 >"),
                            scenes() + "/f.ray");
  const Rgb mid = px(sharp, 40, 30);
  CHECK(((mid.r == 255 && mid.g == 0) || (mid.r == 0 && mid.g == 255)));
}

TEST_CASE("eastray mapping: modes 10-14 pick a halved image by the pixel's footprint", "[eastray][mapping][mip]") {
  // map_mip_checker.ray: single-texel checks, about 3.6 to a pixel. The
  // plates span columns 3-29 and 35-61, rows 3-29 (x = +-1.8 +- 1.5 at
  // distance 9.9, 64 columns across 2 tan 20 9.9).
  const auto im = render_file("map_mip_checker.ray");
  int black = 0, white = 0, other = 0;
  for (int y = 8; y <= 23; ++y)
    for (int x = 8; x <= 23; ++x) {
      const Rgb m = px(im, x, y);  // mipped: every pixel the checks' mean
      CHECK((std::abs(m.r - 128) <= 1 && m.g == m.r && m.b == m.r));
      const Rgb p = px(im, x + 32, y);  // plain: a texel, black or white
      black += p.r == 0 && p.g == 0 && p.b == 0;
      white += p.r == 255 && p.g == 255 && p.b == 255;
      other += !(p.r == 0 || p.r == 255);
    }
  CHECK(black > 20);
  CHECK(white > 20);
  CHECK(other == 0);
  // Where a texel covers several pixels the halved images are not used:
  // "modes 10-14 blend neighbouring texels" (halves.ppm, read with mip 1).
}

TEST_CASE("eastray mapping: the halved images", "[eastray][mapping][mip]") {
  // 3 x 1 texels 0, 100, 255 (red), 10 (green), 20 (blue): 2 x 1, then 1 x 1,
  // each texel the rounded mean of those under it.
  const uint8_t base[9] = {0, 10, 20, 100, 10, 20, 255, 10, 20};
  const minrt::model::Texture t{3, 1, base};
  REQUIRE(minrt::general::eastray_mip_bytes(3, 1) == 9);
  uint8_t bytes[9] = {};
  minrt::model::Texture levels[minrt::model::kMipLevels];
  minrt::general::eastray_build_mips(t, bytes, levels);
  CHECK(levels[0].width == 2);
  CHECK(levels[0].height == 1);
  CHECK(levels[0].rgb[0] == 50);   // (0 + 100 + 1) / 2
  CHECK(levels[0].rgb[3] == 255);  // the odd edge: alone
  CHECK(levels[1].width == 1);
  CHECK(levels[1].rgb[0] == 153);  // (50 + 255 + 1) / 2
  CHECK(levels[1].rgb[1] == 10);
  CHECK(levels[2].width == 0);
}

TEST_CASE("eastray mapping: bump mapping leans the normal away from the rise", "[eastray][mapping]") {
  const auto im = render_file("map_bump_ramp.ray");
  // Slope 256/255 (the ramp's 0..255 over 256 texels): the left light at
  // 45 degrees meets the bent normal at cos(45 - atan(256/255)) = 0.99999.
  expect_px(im, 40, 30, Rgb{254, 254, 254}, 1);
  expect_px(im, 30, 30, Rgb{254, 254, 254}, 1);
  std::string text = minrt::test::read_file(scenes() + "/map_bump_ramp.ray");
  SECTION("the light from the right grazes it: dark") {
    std::string right = text;
    right.replace(right.find("e_light [ -1"), 12, "e_light [ 1 ");
    const auto r = render(right, scenes() + "/r.ray");
    expect_px(r, 40, 30, Rgb{0, 0, 0}, 0);
  }
  SECTION("head on: cos(atan(256/255)) = 0.7057") {
    std::string head = text;
    head.replace(head.find("e_light [ -1"), 12, "e_light [ 0 ");
    const auto h = render(head, scenes() + "/h.ray");
    const double k = 1.0 / std::sqrt(1.0 + (256.0 / 255.0) * (256.0 / 255.0));
    CHECK(byte_is(px(h, 40, 30).r, k));
  }
  SECTION("a constant height is flat: the same image as no bump") {
    const std::string flat = plate_scene("map_data [ g grey.ppm 0 ; ]\ne_light [ -1 0 1  1 1 1  0 0 n ; ]\n",
                                         "1 1 1", "0 < g 3 1  -2 2 2 -2  -3 -3 3 3 >  0  0 0");
    std::string none = flat;
    none.replace(none.find("< g"), none.find('>', none.find("< g")) - none.find("< g") + 1, "");
    CHECK(differing(render(flat, scenes() + "/b.ray"), render(none, scenes() + "/b.ray"), 0) == 0);
  }
}

TEST_CASE("eastray mapping: colour-number mapping adds the red byte to the colour number", "[eastray][mapping]") {
  const auto im = render_file("map_colour_number.ray");
  expect_px(im, 30, 30, kGreen);
  expect_px(im, 50, 30, kRed);
}

TEST_CASE("eastray mapping: other parameters take their mappings", "[eastray][mapping]") {
  // The Blinn intensity (mono: the mean of the texel) mapped to 0.4 equals
  // 0.4 written; the reflectance mapped to 0.2 0.4 0.8 equals it written.
  const std::string light = "e_light [ 0 0 1  1 1 1  0 0 n ; ]\nmap_data [ g grey.ppm 0 ; c const.ppm 0 ; ]\n";
  auto sphere = [&](const std::string& colour) {
    return "display 41 31 0 0 40 30 1 1 1 ;\ncondition 3 0.01 0.00001 0 ;\ncamera 0 0 10  0 0 0  0 10 0  20 0 ;\n"
           "sky 0.3 0.6 0.9 ;\nenv 0.1 0.1 0.1 ;\n" + light + "color [ " + colour + " ; ]\nobj [ 2 0 1  0 0 0  2 ; ]\n";
  };
  const auto a = render(sphere("0.5 0.5 0.5  0 0 0  0 0 0  1 0 0  0  0.4 10"), scenes() + "/a.ray");
  const auto b = render(sphere("0.5 0.5 0.5  0 0 0  0 0 0  1 0 0  0  1 < g 1 0 1 > 10"), scenes() + "/a.ray");
  CHECK(differing(a, b, 1) == 0);
  const auto c = render(sphere("0.5 0.5 0.5  0.2 0.4 0.8  0 0 0  1 0 0  0  0 1"), scenes() + "/a.ray");
  const auto d = render(sphere("0.5 0.5 0.5  0 0 0 < c 1 0 1 >  0 0 0  1 0 0  0  0 1"), scenes() + "/a.ray");
  CHECK(differing(c, d, 0) == 0);
}

TEST_CASE("eastray mapping: every TIFF kind of line 390 reads as its colours", "[eastray][mapping]") {
  const std::string dir = temp_dir();
  // Colour 0.2 0.4 0.8 everywhere: 8-bit RGB (LZW and none), 16-bit RGB,
  // a 16-colour (4-bit) and a 256-colour palette; white: a 2-colour
  // (bilevel) file.
  write_tiff(dir + "/rgb.tif", 3, 2, 3, 8, COMPRESSION_NONE, [](int, int, int s) { return s == 0 ? 51 : s == 1 ? 102 : 204; });
  write_tiff(dir + "/lzw.tif", 3, 2, 3, 8, COMPRESSION_LZW, [](int, int, int s) { return s == 0 ? 51 : s == 1 ? 102 : 204; });
  write_tiff(dir + "/deep.tif", 3, 2, 3, 16, COMPRESSION_NONE,
             [](int, int, int s) { return (s == 0 ? 51 : s == 1 ? 102 : 204) * 257; });
  write_tiff(dir + "/p16.tif", 3, 2, 1, 4, COMPRESSION_NONE, [](int, int, int) { return 5; },
             {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}, {51, 102, 204}});
  write_tiff(dir + "/p256.tif", 3, 2, 1, 8, COMPRESSION_PACKBITS, [](int, int, int) { return 200; },
             std::vector<Rgb>(201, Rgb{51, 102, 204}));
  write_tiff(dir + "/bi.tif", 9, 3, 1, 1, COMPRESSION_NONE, [](int, int, int) { return 1; });
  const auto plain = render(plate_scene("", "0.2 0.4 0.8"), dir + "/plain.ray");
  for (const char* f : {"rgb.tif", "lzw.tif", "deep.tif", "p16.tif", "p256.tif"}) {
    INFO(f);
    const auto m = render(plate_scene(std::string("map_data [ ") + f + " 0 ; ]\n", "0 0 0 < 0 1 1  -2 2 2 -2  -3 -3 3 3 >"),
                          dir + "/m.ray");
    CHECK(differing(plain, m, 0) == 0);
  }
  const auto white = render(plate_scene("", "1 1 1"), dir + "/plain.ray");
  const auto bi = render(plate_scene("map_data [ bi.tif 0 ; ]\n", "0 0 0 < 0 1 1  -2 2 2 -2  -3 -3 3 3 >"), dir + "/m.ray");
  CHECK(differing(white, bi, 0) == 0);
}

TEST_CASE("eastray mapping: the anisotropic models", "[eastray][mapping][aniso]") {
  auto scene = [](const std::string& colour) {
    return "display 61 61 0 0 60 60 1 1 1 ;\ncondition 1 0.01 0.00001 0 ;\ncamera 0 0 1000  0 0 0  0 10 0  0.15 0 ;\n"
           "sky 0 0 0 ;\nenv 0 0 0 ;\ne_light [ 0 0 1  1 1 1  0 0 n ; ]\ncolor [ " + colour +
           " ; ]\nobj [ 2 0 1  0 0 0  2.5 ; ]\n";
  };
  const std::string head = "0 0 0  0 0 0  0 0 0  1 0 0  ";
  // Seen from far along z and lit from there, the centre's normal is the
  // half vector: exp(0) / (4 pi A B) times C.
  const double peak = 1.0 / (4 * 3.14159265358979323846 * 1.0 * 0.1);
  const auto x = render(scene(head + "3  1 1 1  1 0 0  1 0.1 1"));
  CHECK(byte_is(px(x, 30, 30).r, peak));
  const auto y = render(scene(head + "3  1 1 1  0 1 0  1 0.1 1"));
  int row = 0, col = 0;
  for (int i = 0; i < 61; ++i) row += px(x, i, 30).r > 100, col += px(x, 30, i).r > 100;
  INFO("bright pixels: row " << row << ", column " << col);
  CHECK(col > 2 * row);  // scratches along x: the streak runs up and down
  // Turning the scratches by 90 degrees turns the image.
  int off = 0;
  for (int i = 0; i < 61; ++i)
    for (int j = 0; j < 61; ++j) off += std::abs(px(x, i, j).r - px(y, 60 - j, i).r) > 2;
  CHECK(off <= 4);
  SECTION("model 2: circles around the view axis are the same in every direction; A = B is isotropic") {
    const auto c = render(scene(head + "2  1 1 1  0 0 0  0 0 1  1 0.1 1"));
    CHECK(byte_is(px(c, 30, 30).r, peak));
    int asym = 0;
    for (int i = 0; i < 61; ++i)
      for (int j = 0; j < 61; ++j) asym += std::abs(px(c, i, j).r - px(c, 60 - j, i).r) > 2;
    CHECK(asym <= 4);
    const auto iso_x = render(scene(head + "3  1 1 1  1 0 0  0.3 0.3 1"));
    const auto iso_c = render(scene(head + "2  1 1 1  5 5 0  0 0 1  0.3 0.3 1"));
    CHECK(differing(iso_x, iso_c, 1) == 0);
  }
}

TEST_CASE("eastray mapping: bad mappings and map files are located errors", "[eastray][mapping]") {
  const std::string dir = temp_dir();
  std::ofstream(dir + "/q.ppm", std::ios::binary) << minrt::test::read_file(scenes() + "/quad.ppm");
  std::ofstream(dir + "/old.fal", std::ios::binary) << "x";
  struct Bad {
    std::string maps, diffuse, message;
  };
  const std::vector<Bad> bad = {
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < r 1 1  0 0 1 1  0 0 1 1 >", "undefined map_data name 'r'"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < 3 1 1  0 0 1 1  0 0 1 1 >", "undefined map_data number 3"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < q 1 12  0 0 1 1  0 0 1 1 >", "need a map_data entry read with mip"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < q 1 5  0 0 1 1  0 0 1 1 >", "mapping mode must be"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < q 1 1  0 0 0 1  0 0 1 1 >", "span no area"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < q 1 1  0 0 1 1  0 0 1 >", "expected a number"},
      {"map_data [ q q.ppm 0 ; ]\n", "1 1 1 < >", "empty mapping"},
      {"map_data [ q missing.tif 0 ; ]\n", "1 1 1", "missing.tif: no such file"},
      {"map_data [ q old.fal 0 ; ]\n", "1 1 1", "convert the raw RGB file to TIFF"},
      {"map_data [ q q.bmp 0 ; ]\n", "1 1 1", "must be .tif, .tiff, .png, .ppm or .pnm"},
      {"map_data [ q q.ppm 2 ; ]\n", "1 1 1", "mip-mapping switch must be 0 or 1"},
      {"map_data [ q qppm 0 ; ]\n", "1 1 1", "expected a map_data file name"},
  };
  for (const Bad& b : bad) {
    INFO(b.maps << b.diffuse);
    write(dir + "/bad.ray", plate_scene(b.maps, b.diffuse));
    const Run r = run(std::string(MINRT_BIN) + " -o out.png bad.ray", dir);
    CHECK(r.status == 2);
    CHECK(r.err.find("bad.ray:") == 0);
    CHECK(r.err.find(b.message) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(exists(dir + "/out.png"));
  }
  // The all-directions mode has no range to map a colour number with.
  write(dir + "/bad.ray", "display 8 8 0 0 7 7 1 1 1 ;\nmap_data [ q.ppm 0 ; ]\ncolor [ 1 1 1  0 0 0  0 0 0  1 0 0  0 0 1 ; ]\n"
                          "obj [ 2 0 < 0 1 0 1 > 1  0 0 0 1 ; ]\n");
  const Run r = run(std::string(MINRT_BIN) + " -o out.png bad.ray", dir);
  CHECK(r.status == 2);
  CHECK(r.err.find("bad.ray:4:") == 0);
  CHECK(r.err.find("all-directions") != std::string::npos);
}
