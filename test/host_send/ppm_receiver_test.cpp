#include <catch2/catch.hpp>

#include "test_support.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <string>

#include "ppm_receiver.hpp"

using minrt::send::ImageSpec;
using minrt::send::PpmKind;
using minrt::send::PpmReceiver;

namespace {

std::string p6_image(int w, int h) {
  std::string s = "P6\n" + std::to_string(w) + " " + std::to_string(h) + " 255\n";
  for (int i = 0; i < w * h * 3; ++i) s.push_back(static_cast<char>((i * 37) & 0xFF));
  return s;
}

std::string p3_image(int w, int h) {
  std::string s = "P3\n" + std::to_string(w) + " " + std::to_string(h) + " 255\n";
  for (int i = 0; i < w * h; ++i)
    s += std::to_string((i * 3) & 0xFF) + " " + std::to_string((i * 7) & 0xFF) + " " + std::to_string(255 - (i & 0xFF)) + "\n";
  return s;
}

// Feeds in chunks of `chunk` bytes; returns the bytes consumed.
size_t feed(PpmReceiver& rx, const std::string& s, size_t chunk) {
  size_t used = 0;
  for (size_t at = 0; at < s.size(); at += chunk) {
    const size_t n = std::min(chunk, s.size() - at);
    used += rx.feed(reinterpret_cast<const uint8_t*>(s.data()) + at, n);
    if (rx.done() || rx.failed() || rx.firmware_error()) break;
  }
  return used;
}

}  // namespace

TEST_CASE("PPM receiver takes a P6 image in any chunking", "[ppm]") {
  const std::string img = p6_image(7, 5);
  for (size_t chunk : {1u, 2u, 3u, 13u, 4096u}) {
    PpmReceiver rx(ImageSpec{7, 5, PpmKind::kP6});
    CHECK(feed(rx, img, chunk) == img.size());
    REQUIRE(rx.done());
    CHECK(rx.rows_complete() == 5);
    CHECK(rx.pixels()[3] == static_cast<uint8_t>(img[11 + 3]));
  }
}

TEST_CASE("PPM receiver stops at the end of the image", "[ppm]") {
  const std::string img = p6_image(2, 2);
  PpmReceiver rx(ImageSpec{2, 2, PpmKind::kP6});
  const std::string more = img + "trailing";
  CHECK(rx.feed(reinterpret_cast<const uint8_t*>(more.data()), more.size()) == img.size());
  CHECK(rx.done());
}

TEST_CASE("PPM receiver parses P3 triplets", "[ppm]") {
  const std::string img = p3_image(4, 3);
  for (size_t chunk : {1u, 5u, 4096u}) {
    PpmReceiver rx(ImageSpec{4, 3, PpmKind::kP3});
    CHECK(feed(rx, img, chunk) == img.size());
    REQUIRE(rx.done());
    CHECK(rx.pixels()[0] == 0);
    CHECK(rx.pixels()[2] == 255);
    CHECK(rx.pixels()[3 * 11 + 1] == 77);
  }
}

TEST_CASE("PPM receiver accepts a P3 image missing only its last newline", "[ppm]") {
  std::string img = p3_image(2, 1);
  img.pop_back();
  PpmReceiver rx(ImageSpec{2, 1, PpmKind::kP3});
  feed(rx, img, 100);
  CHECK_FALSE(rx.done());
  rx.finish();
  CHECK(rx.done());
}

TEST_CASE("PPM receiver reports truncated images", "[ppm]") {
  SECTION("P6") {
    const std::string img = p6_image(8, 8);
    PpmReceiver rx(ImageSpec{8, 8, PpmKind::kP6});
    feed(rx, img.substr(0, img.size() - 10), 64);
    CHECK_FALSE(rx.done());
    rx.finish();
    REQUIRE(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains("truncated") && Catch::Contains("7 of 8 rows"));
  }
  SECTION("P3") {
    const std::string img = p3_image(4, 4);
    PpmReceiver rx(ImageSpec{4, 4, PpmKind::kP3});
    feed(rx, img.substr(0, img.size() / 2), 64);
    rx.finish();
    CHECK(rx.failed());
  }
  SECTION("header") {
    PpmReceiver rx(ImageSpec{8, 8, PpmKind::kP6});
    feed(rx, "P6\n8 ", 64);
    rx.finish();
    REQUIRE(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains("header"));
  }
  SECTION("nothing") {
    PpmReceiver rx(ImageSpec{8, 8, PpmKind::kP6});
    rx.finish();
    REQUIRE(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains("no reply"));
  }
}

