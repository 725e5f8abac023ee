// minrt on CS418 files as a student meets it: the PNG named in the scene,
// -o, located errors with status 2 and no image for every broken file in
// test/cs418/bad, the output checked before the render.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "png_io.hpp"
#include "test_support.hpp"

namespace {

using Run = minrt::test::CommandRun;

std::string temp_dir() { return minrt::test::temp_dir("cs418"); }

// Runs minrt in `cwd` with shell words `args`, standard input from `input`.
Run run_in(const std::string& cwd, const std::string& args, const std::string& input = "/dev/null") {
  return minrt::test::run_in_dir(cwd, std::string(MINRT_BIN) + " " + args, input);
}

bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

const std::string kBad = std::string(MINRT_SOURCE_DIR) + "/test/cs418/bad";

}  // namespace

TEST_CASE("minrt CS418: writes the PNG named on the png line, or -o", "[cs418][cli]") {
  const std::string dir = temp_dir();
  {
    std::ofstream(dir + "/scene.txt") << "png 30 20 named.png\nsphere 0 0 -2 1\nsun 1 1 1\n";
  }
  const Run r = run_in(dir, "scene.txt");
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  minrt::host::RgbaImage img;
  std::string why;
  REQUIRE(minrt::host::read_png(dir + "/named.png", img, why));
  CHECK(img.width == 30);
  CHECK(img.height == 20);
  CHECK(img.rgba[4 * (10 * 30 + 15) + 3] == 255);  // the sphere covers the centre
  CHECK(img.rgba[3] == 0);                          // a corner misses: transparent

  CHECK(run_in(dir, "-o other.ppm scene.txt").status == 0);
  CHECK(minrt::test::read_file(dir + "/other.ppm").rfind("P6\n30 20\n255\n", 0) == 0);
  // Without the .txt extension the first word decides; --scene-format too.
  std::rename((dir + "/scene.txt").c_str(), (dir + "/scene.dat").c_str());
  CHECK(run_in(dir, "-o sniffed.png scene.dat").status == 0);
  CHECK(exists(dir + "/sniffed.png"));
  CHECK(run_in(dir, "--scene-format cs418 -o forced.png -", dir + "/scene.dat").status == 0);
  CHECK(exists(dir + "/forced.png"));
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("minrt CS418: every broken file gets its located error, status 2 and no image", "[cs418][cli][errors]") {
  std::ifstream expected(kBad + "/EXPECTED");
  std::string line;
  int n = 0;
  while (std::getline(expected, line)) {
    const std::string file = line.substr(0, line.find(':'));
    std::string want = line;
    for (std::size_t at; (at = want.find("BAD/")) != std::string::npos;) want.replace(at, 3, kBad);
    const std::string dir = temp_dir();
    const Run r = run_in(dir, "'" + kBad + "/" + file + "'");
    INFO(file);
    CHECK(r.status == 2);
    CHECK(r.err == kBad + "/" + want + "\n");
    CHECK(!exists(dir + "/bad.png"));
    const Run o = run_in(dir, "-o out.png '" + kBad + "/" + file + "'");
    CHECK(o.status == 2);
    CHECK(!exists(dir + "/out.png"));
    std::system(("rm -rf '" + dir + "'").c_str());
    ++n;
  }
  CHECK(n == 8);
}

TEST_CASE("minrt CS418: an unwritable output is refused before rendering", "[cs418][cli][errors]") {
  const std::string dir = temp_dir();
  {
    std::ofstream(dir + "/scene.txt") << "png 30 20 sub\nsphere 0 0 -2 1\nsun 1 1 1\n";
  }
  ::mkdir((dir + "/sub").c_str(), 0755);
  const Run r = run_in(dir, "scene.txt");
  CHECK(r.status == 1);
  CHECK(r.err.find("minrt: error:") == 0);
  CHECK(r.err.find("sub") != std::string::npos);
  const Run missing = run_in(dir, "-o no/such/dir/x.png scene.txt");
  CHECK(missing.status == 1);
  std::system(("rm -rf '" + dir + "'").c_str());
}
