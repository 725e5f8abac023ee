// Jaworski's scenes: the double build writes the original program's BMPs
// byte for byte (sha256 of ../shared/formats/jaworski/manifest.tsv); every
// file the original rejects gets our located error, status 2 and no file;
// the number and keyword forms of the grammar.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "core/math/math_libm.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "sha256.hpp"
#include "test_support.hpp"

namespace {

struct Run {
  int status = -1;
  std::string err;
};

Run run_minrt(const std::string& args) {
  char errf[] = "/tmp/minrt-jw-err-XXXXXX";
  const int fd = mkstemp(errf);
  REQUIRE(fd >= 0);
  close(fd);
  const int rc = std::system((std::string(MINRT_BIN) + " " + args + " 2>" + errf + " >/dev/null </dev/null").c_str());
  Run r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.err = minrt::test::read_file(errf);
  std::remove(errf);
  return r;
}

std::string jw_dir() { return minrt::test::shared_dir() + "/formats/jaworski/"; }

struct Parsed {
  bool ok;
  std::string error;
  minrt::jaworski::Scene<double> scene;
  std::vector<unsigned char> storage = std::vector<unsigned char>(1 << 20);
};

std::unique_ptr<Parsed> parse(const std::string& text) {
  auto p = std::make_unique<Parsed>();
  minrt::Arena arena(p->storage.data(), p->storage.size());
  REQUIRE(p->scene.allocate(arena, 64));
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::jaworski::Reader<minrt::LibmDouble> reader(mem.source(), p->scene);
  minrt::Diagnostic d;
  p->ok = reader.read(d);
  if (!p->ok) p->error = std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": " + d.message;
  return p;
}

}  // namespace

TEST_CASE("Jaworski: the double build writes the original's 24 BMPs byte for byte", "[jaworski][golden]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  std::ifstream manifest(jw_dir() + "manifest.tsv");
  std::string line;
  std::getline(manifest, line);  // header
  int n = 0;
  char dir[] = "/tmp/minrt-jw-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  while (std::getline(manifest, line)) {
    std::istringstream f(line);
    std::string scene, bmp, sha;
    f >> scene >> bmp >> sha;
    const std::string out = std::string(dir) + "/" + bmp;
    const Run r = run_minrt("-q -o '" + out + "' '" + jw_dir() + scene + "'");
    INFO(scene << ": " << r.err);
    REQUIRE(r.status == 0);
    CHECK(minrt::host::sha256_hex(minrt::test::read_file(out)) == sha);
    // Rows rendered on one or three threads: the same bytes.
    for (const char* threads : {"1", "3"}) {
      REQUIRE(run_minrt(std::string("-q --threads ") + threads + " -o '" + out + "' '" + jw_dir() + scene + "'").status == 0);
      CHECK(minrt::host::sha256_hex(minrt::test::read_file(out)) == sha);
    }
    std::remove(out.c_str());
    ++n;
  }
  rmdir(dir);
  CHECK(n == 24);
}

TEST_CASE("Jaworski: files the original rejects get a located error, status 2 and no file", "[jaworski][errors]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::pair<const char*, const char*> cases[] = {
      {"bad-depth-below-eps", "2:55: error: depth 0.000001 must be >= 1e-05"},
      {"bad-float-image-size", "2:9: error: expected an integer, found '64.5'"},
      {"bad-missing-depth", "4:1: error: missing header field 'depth', found 'lights'"},
      {"bad-missing-header", "2:1: error: missing header field 'imwidth', found 'lights'"},
      {"bad-missing-lights-keyword", "4:1: error: expected 'lights' (the light list, may be empty), found 'objects'"},
      {"bad-mixed-weight-without-surface",
       "7:1: error: expected a surface: diffusive, reflective, luminous or mixed, found 'plane'"},
      {"bad-negative-image-height", "2:21: error: image height -48 must be in 1..16384"},
      {"bad-negative-light-intensity", "6:11: error: light intensity x colour must be >= 0 in every component"},
      {"bad-nested-mixed-negative-weight", "8:69: error: mixed weight -0.25 must be >= 0"},
      {"bad-unknown-colour", "6:26: error: expected a colour (R G B or a colour name), found 'orange'"},
      {"bad-unknown-keyword", "7:1: error: expected 'sphere', 'plane' or the end of the scene, found 'cube'"},
      {"bad-zero-image-width", "4:9: error: image width 0 must be in 1..16384"},
  };
  char dir[] = "/tmp/minrt-jw-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  for (const auto& [name, message] : cases) {
    const std::string scene = jw_dir() + "bad/" + name + ".txt";
    const std::string out = std::string(dir) + "/out.bmp";
    const Run r = run_minrt("-o '" + out + "' '" + scene + "'");
    INFO(name);
    CHECK(r.status == 2);
    CHECK(r.err == scene + ":" + message + "\n");
    struct stat st {};
    CHECK(::stat(out.c_str(), &st) != 0);
  }
  rmdir(dir);
}

