// The one bound on a scene file's size (host/file_input.hpp kMaxSceneBytes)
// as every host tool meets it: minrt in each text format, an EASTRAY
// include, host-send. The files are sparse: a real header, then a hole up
// to one byte over the bound, so the test costs no disk.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "file_input.hpp"
#include "test_support.hpp"

namespace {

using minrt::test::run_in_dir;
using Run = minrt::test::CommandRun;

std::string temp_dir() { return minrt::test::temp_dir("scene-size"); }

// `head`, then a hole up to one byte more than the bound.
void write_oversized(const std::string& path, const std::string& head) {
  { std::ofstream(path, std::ios::binary) << head; }
  REQUIRE(::truncate(path.c_str(), static_cast<off_t>(minrt::host::kMaxSceneBytes + 1)) == 0);
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
  CHECK_THAT(r.err, Catch::Contains("big.inc") && Catch::Contains(kTooLarge));
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
