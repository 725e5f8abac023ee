// host-send's command line: help, version, usage errors (status 2) and
// link errors (status 1).
#include <catch2/catch.hpp>

#include <algorithm>

#include "test_support.hpp"

using hs_test::run;

namespace {

// host-send with `args`: a usage error, one line on stderr, status 2.
hs_test::RunResult usage_error(const std::vector<std::string>& args) {
  std::vector<std::string> argv{HS_HOST_SEND};
  argv.insert(argv.end(), args.begin(), args.end());
  const auto r = run(argv);
  INFO(r.err);
  CHECK(r.status == 2);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  return r;
}

}  // namespace

TEST_CASE("host-send --help and --version", "[cli]") {
  auto r = run({HS_HOST_SEND, "--help"});
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("Usage: host-send") && Catch::Contains("--protocol raw|course|framed"));
  r = run({HS_HOST_SEND, "--version"});
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::StartsWith("host-send "));
}

TEST_CASE("usage errors are one line with status 2", "[cli]") {
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  for (const auto& args : std::vector<std::vector<std::string>>{
           {},
           {"--bogus", scene},
           {"--size", "0x3", scene},
           {"--format", "p5", scene},
           {"--baud", "fast", scene},
           {"--flow", "dtr", scene},
           {"--protocol", "zmodem", scene},
           {"--expect-sha256", "12", scene},
           {"--idle-timeout", "-1", scene},
           {"--port", "/dev/null", "--sim", scene},
           {scene, scene},
           {"/nonexistent.sld"},
       }) {
    CHECK_THAT(usage_error(args).err, Catch::StartsWith("host-send: error: "));
  }
}

TEST_CASE("without --port or --sim host-send stops with a hint instead of simulating", "[cli]") {
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  const auto r = usage_error({scene});
  CHECK(r.err ==
        "host-send: error: no board given: --port DEVICE for a board (host-send --list shows them), or --sim for "
        "firmware-sim (see host-send --help)\n");
}

TEST_CASE("a directory as the scene, --program or --verify is a one-line read error with the reason", "[cli]") {
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--sim", "/tmp"},
           {"--sim", "--protocol", "course", "--program", "/tmp", scene},
           {"--sim", "--verify", "/tmp", scene},
       }) {
    CHECK_THAT(usage_error(args).err, Catch::Contains("cannot read /tmp: Is a directory"));
  }
}

TEST_CASE("link errors give status 1", "[cli]") {
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  hs_test::TempDir dir;
  auto r = run({HS_HOST_SEND, "--port", "/nonexistent/ttyUSB9", scene, "-o", dir.file("x.ppm")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("cannot open /nonexistent/ttyUSB9"));
  r = run({HS_HOST_SEND, "--port", "/dev/null", scene, "-o", dir.file("x.ppm")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("not a serial port"));
  r = run({HS_HOST_SEND, "--sim", "/nonexistent/fw.elf", scene, "-o", dir.file("x.ppm")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("/nonexistent/fw.elf"));
  r = run({HS_HOST_SEND, "--sim-binary", "/nonexistent/sim", scene, "-o", dir.file("x.ppm")});
  CHECK(r.status == 1);
  CHECK_THAT(r.err, Catch::Contains("/nonexistent/sim"));
  CHECK_FALSE(hs_test::file_exists(dir.file("x.ppm")));
}

TEST_CASE("host-send --list runs", "[cli]") {
  const auto r = run({HS_HOST_SEND, "--list"});
  CHECK(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("USB devices seen by libusb"));
}

#include "sim_launcher.hpp"

TEST_CASE("the simulator's pty line is recognised", "[cli]") {
  std::string path;
  CHECK(minrt::send::parse_pty_line("firmware-sim: uart on /dev/pts/7", path));
  CHECK(path == "/dev/pts/7");
  CHECK(minrt::send::parse_pty_line("fault-relay: uart on /dev/pts/12\r", path));
  CHECK(path == "/dev/pts/12");
  CHECK_FALSE(minrt::send::parse_pty_line("firmware-sim: loading fw.elf", path));
  CHECK_FALSE(minrt::send::parse_pty_line("uart on ", path));
}