TEST_CASE("Jaworski reader: numbers, names, case and comments", "[jaworski][reader]") {
  const std::string head = "imWidth 0x10 IMHEIGHT 0o10 canvwidth +2.5 canvHeight 1E0 depth 2E-1#c\n";
  auto p = parse(head + "lights objects");
  REQUIRE(p->ok);
  CHECK(p->scene.width == 16);
  CHECK(p->scene.height == 8);
  CHECK(p->scene.canvas_width == 2.5);
  CHECK(p->error.empty());
  // A negative canvas height is the original's validation error.
  CHECK(parse("imwidth 1 imheight 1 canvwidth 1 canvheight - 1 depth 1 lights objects")->error ==
        "1:45: canvas height -1 must be >= 0");
  CHECK(parse("imwidth 1 imheight 1 canvwidth .5 canvheight 1 depth 1 lights objects")->error ==
        "1:32: expected a number, found '.'");
  CHECK(parse("imwidth 1 imheight 1 canvwidth 5. canvheight 1 depth 1 lights objects")->error ==
        "1:32: expected a number, found '5.'");
  const auto scene = parse(
      "imwidth 2 imheight 2 canvwidth 1 canvheight 1 depth 1 bgColor Cyan rayDepth 3\n"
      "LIGHTS directional 2 yellow 0 0 1 spherical 1 1 1 1 0 5 0\n"
      "objects sphere 0 0 5 1 mixed 0.5 diffusive red 0.5 mixed 1 reflective 2 luminous blue\n"
      "plane 0 -1 0 0 3 0 reflective");
  REQUIRE(scene->ok);
  const auto& s = scene->scene;
  CHECK(s.background.y == 1.0);
  CHECK(s.ray_depth == 3);
  REQUIRE(s.light_count == 2);
  CHECK(s.lights[0].color.x == 2.0);
  CHECK(s.lights[0].vector.z == -1.0);  // toward the light: the opposite of its travel
  REQUIRE(s.object_count == 2);
  CHECK(s.objects[1].normal.y == 1.0);  // normalised
  // The nested mixture took both pairs after it (greedy, like the original).
  const auto& root = s.surfaces[s.objects[0].surface];
  REQUIRE(root.s.kind == minrt::jaworski::SurfaceKind::kMixed);
  const auto& second = s.parts[s.parts[root.s.first_part].next];
  CHECK(second.next == minrt::jaworski::kNone);
  const auto& nested = s.surfaces[second.surface];
  REQUIRE(nested.s.kind == minrt::jaworski::SurfaceKind::kMixed);
  CHECK(s.parts[s.parts[nested.s.first_part].next].weight == 2.0);
}

