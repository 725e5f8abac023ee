// miniRT and EASTRAY scenes over the course and framed protocols
// (protocol/text_scene_upload.hpp, tags minrt::formats::format_of(minrt::formats::FormatId::kMinirt).wire_tag and
// _EASTRAY): end to end against firmware-sim running the firmware, the PNG
// byte for byte the raw protocol's and its pixels the host float model's;
// broken files get their located error, a non-zero status and no file.
#include <catch2/catch.hpp>

#include "formats/registry.hpp"

#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "png_io.hpp"
#include "png_receiver.hpp"
#include "protocol/text_scene_upload.hpp"
#include "protocol_course_host.hpp"
#include "protocol_framed_host.hpp"
#include "port.hpp"
#include "sim_launcher.hpp"
#include "test_support.hpp"

using hs_test::joined;
using hs_test::run;
using hs_test::RunResult;
using hs_test::send_sim;
using hs_test::text_protocols;

namespace {

// Small images keep the run short: miniRT files have no size of their own.
const std::vector<std::string> kMinirtSize = {"--size", "48x36"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("text-scene upload: miniRT and EASTRAY tags are accepted, in both byte orders of the course words",
          "[course][framed]") {
  using namespace minrt::send;
  CHECK(text::is_text_format(minrt::formats::format_of(minrt::formats::FormatId::kMinirt).wire_tag));
  CHECK(text::is_text_format(minrt::formats::format_of(minrt::formats::FormatId::kEastray).wire_tag));
  CHECK_FALSE(text::is_text_format(MINRT_SCENE_FORMAT_SLD));
  CHECK_FALSE(text::is_text_format(MINRT_SCENE_FORMAT_TAG_LIMIT));
  for (const bool big : {false, true}) {
    const std::string words = text_scene_course_words(minrt::formats::format_of(minrt::formats::FormatId::kEastray).wire_tag, "/* EASTRAY */", big);
    std::vector<unsigned char> mem(256);
    minrt::Arena arena(mem.data(), mem.size());
    minrt::MemorySource src{reinterpret_cast<const uint8_t*>(words.data()) + 4, words.size() - 4};
    text::TextScene scene;
    bool too_large = false;
    minrt::Diagnostic d;
    REQUIRE(text::read_course(src.source(), big ? course::Endian::kBig : course::Endian::kLittle, arena, scene,
                              too_large, d));
    CHECK(scene.format == minrt::formats::format_of(minrt::formats::FormatId::kEastray).wire_tag);
    CHECK(std::string(reinterpret_cast<const char*>(scene.bytes), scene.size) == "/* EASTRAY */");
  }
}

TEST_CASE("miniRT scenes over course and framed: the raw protocol's PNG, pixels the host float model's",
          "[e2e][firmware][minirt]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string valid = hs_test::shared_dir() + "/formats/minirt/valid/";
  // earth: a texture travels ahead of the text (the preamble, read in place).
  for (const char* name : {"mandatory_basic", "bonus_cone", "earth"})
    hs_test::check_png_on_every_protocol(dir, valid + name + ".rt", kMinirtSize);
}

TEST_CASE("EASTRAY scenes over course and framed: the raw protocol's PNG, pixels the host float model's",
          "[e2e][firmware][eastray]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string ray = hs_test::shared_dir() + "/formats/eastray/";
  // preproc_define_include: host-send expands #include and #define first.
  for (const char* name : {"basic_sphere_floor_elight", "preproc_define_include", "kinds_20_polygon_mesh"})
    hs_test::check_png_on_every_protocol(dir, ray + name + ".ray", {});
}

TEST_CASE("broken miniRT and EASTRAY files over course and framed: located error, status 3, no file",
          "[e2e][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string source = HS_SOURCE_DIR;
  // miniRT: minrt says "Error" then "FILE:LINE: MESSAGE"; the board, which
  // reads these, says "LINE:COL: MESSAGE".
  for (const char* name : {"camera_zero_vector", "colour_256", "brightness_two"}) {
    const std::string scene = source + "/test/minirt/bad/" + name + ".rt";
    const RunResult m = run(with({HS_MINRT, scene, "-o", dir.file("m.png")}, kMinirtSize));
    REQUIRE(m.status != 0);
    const std::size_t nl = m.err.find('\n');
    REQUIRE(nl != std::string::npos);
    const std::string second = m.err.substr(nl + 1, m.err.find('\n', nl + 1) - nl - 1);
    REQUIRE(second.rfind(scene + ":", 0) == 0);
    const std::string rest = second.substr(scene.size() + 1);  // LINE: MESSAGE
    const std::string line = rest.substr(0, rest.find(':'));
    const std::string message = rest.substr(rest.find(": ") + 2);
    for (const auto& protocol : {text_protocols()[0], text_protocols()[2]}) {
      const std::string out = dir.file("out.png");
      const RunResult r = send_sim(scene, out, with(protocol, kMinirtSize));
      INFO(scene << " " << joined(protocol) << "\n" << r.err << "minrt: " << second);
      CHECK(r.status == 3);
      const std::string prefix = "the board reported an error: " + line + ":";
      const std::size_t at = r.err.find(prefix);
      REQUIRE(at != std::string::npos);
      const std::string said = r.err.substr(at + prefix.size(), r.err.find('\n', at) - at - prefix.size());
      CHECK(said.size() > message.size());
      CHECK(said.substr(said.size() - message.size()) == message);  // after the column
      CHECK_FALSE(hs_test::file_exists(out));
    }
  }
  // miniRT textures are read on the host: one that is missing stops host-send
  // before sending, with minrt's own "FILE:LINE: MESSAGE", on every protocol.
  for (const char* name : {"bump_missing_file", "texture_missing_file"}) {
    const std::string scene = source + "/test/minirt/bad/" + name + ".rt";
    const RunResult m = run(with({HS_MINRT, scene, "-o", dir.file("m.png")}, kMinirtSize));
    REQUIRE(m.status != 0);
    const std::size_t nl = m.err.find('\n');
    REQUIRE(nl != std::string::npos);
    const std::string second = m.err.substr(nl + 1, m.err.find('\n', nl + 1) - nl - 1);
    REQUIRE(second.rfind(scene + ":", 0) == 0);
    std::vector<std::vector<std::string>> every = text_protocols();
    every.push_back({"--protocol", "raw"});
    for (const auto& protocol : every) {
      const std::string out = dir.file("out.png");
      const RunResult r = send_sim(scene, out, with(protocol, kMinirtSize));
      INFO(scene << " " << joined(protocol) << "\n" << r.err << "minrt: " << second);
      CHECK(r.status == 3);
      CHECK(r.err.find("scene rejected before sending: " + second + "\n") != std::string::npos);
      CHECK_FALSE(hs_test::file_exists(out));
    }
  }
  // EASTRAY: host-send checks the expanded scene before sending, with
  // minrt's own "FILE:LINE:COL: error: MESSAGE".
  for (const char* name : {"bad-number", "undefined-vertex", "unterminated-block", "range-kind"}) {
    const std::string scene = source + "/test/eastray/eastray_bad/" + name + ".ray";
    const RunResult m = run({HS_MINRT, "--precision", "float", "--shims", "portable", scene, "-o", dir.file("m.png")});
    REQUIRE(m.status != 0);
    std::string line = m.err.substr(0, m.err.find('\n'));
    if (line.rfind("minrt: ", 0) == 0) line = line.substr(7);
    REQUIRE(line.rfind(scene + ":", 0) == 0);
    for (const auto& protocol : {text_protocols()[0], text_protocols()[2]}) {
      const std::string out = dir.file("out.png");
      const RunResult r = send_sim(scene, out, protocol);
      INFO(scene << " " << joined(protocol) << "\n" << r.err << "minrt: " << line);
      CHECK(r.status == 3);
      CHECK(r.err.find("scene rejected before sending: " + line + "\n") != std::string::npos);
      CHECK_FALSE(hs_test::file_exists(out));
    }
  }
}

TEST_CASE("the board's own EASTRAY and miniRT errors over course and framed: one located error, no image",
          "[e2e][firmware][bad]") {
  // host-send checks EASTRAY scenes before sending, so here the uploads go
  // straight to the firmware: what a host without that check would send.
  HS_NEEDS_FIRMWARE();
  using namespace minrt::send;
  struct Case {
    std::uint32_t tag;
    std::string text;
    std::string error;  // the board's message: LINE:COL: MESSAGE
  };
  // The bad field of the miniRT camera line starts at column 9.
  const std::vector<Case> cases = {
      {minrt::formats::format_of(minrt::formats::FormatId::kEastray).wire_tag, "/* EASTRAY */\ndisplay 8 8 0 0 7 7 1 1 1 ;\nbogus 1 ;\n", "3:1: unknown statement 'bogus'"},
      {minrt::formats::format_of(minrt::formats::FormatId::kMinirt).wire_tag, "A 0.2 255,255,255\nC 0,0,0 0,0,0 70\n", "2:9: camera orientation \"0,0,0\" is the zero vector: it has no direction"}};
  for (const Case& c : cases) {
    for (const bool framed : {false, true}) {
      SimLauncher board;
      SimConfig cfg;
      cfg.simulator = HS_FIRMWARE_SIM;
      cfg.firmware = HS_FIRMWARE_ELF;
      cfg.firmware_args = {"--size", "8x8", framed ? "--protocol=framed" : "--protocol=course"};
      std::string err;
      REQUIRE(board.start(cfg, err));
      SerialPort port;
      port.open(board.pty_path(), PortSettings{});
      Exchange ex{port, {20000, 20000}, nullptr};
      TransferResult r;
      if (framed) {
        r = run_framed_text(ex, c.tag, FramedImage::kPng, c.text, 8, 8);
      } else {
        PngReceiver rx(8, 8);
        r = run_course_words(ex, text_scene_course_words(c.tag, c.text, false), "", CourseHostOptions{}, rx);
      }
      port.close();
      board.stop(2000);
      INFO(c.text << (framed ? "framed" : "course") << ": " << r.message);
      CHECK(r.status == TransferResult::Status::kFirmwareError);
      CHECK(r.message == c.error);
      CHECK(r.image.empty());
    }
  }
}
