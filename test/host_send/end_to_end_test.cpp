// host-send end to end over a pseudo-terminal: against the stand-in board
// (always) and against firmware-sim running the firmware (when built).
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include "png_io.hpp"
#include "port.hpp"
#include "sim_launcher.hpp"
#include "test_support.hpp"

using hs_test::run;
using hs_test::RunResult;

namespace {

std::string ball() { return hs_test::shared_dir() + "/scenes/ball.sld"; }

// host-send with the stand-in board as its "simulator".
RunResult send_standin(const std::vector<std::string>& extra, const std::string& scene, const std::string& out) {
  // The stand-in ignores the ELF; any ELF file will do (it is one itself).
  std::vector<std::string> argv{HS_HOST_SEND, "--sim-binary", HS_STANDIN, "--sim", HS_STANDIN};
  argv.insert(argv.end(), extra.begin(), extra.end());
  argv.push_back(scene);
  argv.push_back("-o");
  argv.push_back(out);
  return run(argv);
}

}  // namespace

TEST_CASE("raw protocol end to end against the stand-in board", "[e2e][raw]") {
  hs_test::TempDir dir;
  for (const char* format : {"p6", "p3"}) {
    const std::string out = dir.file(std::string("ball-") + format + ".ppm");
    const RunResult r = send_standin({"--size", "32x32", "--format", format}, ball(), out);
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(hs_test::read_file(out) == hs_test::reference_image(ball(), "32x32", format));
    CHECK_THAT(r.err, Catch::Contains("sha256"));
    CHECK_THAT(r.err, Catch::Contains("from the simulated board"));
  }
}

TEST_CASE("the summary gives the file's size, then the bytes that crossed the line", "[e2e][raw]") {
  hs_test::TempDir dir;
  const std::string out = dir.file("ball.ppm");
  // Raw with its checks: the CRC-32 trailer follows the image on the line.
  RunResult r = send_standin({"--size", "24x16", "--format", "p3"}, ball(), out);
  INFO(r.err);
  REQUIRE(r.status == 0);
  const std::size_t size = hs_test::read_file(out).size();
  CHECK_THAT(r.err, Catch::StartsWith("host-send: " + out + ": " + std::to_string(size) + " bytes; received " +
                                      std::to_string(size + 13) + " in "));
  // Without them the two agree.
  r = send_standin({"--size", "24x16", "--format", "p3", "--no-check"}, ball(), out);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::StartsWith("host-send: " + out + ": " + std::to_string(size) + " bytes; received " +
                                      std::to_string(size) + " in "));
  r = send_standin({"--size", "24x16", "-q"}, ball(), out);
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
}

TEST_CASE("raw protocol over --port with a separately started board", "[e2e][raw]") {
  minrt::send::SimLauncher board;
  hs_test::start_standin(board, "24x16", "p6");
  hs_test::TempDir dir;
  const std::string out = dir.file("ball.ppm");
  const RunResult r = run({HS_HOST_SEND, "--no-handshake", "--port", board.pty_path(), "--baud", "921600", "--size", "24x16", "--format",
                           "p6", ball(), "-o", out});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(hs_test::read_file(out) == hs_test::reference_image(ball(), "24x16", "p6"));
  // A pty has no baud rate: no share of the 8N1 limit (it used to say 635.9%).
  CHECK_THAT(r.err, !Catch::Contains("8N1"));
  CHECK_THAT(r.err, !Catch::Contains("simulated"));
  CHECK(board.stop(5000) == 0);
}

TEST_CASE("host-send checks images with --verify and --expect-sha256", "[e2e][raw]") {
  hs_test::TempDir dir;
  const std::string ref = dir.file("ref.ppm");
  {
    const std::string bytes = hs_test::reference_image(ball(), "16x16", "p3");
    FILE* f = std::fopen(ref.c_str(), "wb");
    std::fwrite(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
  }
  const std::string out = dir.file("out.ppm");
  RunResult r = send_standin({"--size", "16x16", "--format", "p6", "--verify", ref}, ball(), out);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("verify: 0 pixels differ, max channel error 0, PSNR inf dB"));

  r = send_standin({"--size", "16x16", "--format", "p6", "--expect-sha256", std::string(64, '0')}, ball(), out + "2");
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("differs from the expected"));
  CHECK_FALSE(hs_test::file_exists(out + "2"));
}