TEST_CASE("PPM receiver rejects the wrong size, magic, format and maxval", "[ppm]") {
  auto check = [](const std::string& text, const ImageSpec& spec, const char* what) {
    PpmReceiver rx(spec);
    feed(rx, text, 1);
    INFO(text);
    REQUIRE(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains(what));
  };
  check(p6_image(8, 4), ImageSpec{8, 8, PpmKind::kP6}, "image is 8x4, expected 8x8");
  check(p6_image(4, 8), ImageSpec{8, 8, PpmKind::kP6}, "image is 4x8");
  check("P5\n8 8 255\n", ImageSpec{8, 8, PpmKind::kP6}, "bad PPM magic 'P5'");
  check(p3_image(8, 8), ImageSpec{8, 8, PpmKind::kP6}, "image is P3, expected P6");
  check("P6\n8 8 65535\n", ImageSpec{8, 8, PpmKind::kP6}, "maxval");
  check("P6\n8 x8 255\n", ImageSpec{8, 8, PpmKind::kP6}, "bad PPM header field");
  check("P3\n1 1 255\n1 2 256\n", ImageSpec{1, 1, PpmKind::kP3}, "above 255");
  check("P3\n1 1 255\n1 2 x\n", ImageSpec{1, 1, PpmKind::kP3}, "unexpected byte");
  check("hello", ImageSpec{8, 8, PpmKind::kP6}, "first byte 0x68");
}

TEST_CASE("PPM receiver returns the firmware's error line", "[ppm]") {
  PpmReceiver rx(ImageSpec{8, 8, PpmKind::kP6});
  const std::string line = "!minrt-error: 3:7: bad number 'x'\n";
  CHECK(feed(rx, line, 5) == line.size());
  REQUIRE(rx.firmware_error());
  CHECK(rx.message() == "3:7: bad number 'x'");
}

TEST_CASE("PPM receiver does not take a line without the marker as an error report", "[ppm]") {
  PpmReceiver rx(ImageSpec{8, 8, PpmKind::kP6});
  feed(rx, "!oops\n", 64);
  REQUIRE(rx.failed());
  CHECK_THAT(rx.message(), Catch::Contains("unexpected reply line"));
}

TEST_CASE("expected image size", "[ppm]") {
  CHECK(minrt::send::expected_image_bytes(ImageSpec{512, 512, PpmKind::kP6}) == 15 + 512u * 512u * 3u);
  CHECK(minrt::send::ppm_header(ImageSpec{32, 16, PpmKind::kP3}) == "P3\n32 16 255\n");
}

TEST_CASE("write_file_atomically leaves no partial file", "[ppm]") {
  std::string err;
  CHECK_FALSE(minrt::send::write_file_atomically("/nonexistent-dir/x.ppm", "P6", false, minrt::host::Durability::kSynced, err));
  CHECK_THAT(err, Catch::Contains("/nonexistent-dir/x.ppm"));
}

TEST_CASE("host-send -o refuses a FIFO or a symbolic link before the transfer", "[cli]") {
  hs_test::TempDir dir;
  const std::string fifo = dir.file("fifo"), link = dir.file("link");
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  REQUIRE(::symlink(dir.file("elsewhere").c_str(), link.c_str()) == 0);
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  for (const std::string& target : {fifo, link}) {
    // Checked before the board is even started.
    const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", HS_STANDIN, "--sim", HS_STANDIN, scene,
                                 "-o", target});
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("refusing to replace " + target));
  }
  struct stat st {};
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  REQUIRE(::lstat(link.c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
}
