#include <catch2/catch.hpp>

#include <cmath>

#include "verify.hpp"

using namespace minrt::send;

TEST_CASE("P3 and P6 files with the same pixels parse the same", "[verify]") {
  Image a, b;
  std::string err;
  REQUIRE(parse_ppm("P3\n2 1 255\n1 2 3\n250 251 252\n", a, err));
  REQUIRE(parse_ppm(std::string("P6\n2 1 255\n\x01\x02\x03\xfa\xfb\xfc", 17), b, err));
  CHECK(a.rgb == b.rgb);
  const Comparison c = compare_images(a, b);
  CHECK(c.same_size);
  CHECK(c.differing_pixels == 0);
  CHECK(std::isinf(c.psnr_db));
  CHECK(describe(c) == "0 pixels differ, max channel error 0, PSNR inf dB");
}

TEST_CASE("comparison counts pixels, maximum error and PSNR", "[verify]") {
  Image a, b;
  std::string err;
  REQUIRE(parse_ppm("P3\n2 2 255\n0 0 0 0 0 0 0 0 0 0 0 0\n", a, err));
  REQUIRE(parse_ppm("P3\n2 2 255\n0 0 0 0 0 0 0 0 0 0 0 0\n", b, err));
  b.rgb[4] = 10;
  b.rgb[9] = 3;
  const Comparison c = compare_images(a, b);
  CHECK(c.differing_pixels == 2);
  CHECK(c.max_channel_error == 10);
  const double mse = (100.0 + 9.0) / 12.0;
  CHECK(c.psnr_db == Approx(10 * std::log10(255.0 * 255.0 / mse)));
}

TEST_CASE("bad reference files are refused", "[verify]") {
  Image a;
  std::string err;
  CHECK_FALSE(parse_ppm("P5\n1 1 255\n", a, err));
  CHECK_FALSE(parse_ppm("P6\n2 2 255\nabc", a, err));
  CHECK_FALSE(parse_ppm("P3\n1 1 255\n1 2\n", a, err));
  CHECK_FALSE(load_ppm("/nonexistent.ppm", a, err));
}

TEST_CASE("sha256 helpers", "[verify]") {
  CHECK(sha256_hex_of("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(valid_sha256_hex("BA7816BF8F01CFEA414140DE5DAE2223B00361A396177A9CB410FF61F20015AD"));
  CHECK_FALSE(valid_sha256_hex("abc"));
  CHECK(same_sha256("ABCD", "abcd"));
}