TEST_CASE("a size mismatch between board and host is detected", "[e2e][raw]") {
  minrt::send::SimLauncher board;
  hs_test::start_standin(board, "16x16", "p6");
  hs_test::TempDir dir;
  const RunResult r = run({HS_HOST_SEND, "--no-handshake", "--port", board.pty_path(), "--size", "32x32", "--format", "p6", ball(), "-o",
                           dir.file("x.ppm")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("image is 16x16, expected 32x32"));
  CHECK_FALSE(hs_test::file_exists(dir.file("x.ppm")));
}

TEST_CASE("a port held by another process is refused with its holder", "[e2e]") {
  minrt::send::SimLauncher board;
  hs_test::start_standin(board, "8x8", "p6");
  minrt::send::SerialPort holder;
  holder.open(board.pty_path(), minrt::send::PortSettings{});
  // The holder is this test process; host-send is another process.
  const RunResult r = run({HS_HOST_SEND, "--no-handshake", "--port", board.pty_path(), ball(), "-o", "/tmp/never.ppm"});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("locked by pid"));
  holder.close();
}

namespace {

// Sends every file of shared/bad with `send` and checks the outcome: the
// board's error, status 3, no image (the one valid file renders). A scene
// with a 0x04 byte inside cannot travel over raw (the board would take it
// as the end of the scene): host-send refuses it before sending, with the
// same message.
void check_bad_scenes(const std::function<RunResult(const std::string& scene, const std::string& out)>& send) {
  const auto bad = hs_test::bad_scenes();
  if (bad.empty()) {
    WARN("skipped: no " << hs_test::shared_dir() << "/bad");
    return;
  }
  hs_test::TempDir dir;
  for (const auto& scene : bad) {
    const std::string out = dir.file(scene.substr(scene.rfind('/') + 1) + ".ppm");
    const RunResult r = send(scene, out);
    INFO(scene << "\n" << r.err);
    if (scene.find("sixty-objects-fifty-and-nets") != std::string::npos) {
      CHECK(r.status == 0);  // valid, see shared/README.md
      continue;
    }
    CHECK(r.status == 3);
    if (hs_test::read_file(scene).find('\x04') != std::string::npos)
      CHECK_THAT(r.err, Catch::Contains("scene rejected before sending: "));
    else
      CHECK_THAT(r.err, Catch::Contains("the board reported an error: "));
    CHECK_FALSE(hs_test::file_exists(out));
  }
}

}  // namespace

TEST_CASE("every bad scene ends with the stand-in's error, status 3 and no image", "[e2e][bad]") {
  check_bad_scenes([](const std::string& scene, const std::string& out) {
    return send_standin({"--size", "16x16", "--format", "p6", "--first-byte-timeout", "60"}, scene, out);
  });
}

TEST_CASE("host-send and firmware-sim give the bytes of minrt float/portable", "[e2e][firmware]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  for (const char* baud : {"115200", "921600", "3000000"}) {
    for (const char* format : {"p3", "p6"}) {
      const std::string out = dir.file(std::string("ball-") + baud + format + ".ppm");
      const RunResult r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, "--baud", baud,
                               "--size", "32x32", "--format", format, ball(), "-o", out});
      INFO(baud << " " << format << "\n" << r.err);
      REQUIRE(r.status == 0);
      CHECK(hs_test::read_file(out) == hs_test::reference_image(ball(), "32x32", format));
    }
  }
}

TEST_CASE("every bad scene through firmware-sim ends with the firmware's error", "[e2e][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  check_bad_scenes([](const std::string& scene, const std::string& out) {
    return run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, "--size", "16x16", "--format",
                "p6", scene, "-o", out});
  });
}

TEST_CASE("host-send sends CS418 scenes to firmware-sim and writes the PNG it sends back", "[e2e][firmware][cs418]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string cs418 = hs_test::shared_dir() + "/formats/cs418/";
  // ray-tex and ray-trit: their textures travel decoded ahead of the scene.
  for (const char* name : {"ray-sphere", "ray-shadow-plane", "ray-trans3", "ray-many", "ray-tex", "ray-trit"}) {
    const std::string scene = cs418 + name + ".txt";
    const std::string got = dir.file(std::string(name) + "-board.png");
    const std::string want = dir.file(std::string(name) + "-host.png");
    const RunResult r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, scene, "-o", got});
    INFO(name << "\n" << r.err);
    REQUIRE(r.status == 0);
    REQUIRE(run({HS_MINRT, "-q", "--precision", "float", "--shims", "portable", scene, "-o", want}).status == 0);
    minrt::host::RgbaImage a, b;
    std::string why;
    REQUIRE(minrt::host::read_png(got, a, why));
    REQUIRE(minrt::host::read_png(want, b, why));
    CHECK(a.width == b.width);
    CHECK(a.rgba == b.rgba);
  }
}

