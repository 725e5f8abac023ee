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

#include <functional>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "cli.hpp"

namespace {

using minrt::send::Options;
using minrt::send::ParseResult;

// host-send's parser on `args` (after the program name).
ParseResult parse(std::vector<std::string> args, Options& o, std::string& error) {
  args.insert(args.begin(), "host-send");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  return minrt::send::parse_command_line(static_cast<int>(argv.size()), argv.data(), o, error);
}

// Each option of --help with a value and what it must set.
struct Sample {
  std::vector<std::string> args;  // the option (long form) and its value
  std::function<bool(const Options&)> took;
};

const std::map<std::string, Sample>& samples() {
  using minrt::send::Flow;
  using minrt::send::Protocol;
  static const std::map<std::string, Sample> s = {
      {"port", {{"--port", "/dev/ttyUSB3"}, [](const Options& o) { return o.port == "/dev/ttyUSB3" && !o.sim; }}},
      {"sim", {{"--sim", "fw.elf"}, [](const Options& o) { return o.sim && o.sim_elf == "fw.elf"; }}},
      {"sim-ram-size", {{"--sim-ram-size", "16M"}, [](const Options& o) { return o.sim && o.sim_ram_bytes == 16u << 20; }}},
      {"board", {{"--board", "b.board"}, [](const Options& o) { return o.sim && o.sim_board == "b.board"; }}},
      {"sim-binary", {{"--sim-binary", "/x/sim"}, [](const Options& o) { return o.sim && o.sim_binary == "/x/sim"; }}},
      {"rtl", {{"--rtl", "fw.elf"}, [](const Options& o) { return o.sim && o.rtl && o.sim_elf == "fw.elf"; }}},
      {"baud", {{"--baud", "921600"}, [](const Options& o) { return o.baud_given && o.port_settings.baud == 921600; }}},
      {"flow", {{"--flow", "rtscts"}, [](const Options& o) { return o.port_settings.flow == Flow::kRtsCts; }}},
      {"list", {{"--list"}, [](const Options& o) { return o.list; }}},
      {"probe", {{"--probe", "--port", "/dev/ttyUSB3"}, [](const Options& o) { return o.probe && !o.sim; }}},
      {"no-handshake", {{"--no-handshake"}, [](const Options& o) { return !o.handshake; }}},
      {"protocol", {{"--protocol", "course"}, [](const Options& o) { return o.protocol == Protocol::kCourse; }}},
      {"size", {{"--size", "64x32"}, [](const Options& o) { return o.size_given && o.spec.width == 64 && o.spec.height == 32; }}},
      {"format", {{"--format", "p6"}, [](const Options& o) { return o.spec.kind == minrt::send::PpmKind::kP6; }}},
      {"program", {{"--protocol", "course", "--program", "p.bin"}, [](const Options& o) { return o.program == "p.bin"; }}},
      {"endian", {{"--endian", "big"}, [](const Options& o) { return o.big_endian; }}},
      {"full-textures", {{"--full-textures"}, [](const Options& o) { return o.full_textures; }}},
      {"output", {{"--output", "x.ppm"}, [](const Options& o) { return o.output_given && o.output == "x.ppm"; }}},
      {"write-through", {{"--write-through"}, [](const Options& o) { return o.write_through; }}},
      {"allow-any-output", {{"--allow-any-output"}, [](const Options& o) { return o.allow_any_output; }}},
      {"as-received", {{"--as-received"}, [](const Options& o) { return o.as_received; }}},
      {"verify", {{"--verify", "r.ppm"}, [](const Options& o) { return o.verify_ref == "r.ppm"; }}},
      {"expect-sha256",
       {{"--expect-sha256", std::string(64, 'a')}, [](const Options& o) { return o.expect_sha256 == std::string(64, 'a'); }}},
      {"check", {{"--check"}, [](const Options& o) { return o.check == minrt::send::RawCheck::kRequire; }}},
      {"no-check", {{"--no-check"}, [](const Options& o) { return o.check == minrt::send::RawCheck::kOff; }}},
      {"first-byte-timeout", {{"--first-byte-timeout", "2.5"}, [](const Options& o) { return o.first_byte_timeout == 2.5; }}},
      {"idle-timeout", {{"--idle-timeout", "7"}, [](const Options& o) { return o.idle_timeout == 7; }}},
      {"reply-timeout", {{"--reply-timeout", "40"}, [](const Options& o) { return o.reply_timeout == 40; }}},
      {"sim-start-timeout",
       {{"--sim-start-timeout", "1.5"}, [](const Options& o) { return o.sim_start_timeout == 1.5; }}},
      {"progress", {{"--progress"}, [](const Options& o) { return o.progress_forced; }}},
      {"show", {{"--show"}, [](const Options& o) { return o.show; }}},
      {"quiet", {{"--quiet"}, [](const Options& o) { return o.quiet; }}},
      {"help", {{"--help"}, nullptr}},
      {"version", {{"--version"}, nullptr}},
  };
  return s;
}

}  // namespace

