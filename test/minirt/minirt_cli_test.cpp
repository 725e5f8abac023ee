// minrt on miniRT files as a student meets it: every valid shared scene
// renders to its reviewed golden image; every shared invalid file, every
// file of test/minirt/bad and every command-line mistake of SPEC.md 2.7
// gives "Error", one explicit line naming what and where, status 1, and no
// image.
#include <catch2/catch.hpp>

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sha256.hpp"
#include "test_support.hpp"

namespace {

using Run = minrt::test::CommandRun;

std::string temp_dir() { return minrt::test::temp_dir("minirt"); }

// Runs minrt in `cwd` with shell words `args`; no display, so a window
// cannot open by accident.
Run run_in(const std::string& cwd, const std::string& args) {
  return minrt::test::run_in_dir(
      cwd, std::string("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER ") + MINRT_BIN + " " + args);
}

bool exists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

// The subject's error form: "Error\n" then one non-empty line.
void check_error(const Run& r, const std::string& fragment) {
  INFO(r.err);
  CHECK(r.status == 1);
  REQUIRE(r.err.rfind("Error\n", 0) == 0);
  const std::string rest = r.err.substr(6);
  CHECK(!rest.empty());
  CHECK(rest.find('\n') == rest.size() - 1);  // exactly one line
  CHECK(rest.find(fragment) != std::string::npos);
}

struct Row {
  std::string file, rule, text;
};
std::vector<Row> read_tsv(const std::string& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream f(line);
    Row r;
    std::getline(f, r.file, '\t');
    std::getline(f, r.rule, '\t');
    std::getline(f, r.text);
    rows.push_back(r);
  }
  return rows;
}

std::set<std::string> rt_files(const std::string& dir) {
  std::set<std::string> out;
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > 3 && n.compare(n.size() - 3, 3, ".rt") == 0) out.insert(n);
    }
    closedir(d);
  }
  return out;
}

// Pixels of two same-size P6 images (maxval 255, single-space headers as
// minrt writes them) differing by more than 1 in a channel; -1 on a size or
// header mismatch.
long pixels_off(const std::string& a, const std::string& b) {
  if (a.size() != b.size() || a.size() < 16) return -1;
  std::size_t header = 0;
  for (int newlines = 0; header < a.size() && newlines < 3; ++header) newlines += a[header] == '\n';
  if (a.compare(0, header, b, 0, header) != 0) return -1;
  long off = 0;
  for (std::size_t i = header; i + 2 < a.size(); i += 3) {
    bool far = false;
    for (int c = 0; c < 3; ++c)
      far = far || std::abs(static_cast<unsigned char>(a[i + c]) - static_cast<unsigned char>(b[i + c])) > 1;
    off += far;
  }
  return off;
}

const std::string kOwnBad = std::string(MINRT_SOURCE_DIR) + "/test/minirt/bad";
const std::string kTables = std::string(MINRT_SOURCE_DIR) + "/test/minirt";
std::string shared_minirt() { return minrt::test::shared_dir() + "/formats/minirt"; }

}  // namespace

TEST_CASE("minrt miniRT: every shared valid scene renders to its reviewed golden image, on its path and on the full one, and float is within rounding", "[minirt][golden]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::vector<Row> rows = read_tsv(kTables + "/golden.tsv");
  std::set<std::string> listed;
  const std::string out = temp_dir();
  for (const Row& r : rows) {  // file, sha256 (in the "rule" column)
    listed.insert(r.file);
    INFO(r.file);
    const Run run = run_in(out, "'" + shared_minirt() + "/valid/" + r.file + "' -o image.ppm");
    CHECK(run.status == 0);
    CHECK(run.err.empty());
    CHECK(minrt::host::sha256_hex(minrt::test::read_file(out + "/image.ppm")) == r.rule);
    // The board's arithmetic (float, portable shims) is within rounding of
    // the double image: at most 0.01 % of the pixels off by more than 1.
    CHECK(run_in(out, "--precision float --shims portable '" + shared_minirt() + "/valid/" + r.file + "' -o f.ppm")
              .status == 0);
    CHECK(pixels_off(minrt::test::read_file(out + "/image.ppm"), minrt::test::read_file(out + "/f.ppm")) <= 48);
    // The path with every feature compiled in gives the same bytes.
    CHECK(run_in(out, "--all-features '" + shared_minirt() + "/valid/" + r.file + "' -o all.ppm").status == 0);
    CHECK(minrt::host::sha256_hex(minrt::test::read_file(out + "/all.ppm")) == r.rule);
  }
  CHECK(listed == rt_files(shared_minirt() + "/valid"));
}

TEST_CASE("minrt miniRT: the 30 shared invalid files give Error and their reason", "[minirt][errors]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::vector<Row> rows = read_tsv(kTables + "/shared_invalid.tsv");
  std::set<std::string> listed;
  const std::string out = temp_dir();
  for (const Row& r : rows) {
    listed.insert(r.file);
    INFO(r.file);
    // Relative to the folder, so the message starts with the bare file name.
    const Run run = run_in(shared_minirt() + "/invalid", r.file + " -o '" + out + "/image.png'");
    check_error(run, r.text);
    CHECK_FALSE(exists(out + "/image.png"));
  }
  CHECK(listed.size() == 30);
  CHECK(listed == rt_files(shared_minirt() + "/invalid"));
}

