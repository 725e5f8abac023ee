// The one bound on a scene file's size (host/file_input.hpp kMaxSceneBytes)
// as every host tool meets it: minrt in each text format and on standard
// input, an EASTRAY include, host-send; and host-send's other inputs, the
// --program image (the board's program region) and the --verify reference.
// The files are sparse: a real header, then a hole up to one byte over the
// bound, so the test costs no disk.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <minrt/memory_map.h>

#include "file_input.hpp"
#include "test_support.hpp"
#include "verify.hpp"

namespace {

using minrt::test::run_in_dir;
using Run = minrt::test::CommandRun;

std::string temp_dir() { return minrt::test::temp_dir("scene-size"); }

// `head`, then a hole up to one byte more than `bound`.
void write_oversized(const std::string& path, const std::string& head,
                     std::size_t bound = minrt::host::kMaxSceneBytes) {
  { std::ofstream(path, std::ios::binary) << head; }
  REQUIRE(::truncate(path.c_str(), static_cast<off_t>(bound + 1)) == 0);
}

// Names in `dir` other than . and ..
int entries(const std::string& dir) {
  int n = 0;
  DIR* d = ::opendir(dir.c_str());
  REQUIRE(d != nullptr);
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name != "." && name != "..") ++n;
  }
  ::closedir(d);
  return n;
}

// One red ball: a valid SLD scene, so that host-send gets past the scene.
constexpr const char* kBall =
    "0 0 -100 0 0\n1 0 0\n255\n0 3 1 0 50 50 50 0 0 0 1 1 250 255 0 0\n-1\n0 -1\n-1\n99 0 -1\n-1\n";

const std::string kTooLarge = "larger than " + std::to_string(minrt::host::kMaxSceneBytes) + " bytes";

}  // namespace

TEST_CASE("minrt refuses a scene file over the size bound in every text format, one line, no image",
          "[cli][bad][size]") {
  struct Case {
    const char* name;
    const char* file;
    const char* head;
    const char* expected;  // the line as the format's errors are written
  };
  const Case cases[] = {
      {"CS418", "scene.txt", "png 8 8 out.png\nsphere 0 0 -2 1\n", "minrt: error: cannot read scene.txt: "},
      {"Jaworski", "scene.txt", "imWidth 8\nimHeight 8\n", "minrt: error: cannot read scene.txt: "},
      {"EASTRAY", "scene.ray", "display 8 8\n", "minrt: error: cannot read scene.ray: "},
      {"miniRT", "scene.rt", "A 0.2 255,255,255\n", "Error\nscene.rt: cannot read the scene: "},
  };
  for (const Case& c : cases) {
    SECTION(c.name) {
      const std::string dir = temp_dir();
      write_oversized(dir + "/" + c.file, c.head);
      const Run r = run_in_dir(dir, std::string(MINRT_BIN) + " " + c.file + " -o out.png");
      CHECK(r.status != 0);
      CHECK(r.err == std::string(c.expected) + kTooLarge + "\n");
      CHECK(entries(dir) == 1);  // the scene alone: no image, no temporary
      std::system(("rm -rf '" + dir + "'").c_str());
    }
  }
}

TEST_CASE("minrt refuses an EASTRAY include over the size bound", "[cli][bad][size][eastray]") {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/scene.ray") << "#include \"big.inc\"\ndisplay 8 8\n"; }
  write_oversized(dir + "/big.inc", "/* included */\n");
  const Run r = run_in_dir(dir, std::string(MINRT_BIN) + " scene.ray -o out.png");
  CHECK(r.status != 0);
  // Refused by the preprocessor's budget (64 times the scene, at least
  // 1 MiB) before the size bound, and before it is read.
  CHECK_THAT(r.err, Catch::Contains("big.inc") && Catch::Contains("bytes left of the scene's budget"));
  CHECK(r.err.find('\n') == r.err.size() - 1);  // one line
  CHECK(entries(dir) == 2);
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("host-send refuses a scene file over the size bound before it opens a port", "[send][bad][size]") {
  const std::string dir = temp_dir();
  write_oversized(dir + "/scene.txt", "png 8 8 out.png\nsphere 0 0 -2 1\n");
  const Run r = run_in_dir(dir, std::string(MINRT_SEND_BIN) + " --sim scene.txt");
  CHECK(r.status != 0);
  CHECK_THAT(r.err, Catch::Contains("cannot read scene.txt: " + kTooLarge));
  CHECK(r.err.find('\n') == r.err.size() - 1);
  CHECK(entries(dir) == 1);
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("minrt refuses standard input over the scene bound, from a pipe or a file, one line, no image",
          "[cli][bad][size]") {
  const std::string dir = temp_dir();
  const std::string expected = "minrt: error: cannot read <stdin>: " + kTooLarge + "\n";
  SECTION("a pipe: read up to the bound, then refused") {
    const Run r = run_in_dir(dir, "(head -c " + std::to_string(minrt::host::kMaxSceneBytes + 1) + " /dev/zero | " +
                                      MINRT_BIN + " -o out.png)");
    CHECK(r.status == 2);
    CHECK(r.err == expected);
    CHECK(entries(dir) == 0);
  }
  SECTION("a file: refused by its size before reading") {
    write_oversized(dir + "/scene.txt", "png 8 8 out.png\nsphere 0 0 -2 1\n");
    const Run r = run_in_dir(dir, std::string(MINRT_BIN) + " -o out.png", dir + "/scene.txt");
    CHECK(r.status == 2);
    CHECK(r.err == expected);
    CHECK(entries(dir) == 1);
  }
  SECTION("at the bound exactly: read, then judged as a scene") {
    write_oversized(dir + "/scene.txt", "png 8 8 out.png\nsphere 0 0 -2 1\n", minrt::host::kMaxSceneBytes - 1);
    const Run r = run_in_dir(dir, std::string(MINRT_BIN) + " -o out.png", dir + "/scene.txt");
    CHECK(r.err.find(kTooLarge) == std::string::npos);
  }
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("host-send refuses a --program larger than the board's program region before it opens a port",
          "[send][bad][size]") {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/scene.sld") << kBall; }
  write_oversized(dir + "/big.bin", "\x6f", MINRT_PROGRAM_MAX_SIZE);
  const Run r = run_in_dir(dir, std::string(MINRT_SEND_BIN) + " --sim --protocol course --program big.bin scene.sld");
  CHECK(r.status == 2);
  CHECK(r.err == "host-send: error: cannot read big.bin: larger than " + std::to_string(MINRT_PROGRAM_MAX_SIZE) +
                     " bytes\n");
  CHECK(entries(dir) == 2);  // no image
  std::system(("rm -rf '" + dir + "'").c_str());
}

TEST_CASE("host-send refuses a --verify reference larger than the largest image before it opens a port",
          "[send][bad][size]") {
  const std::string dir = temp_dir();
  { std::ofstream(dir + "/scene.sld") << kBall; }
  write_oversized(dir + "/ref.ppm", "P3\n4096 4096\n255\n", minrt::send::kMaxReferenceBytes);
  const Run r = run_in_dir(dir, std::string(MINRT_SEND_BIN) + " --sim --verify ref.ppm scene.sld");
  CHECK(r.status == 2);
  CHECK(r.err == "host-send: error: cannot read ref.ppm: larger than " +
                     std::to_string(minrt::send::kMaxReferenceBytes) + " bytes\n");
  CHECK(entries(dir) == 2);
  std::system(("rm -rf '" + dir + "'").c_str());
}