namespace {

// Runs `command` in sh with MINRT standing for the binary; the status.
int shell(const std::string& command) {
  const int rc = std::system(("MINRT='" + std::string(MINRT_BIN) + "'; " + command).c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

// The rows go to a BMP or PPM file as they are rendered, each at its place
// (host/row_file_writer.hpp); standard output that is not an empty file at
// its start (a pipe, a file opened to append) gets the image written whole
// after the render. Every way gives the same image.
TEST_CASE("Jaworski: rows written as rendered: file, standard output, pipe, append and PPM agree",
          "[jaworski][output]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string scene = jw_dir() + "colour-names-all.txt";
  const std::string golden = minrt::test::read_file(jw_dir() + "colour-names-all.bmp");
  REQUIRE(golden.size() > 54);
  char dir_buf[] = "/tmp/minrt-jw-XXXXXX";
  REQUIRE(mkdtemp(dir_buf) != nullptr);
  const std::string dir = dir_buf;
  const std::string q = "'" + scene + "'";

  CHECK(shell("$MINRT -q --threads 2 -o - " + q + " >'" + dir + "/stdout.bmp'") == 0);
  CHECK(minrt::test::read_file(dir + "/stdout.bmp") == golden);
  CHECK(shell("$MINRT -q --threads 2 -o - " + q + " | cat >'" + dir + "/pipe.bmp'") == 0);
  CHECK(minrt::test::read_file(dir + "/pipe.bmp") == golden);
  CHECK(shell("printf before >'" + dir + "/append.bmp' && $MINRT -q -o - " + q + " >>'" + dir + "/append.bmp'") == 0);
  CHECK(minrt::test::read_file(dir + "/append.bmp") == "before" + golden);

  // The PPM: the BMP's pixels (BGRA, bottom row first) as RGB, top row first.
  REQUIRE(shell("$MINRT -q --threads 3 -o '" + dir + "/out.ppm' " + q) == 0);
  const std::string ppm = minrt::test::read_file(dir + "/out.ppm");
  auto u32 = [&](std::size_t at) {
    return static_cast<uint32_t>(static_cast<unsigned char>(golden[at])) |
           static_cast<uint32_t>(static_cast<unsigned char>(golden[at + 1])) << 8 |
           static_cast<uint32_t>(static_cast<unsigned char>(golden[at + 2])) << 16 |
           static_cast<uint32_t>(static_cast<unsigned char>(golden[at + 3])) << 24;
  };
  const uint32_t w = u32(18), h = u32(22);
  const std::string header = "P6\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  REQUIRE(ppm.size() == header.size() + std::size_t{3} * w * h);
  CHECK(ppm.compare(0, header.size(), header) == 0);
  std::size_t differ = 0;
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        differ += ppm[header.size() + 3 * (std::size_t{y} * w + x) + c] !=
                  golden[54 + 4 * (std::size_t{h - 1 - y} * w + x) + (2 - c)];
  CHECK(differ == 0);
  for (const char* name : {"stdout.bmp", "pipe.bmp", "append.bmp", "out.ppm"}) std::remove((dir + "/" + name).c_str());
  rmdir(dir.c_str());
}

TEST_CASE("Jaworski: a row that cannot be written: one error line, status 1, the old file kept, nothing left",
          "[jaworski][output]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  char dir_buf[] = "/tmp/minrt-jw-XXXXXX";
  REQUIRE(mkdtemp(dir_buf) != nullptr);
  const std::string dir = dir_buf;
  const std::string out = dir + "/out.bmp", err = dir + "/err.txt";
  // The file size limit (32 or 64 KiB, sh's unit) lets the header through
  // and stops the rows of a 128 KiB image; SIGXFSZ ignored makes it EFBIG.
  const int status = shell("printf before >'" + out + "' && (trap '' XFSZ; ulimit -f 64; $MINRT -q --threads 2 -o '" +
                           out + "' '" + jw_dir() + "colour-names-all.txt' 2>'" + err + "')");
  CHECK(status == 1);
  CHECK(minrt::test::read_file(err) == "minrt: error: cannot write " + out + ": File too large\n");
  CHECK(minrt::test::read_file(out) == "before");
  std::remove(out.c_str());
  std::remove(err.c_str());
  CHECK(rmdir(dir.c_str()) == 0);  // no temporary file left beside it
}