TEST_CASE("minrt miniRT: every file of test/minirt/bad gives Error and its reason", "[minirt][errors]") {
  const std::vector<Row> rows = read_tsv(kOwnBad + "/EXPECTED.tsv");
  std::set<std::string> listed;
  const std::string out = temp_dir();
  for (const Row& r : rows) {
    listed.insert(r.file);
    INFO(r.file);
    const Run run = run_in(kOwnBad, r.file + " -o '" + out + "/image.png'");
    check_error(run, r.text);
    CHECK_FALSE(exists(out + "/image.png"));
  }
  CHECK(listed == rt_files(kOwnBad));  // no file without its expected message
}

TEST_CASE("minrt miniRT: command-line mistakes give Error too (SPEC.md 2.7)", "[minirt][errors][cli]") {
  const std::string dir = temp_dir();
  const std::string scene = "A 0.2 255,255,255\nC 0,0,10 0,0,-1 70\nL 0,5,5 0.8 255,255,255\nsp 0,0,0 2 255,0,0\n";
  std::ofstream(dir + "/good.rt") << scene;
  std::ofstream(dir + "/good.txt") << scene;
  std::ofstream(dir + "/good.rt.bak") << scene;
  std::ofstream(dir + "/.rt") << scene;
  ::mkdir((dir + "/folder.rt").c_str(), 0755);

  check_error(run_in(dir, "good.txt -o out.png"), "good.txt: a miniRT scene file's name must end in .rt");
  check_error(run_in(dir, "good.rt.bak -o out.png"), "must end in .rt");
  check_error(run_in(dir, ".rt -o out.png"), "must end in .rt");
  check_error(run_in(dir, "missing.rt -o out.png"), "missing.rt: cannot read the scene: No such file or directory");
  check_error(run_in(dir, "folder.rt -o out.png"), "folder.rt: cannot read the scene: Is a directory");
  check_error(run_in(dir, "good.rt good.rt -o out.png"), "expected one scene file");
  check_error(run_in(dir, "good.rt -o out.jpg"), "must end in .png, .ppm, .bmp, .tif or .tiff");
  check_error(run_in(dir, "--scene-format minirt - -o out.png"), "not from standard input");
  check_error(run_in(dir, "good.rt --bogus -o out.png"), "unknown option '--bogus'");
  check_error(run_in(dir, "good.rt --size 0x0 -o out.png"), "bad --size '0x0'");
  if (geteuid() != 0) {  // root reads anything
    std::ofstream(dir + "/locked.rt") << scene;
    ::chmod((dir + "/locked.rt").c_str(), 0);
    check_error(run_in(dir, "locked.rt -o out.png"), "locked.rt: cannot read the scene: Permission denied");
  }
  CHECK_FALSE(exists(dir + "/out.png"));
  CHECK_FALSE(exists(dir + "/out.jpg"));
  // Without a display and without -o there is nothing to show the image on.
  const Run headless = run_in(dir, "good.rt");
  check_error(headless, "give -o FILE.png");
  // And the good scene itself is fine, as PNG and as PPM.
  CHECK(run_in(dir, "good.rt -o out.png").status == 0);
  CHECK(run_in(dir, "good.rt --size 64x48 -o out.ppm").status == 0);
  CHECK(minrt::test::read_file(dir + "/out.ppm").rfind("P6\n64 48\n255\n", 0) == 0);
}

TEST_CASE("minrt miniRT --mandatory: the mandatory-only shared scenes render, the bonus ones give Error", "[minirt][errors][mandatory]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  // SPEC.md 2.4's split of the 18 valid scenes.
  const std::set<std::string> mandatory_only = {"cylinders.rt", "mandatory_basic.rt", "mandatory_shadows.rt",
                                                "room_test1.rt", "room_test2.rt", "room_test3.rt",
                                                "spheres.rt", "test.rt"};
  const std::string out = temp_dir();
  for (const std::string& file : rt_files(shared_minirt() + "/valid")) {
    INFO(file);
    const Run run = run_in(shared_minirt() + "/valid", "--mandatory --size 64x48 " + file + " -o '" + out + "/m.ppm'");
    if (mandatory_only.count(file) != 0) {
      CHECK(run.status == 0);
      CHECK(run.err.empty());
    } else {
      // The first bonus element or second light, located.
      const bool bonus = run.err.find("is a bonus element") != std::string::npos;
      const bool second = run.err.find("second light 'L'") != std::string::npos;
      CHECK((bonus || second));
      check_error(run, file + ":");
      CHECK_FALSE(exists(out + "/m.ppm"));
    }
    std::remove((out + "/m.ppm").c_str());
  }
  // The options belong to miniRT: elsewhere they are a usage error.
  const Run sld = minrt::test::run_in_dir(out, std::string(MINRT_BIN) + " --mandatory '" +
                                                   minrt::test::shared_dir() + "/scenes/contest.sld' --size 8x8");
  CHECK(sld.status == 2);
  CHECK(sld.err.find("--mandatory applies to 42 miniRT scenes only") != std::string::npos);
}