TEST_CASE("host-send writes the board's stored-deflate PNG compressed, --as-received as sent", "[e2e][firmware][cs418]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string scene = hs_test::shared_dir() + "/formats/cs418/ray-shadow-plane.txt";
  const std::string packed = dir.file("packed.png"), stored = dir.file("stored.png");
  RunResult r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, scene, "-o", packed});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK_THAT(r.err, Catch::Contains("as the board sent it"));
  CHECK_THAT(r.err, Catch::StartsWith("host-send: " + packed + ": " + std::to_string(hs_test::read_file(packed).size()) +
                                      " bytes; received "));
  r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, "--as-received", scene, "-o",
           stored});
  REQUIRE(r.status == 0);
  const std::string a = hs_test::read_file(packed), b = hs_test::read_file(stored);
  // The summary names the file's size: the compressed PNG's, or the stream's.
  CHECK_THAT(r.err, Catch::StartsWith("host-send: " + stored + ": " + std::to_string(b.size()) + " bytes; received "));
  // The board's stream is stored deflate: 4 bytes a pixel and more.
  CHECK(b.size() > 4u * 120 * 120);
  CHECK(a.size() * 4 < b.size());
  minrt::host::RgbaImage pa, pb;
  std::string why;
  REQUIRE(minrt::host::read_png(packed, pa, why));
  REQUIRE(minrt::host::read_png(stored, pb, why));
  CHECK(pa.width == pb.width);
  CHECK(pa.height == pb.height);
  CHECK(pa.rgba == pb.rgba);
}

TEST_CASE("host-send: a broken CS418 scene ends with the board's located error and no image", "[e2e][firmware][cs418]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string out = dir.file("x.png");
  const RunResult r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                           std::string(HS_SOURCE_DIR) + "/test/cs418/bad/bad-number.txt", "-o", out});
  CHECK(r.status == 3);
  CHECK(r.err.find("the board reported an error: 2:15: not a number: 'O.5'") != std::string::npos);
  CHECK(!hs_test::file_exists(out));
  // Over framed the same error comes back in an X frame.
  const RunResult framed = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, "--protocol",
                                "framed", std::string(HS_SOURCE_DIR) + "/test/cs418/bad/bad-number.txt", "-o", out});
  CHECK(framed.status == 3);
  CHECK(framed.err.find("the board reported an error: 2:15: not a number: 'O.5'") != std::string::npos);
  CHECK(!hs_test::file_exists(out));
}

TEST_CASE("host-send: textures too large for the board are refused before sending, and fit a larger simulated RAM",
          "[e2e][firmware][cs418]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  minrt::host::RgbaImage big;
  big.width = 1500;
  big.height = 1000;  // 4.5 MB of texels: more than the board's 4 MiB
  big.rgba.assign(static_cast<std::size_t>(big.width) * big.height * 4, 200);
  {
    std::FILE* f = std::fopen(dir.file("big.png").c_str(), "wb");
    std::string why;
    REQUIRE(minrt::host::write_png(f, big, why));
    std::fclose(f);
  }
  {
    std::FILE* f = std::fopen(dir.file("big.txt").c_str(), "w");
    std::fputs("png 12 8 out.png\ntexture big.png\nsphere 0 0 -2 1\nsun 1 1 1\n", f);
    std::fclose(f);
  }
  const std::string out = dir.file("out.png");
  const RunResult small = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                               dir.file("big.txt"), "-o", out});
  CHECK(small.status == 3);
  CHECK(small.err.find("scene rejected before sending: " + dir.file("big.txt") +
                       ":2:9: error: texture big.png (1500x1000) takes the textures to 4500000 bytes decoded, over the "
                       "3670016 bytes the board has for them") != std::string::npos);
  CHECK(!hs_test::file_exists(out));
  const RunResult larger = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim-ram-size", "16M", "--sim",
                                HS_FIRMWARE_ELF, dir.file("big.txt"), "-o", out});
  INFO(larger.err);
  CHECK(larger.status == 0);
  minrt::host::RgbaImage img;
  std::string why;
  REQUIRE(minrt::host::read_png(out, img, why));
  CHECK(img.width == 12);
}

TEST_CASE("host-send sends Jaworski scenes to firmware-sim and writes the BMP it sends back", "[e2e][firmware][jaworski]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string jw = hs_test::shared_dir() + "/formats/jaworski/";
  for (const char* name : {"basic-diffuse-sphere", "mixed-nested-deep", "syntax-case-comments"}) {
    const std::string scene = jw + name + ".txt";
    const std::string got = dir.file(std::string(name) + "-board.bmp");
    const std::string want = dir.file(std::string(name) + "-host.bmp");
    const RunResult r = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, scene, "-o", got});
    INFO(name << "\n" << r.err);
    REQUIRE(r.status == 0);
    REQUIRE(run({HS_MINRT, "-q", "--precision", "float", "--shims", "portable", scene, "-o", want}).status == 0);
    CHECK(hs_test::read_file(got) == hs_test::read_file(want));
  }
  const std::string out = dir.file("bad.bmp");
  const RunResult bad = run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                             jw + "bad/bad-unknown-colour.txt", "-o", out});
  CHECK(bad.status == 3);
  CHECK(bad.err.find("the board reported an error: 6:26: expected a colour") != std::string::npos);
  CHECK(!hs_test::file_exists(out));
}