TEST_CASE("host-send --board with --port names the board expected there, --probe takes a port and no scene", "[cli]") {
  Options o;
  std::string error;
  REQUIRE(parse({"--board", "b.board", "--port", "/dev/ttyUSB3", "scene.sld"}, o, error) == ParseResult::kRun);
  CHECK(!o.sim);
  CHECK(o.sim_board == "b.board");
  Options p;
  CHECK(parse({"--probe"}, p, error) == ParseResult::kError);
  CHECK(error == "--probe needs the board's port (-p DEV)");
  Options q;
  CHECK(parse({"--probe", "-p", "/dev/ttyUSB3", "scene.sld"}, q, error) == ParseResult::kError);
  CHECK(error == "--probe takes no scene ('scene.sld')");
}

TEST_CASE("every option --help lists is accepted and sets what it says", "[cli]") {
  const auto help = run({HS_HOST_SEND, "--help"});
  REQUIRE(help.status == 0);
  // "  -p, --port DEV   ..." or "      --list   ...": the option column.
  const std::regex row(R"(^  (?:-(\w), |    )--([a-z0-9-]+))");
  std::set<std::string> listed;
  std::map<std::string, char> letters;
  std::istringstream lines(help.out);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    listed.insert(m[2]);
    if (m[1].matched) letters[m[2]] = m[1].str()[0];
  }
  std::set<std::string> sampled;
  for (const auto& [name, sample] : samples()) sampled.insert(name);
  CHECK(listed == sampled);  // an option added to the table gets a sample here
  CHECK(letters == std::map<std::string, char>{{"help", 'h'}, {"output", 'o'}, {"port", 'p'}, {"baud", 'b'},
                                                {"show", 's'}, {"quiet", 'q'}});
  for (const auto& [name, sample] : samples()) {
    INFO("--" << name);
    std::vector<std::string> args = sample.args;
    if (name != "port" && name != "list" && name != "sim" && name != "board" && name != "sim-binary" &&
        name != "sim-ram-size" && name != "probe" && name != "rtl")
      args.push_back("--sim");
    if (name != "probe") args.push_back("scene.sld");  // --probe takes none
    Options o;
    std::string error;
    const ParseResult result = parse(args, o, error);
    INFO(error);
    if (name == "help") CHECK(result == ParseResult::kHelp);
    else if (name == "version") CHECK(result == ParseResult::kVersion);
    else {
      REQUIRE(result == ParseResult::kRun);
      CHECK(sample.took(o));
    }
    // The short form, and --name=VALUE, mean the same.
    if (letters.count(name) != 0 && sample.took) {
      args[0] = std::string("-") + letters[name];
      Options s;
      REQUIRE(parse(args, s, error) == ParseResult::kRun);
      CHECK(sample.took(s));
    }
    if (sample.args.size() == 2 && sample.took) {
      std::vector<std::string> joined{sample.args[0] + "=" + sample.args[1]};
      joined.insert(joined.end(), args.begin() + 2, args.end());
      Options j;
      REQUIRE(parse(joined, j, error) == ParseResult::kRun);
      CHECK(sample.took(j));
    }
  }
}

TEST_CASE("host-send: --sim takes the next argument as its ELF only when it is one", "[cli]") {
  hs_test::TempDir dir;
  Options o;
  std::string error;
  REQUIRE(parse({"--sim", "scene.sld"}, o, error) == ParseResult::kRun);
  CHECK(o.sim_elf.empty());
  CHECK(o.scene == "scene.sld");
  Options e;
  REQUIRE(parse({"--sim", HS_STANDIN, "scene.sld"}, e, error) == ParseResult::kRun);  // an ELF by its bytes
  CHECK(e.sim_elf == HS_STANDIN);
  Options d;
  REQUIRE(parse({"scene.sld", "--sim", "-o", "x.ppm"}, d, error) == ParseResult::kRun);
  CHECK(d.sim_elf.empty());
  CHECK(d.output == "x.ppm");
  Options q;
  REQUIRE(parse({"scene.sld"}, q, error) == ParseResult::kError);
  Options defaults;
  REQUIRE(parse({"--sim", "dir/scene.sld"}, defaults, error) == ParseResult::kRun);
  CHECK(defaults.output == "scene.ppm");  // the scene's name in the working folder
}

TEST_CASE("an unknown option or a flag given a value is one line and status 2", "[cli]") {
  const std::string scene = hs_test::shared_dir() + "/scenes/ball.sld";
  CHECK(usage_error({"--sim", "--frobnicate", scene}).err ==
        "host-send: error: unknown option '--frobnicate' (see host-send --help)\n");
  CHECK(usage_error({"--sim", "-z", scene}).err == "host-send: error: unknown option '-z' (see host-send --help)\n");
  CHECK(usage_error({"--sim", "--quiet=yes", scene}).err ==
        "host-send: error: --quiet takes no value (see host-send --help)\n");
  CHECK(usage_error({"--sim", scene, "-o"}).err == "host-send: error: --output needs a value (see host-send --help)\n");
}
