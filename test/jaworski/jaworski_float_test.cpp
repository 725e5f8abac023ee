// Jaworski's scenes in float (the board's precision, `--precision float
// --shims portable`) against the original program's double images: at most
// kMaxShare of the pixels may differ at all (any channel by any amount),
// scene by scene. Prints each scene's count (ctest -V shows them).
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "image_load.hpp"
#include "test_support.hpp"

namespace {

constexpr double kMaxShare = 0.005;  // 0.5 % of the pixels

int run(const std::string& command) {
  const int rc = std::system((command + " </dev/null").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// Pixels whose R, G or B differ (both images opaque, as Jaworski's BMPs are).
long differing_pixels(const minrt::host::RgbaImage& a, const minrt::host::RgbaImage& b) {
  long n = 0;
  for (size_t i = 0; i + 3 < a.rgba.size(); i += 4)
    if (a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2]) ++n;
  return n;
}

// Renders `scene` in float and compares it with `reference`.
void check_float(const std::string& name, const std::string& scene, const std::string& reference,
                 const std::string& dir) {
  const std::string out = dir + "/float.bmp";
  REQUIRE(run(std::string(MINRT_BIN) + " -q --precision float --shims portable -o '" + out + "' '" + scene + "'") ==
          0);
  minrt::host::RgbaImage ref, got;
  std::string error;
  REQUIRE(minrt::host::load_image(reference, ref, error));
  REQUIRE(minrt::host::load_image(out, got, error));
  std::remove(out.c_str());
  REQUIRE(ref.width == got.width);
  REQUIRE(ref.height == got.height);
  const long pixels = static_cast<long>(ref.width) * ref.height;
  const long off = differing_pixels(ref, got);
  std::printf("%-36s %7ld of %8ld pixels differ (%.3f%%)\n", name.c_str(), off, pixels, 100.0 * off / pixels);
  INFO(name << ": " << off << " of " << pixels << " pixels differ");
  CHECK(off <= static_cast<long>(kMaxShare * pixels));
}

}  // namespace

TEST_CASE("Jaworski float: each shared scene differs from the original in at most 0.5% of pixels",
          "[jaworski][float]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string jw = minrt::test::shared_dir() + "/formats/jaworski/";
  std::ifstream manifest(jw + "manifest.tsv");
  std::string line;
  std::getline(manifest, line);  // header
  char dir[] = "/tmp/minrt-jwf-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  int n = 0;
  while (std::getline(manifest, line)) {
    std::istringstream f(line);
    std::string scene, bmp;
    f >> scene >> bmp;
    check_float(scene, jw + scene, jw + bmp, dir);
    ++n;
  }
  rmdir(dir);
  CHECK(n == 24);
}

// The speed scene (bench/host/make_jaworski_scene.py); its reference is our
// double image, which bench/host/jaworski_speed.sh checks to be the
// original's, byte for byte.
TEST_CASE("Jaworski float: the speed scene differs from the double image in at most 0.5% of pixels",
          "[jaworski][float]") {
  char dir[] = "/tmp/minrt-jwf-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string d = dir, scene = d + "/speed.txt", reference = d + "/double.bmp";
  REQUIRE(run(std::string("python3 '") + MINRT_SOURCE_DIR + "/bench/host/make_jaworski_scene.py' >'" + scene + "'") ==
          0);
  REQUIRE(run(std::string(MINRT_BIN) + " -q -o '" + reference + "' '" + scene + "'") == 0);
  check_float("speed scene", scene, reference, d);
  std::remove(scene.c_str());
  std::remove(reference.c_str());
  rmdir(dir);
}
