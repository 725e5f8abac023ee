// The shared course and framed protocol code, and both protocols end to end
// over a pty against the stand-in board.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "formats/sld/sld_reader.hpp"
#include "core/image/row_sink.hpp"
#include "protocol/course_word_values.hpp"
#include "protocol/protocol_course.hpp"
#include "protocol_course_host.hpp"
#include "protocol/protocol_framed.hpp"
#include "protocol_framed_host.hpp"
#include "test_support.hpp"

using namespace minrt::send;

namespace {

std::string ball() { return hs_test::shared_dir() + "/scenes/ball.sld"; }

void append_fn(void* ctx, const uint8_t* d, size_t n) { static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(d), n); }

// Reads a scene the board's way, from course words.
bool read_words(const std::string& words, course::Endian e, minrt::Scene<float>& scene, minrt::Diagnostic& d) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(words.data()), words.size()};
  minrt::SldReader<float, course::CourseWordValues<float>> reader(course::CourseWordValues<float>(mem.source(), e),
                                                                  minrt::WarningSink{});
  return reader.read(scene, d);
}

// Reads a scene the host's way, from text.
bool read_text(const std::string& text, minrt::Scene<float>& scene, minrt::Diagnostic& d) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::SldReader<float> reader(mem.source(), minrt::WarningSink{});
  return reader.read(scene, d);
}

}  // namespace

TEST_CASE("the course word layout follows min-rt's token order", "[course]") {
  // screen 5 floats, 1 light, light 3 floats, one rotated object, one plain,
  // -1, AND nets "0 -1" "-1", OR nets "99 0 -1" "-1".
  const std::string sld =
      "0 0 -100 0 0\n1 0.5 -0.5 255\n"
      "0 2 0 1  1 1 1  0 0 0  1  0.5 0.5  255 0 0  10 20 30\n"
      "0 1 0 0  1 1 1  0 0 0  1  0.5 0.5  255 0 0\n"
      "-1\n0 -1\n-1\n99 0 -1\n-1\n";
  std::string words, err;
  REQUIRE(sld_to_course_words(sld, false, words, err));
  CHECK(words.size() == 4 * (5 + 1 + 3 + 19 + 16 + 1 + 2 + 1 + 3 + 1));
  // Ints where ints are expected: the light count is word 5.
  CHECK(course::get_u32(reinterpret_cast<const uint8_t*>(words.data()) + 20, course::Endian::kLittle) == 1u);
  std::string big;
  REQUIRE(sld_to_course_words(sld, true, big, err));
  CHECK(course::get_u32(reinterpret_cast<const uint8_t*>(big.data()) + 20, course::Endian::kBig) == 1u);
  // The board's reader takes the same values back from the words.
  auto from_text = std::make_unique<minrt::Scene<float>>();
  auto from_words = std::make_unique<minrt::Scene<float>>();
  minrt::Diagnostic d;
  REQUIRE(read_text(sld, *from_text, d));
  REQUIRE(read_words(words, course::Endian::kLittle, *from_words, d));
  CHECK(from_words->object_count == 2);
  CHECK(from_words->objects[0].rotation_deg[2] == 30.0f);
  CHECK(from_words->objects[1].color[0] == 255.0f);
  CHECK(from_words->or_nets[0][0] == 99);
  auto from_big = std::make_unique<minrt::Scene<float>>();
  REQUIRE(read_words(big, course::Endian::kBig, *from_big, d));
  CHECK(from_big->objects[0].abc[1] == from_text->objects[0].abc[1]);
}

TEST_CASE("the course converter refuses what minrt refuses, with minrt's message", "[course]") {
  std::string words, err;
  CHECK_FALSE(sld_to_course_words("0 0 -100 0 0\n1.5 0 0 0\n", false, words, err));
  CHECK(err == "2:1: expected an integer for light count, got '1.5'");
  CHECK_FALSE(sld_to_course_words("0 0 -100 abc 0\n", false, words, err));
  CHECK(err == "1:10: expected a number for screen rotation (x axis), got 'abc'");
  CHECK_FALSE(sld_to_course_words("0 0 -100 0 0\n1 0 0 0\n-1\n", false, words, err));
  CHECK_THAT(err, Catch::StartsWith("4:1: unexpected end of input: expected object index of AND network 0"));
  // The old tokenizer passed these; the core's lexer does not.
  CHECK_FALSE(sld_to_course_words(std::string("0 0 -1\0" "00 0 0\n", 15), false, words, err));
  CHECK_FALSE(sld_to_course_words("0 0 -100 0\f 0\n", false, words, err));
  CHECK_FALSE(sld_to_course_words("0 0 " + std::string(257, '1') + " 0 0\n", false, words, err));
  CHECK_THAT(err, Catch::Contains("token longer than 256 bytes"));
}

TEST_CASE("the course converter reads numbers by the core's rules", "[course]") {
  // 0b1, 0o17 and 1_0 are OCaml integer spellings the core reads (the old
  // strtol-based converter refused them).
  const std::string sld =
      "0 0 -100 0 0\n0b1 0.5 -0.5 255\n"
      "0 0o2 0 0  1_0 1 1  0 0 0  1  0.5 0.5  255 0 0\n"
      "-1\n0 -1\n-1\n99 0 -1\n-1\n";
  std::string words, err;
  REQUIRE(sld_to_course_words(sld, false, words, err));
  auto scene = std::make_unique<minrt::Scene<float>>();
  minrt::Diagnostic d;
  REQUIRE(read_words(words, course::Endian::kLittle, *scene, d));
  CHECK(scene->light_count == 1);
  CHECK(scene->objects[0].form == 2);
  CHECK(scene->objects[0].abc[0] == 10.0f);
}

TEST_CASE("frames survive the parser and damage is rejected", "[framed]") {
  std::string wire;
  const uint8_t payload[] = {1, 2, 3, 4, 5};
  framed::write_frame(minrt::ByteSink{&append_fn, &wire}, framed::kRow, 513, payload, 5);
  CHECK(wire.size() == 5 + framed::kOverhead);
  uint8_t buf[64];
  framed::FrameParser parser(buf, sizeof buf);
  int frames = 0;
  // Noise, the frame, a damaged copy, the frame again.
  std::string stream = std::string("\xA5\x00junk", 6) + wire;
  std::string damaged = wire;
  damaged[10] ^= 0x10;
  stream += damaged + wire;
  int bad = 0;
  for (char c : stream) {
    const auto r = parser.feed(static_cast<uint8_t>(c));
    if (r == framed::FrameParser::kFrame) {
      ++frames;
      CHECK(parser.type() == framed::kRow);
      CHECK(parser.seq() == 513);
      CHECK(parser.length() == 5);
      CHECK(std::memcmp(parser.payload(), payload, 5) == 0);
    }
    if (r == framed::FrameParser::kBad) ++bad;
  }
  CHECK(frames == 2);
  CHECK(bad == 1);
}

TEST_CASE("framed overhead is under 1% at 512x512 P6", "[framed]") {
  const double payload = 512.0 * 512 * 3;
  const double overhead = 512.0 * framed::kOverhead + (4 + framed::kOverhead) + (2 + framed::kOverhead) +
                          framed::kOverhead;  // rows, H, Z, F
  CHECK(overhead / payload < 0.01);
  SUCCEED("overhead " << 100.0 * overhead / payload << "%");
}

TEST_CASE("RowFramer turns finished rows into H and D frames and re-sends rows", "[framed]") {
  std::string wire;
  std::vector<uint8_t> store(4 * 3 * 3);
  framed::RowFramer framer(minrt::ByteSink{&append_fn, &wire}, store.data(), store.size());
  const minrt::RowSink rows = minrt::row_sink_of(framer);
  uint8_t pixels[36];
  for (int i = 0; i < 36; ++i) pixels[i] = static_cast<uint8_t>(i);
  rows.begin(4, 3);
  for (int y = 0; y < 3; ++y) rows.row(y, pixels + 12 * y);
  rows.end();
  framer.send_end();
  CHECK(framer.stored());
  CHECK(framer.rows_sent() == 3);
  uint8_t buf[64];
  framed::FrameParser parser(buf, sizeof buf);
  std::string types;
  for (char c : wire)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) {
      types.push_back(static_cast<char>(parser.type()));
      if (parser.type() == framed::kRow) CHECK(parser.payload()[0] == parser.seq() * 12);
    }
  CHECK(types == "HDDDZ");
  // A request for row 1 and the header.
  std::string req;
  const uint8_t list[] = {1, 0, 0xFF, 0xFF};
  framed::write_frame(minrt::ByteSink{&append_fn, &req}, framed::kRequest, 0, list, 4);
  for (char c : req)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) {
      wire.clear();
      framer.answer_request(parser);
    }
  types.clear();
  for (char c : wire)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) types.push_back(static_cast<char>(parser.type()));
  CHECK(types == "DHZ");
}

TEST_CASE("the scene collector needs every chunk in order", "[framed]") {
  std::string scene(3000, 'x');
  for (size_t i = 0; i < scene.size(); ++i) scene[i] = static_cast<char>('a' + i % 26);
  const std::string up = framed_upload(scene);
  std::vector<uint8_t> pbuf(2048), sbuf(8192);
  framed::FrameParser parser(pbuf.data(), pbuf.size());
  framed::SceneCollector col(sbuf.data(), sbuf.size());
  framed::SceneCollector::Result last = framed::SceneCollector::kMore;
  for (char c : up)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) last = col.frame(parser);
  REQUIRE(last == framed::SceneCollector::kComplete);
  CHECK(std::string(reinterpret_cast<const char*>(col.data()), col.size()) == scene);
  // Drop the second chunk: the end frame reports the damage.
  framed::SceneCollector col2(sbuf.data(), sbuf.size());
  const size_t chunk = framed::kSceneChunk + framed::kOverhead;
  const std::string holed = up.substr(0, chunk) + up.substr(2 * chunk);
  for (char c : holed)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) last = col2.frame(parser);
  CHECK(last == framed::SceneCollector::kDamaged);
  framed::SceneCollector small(sbuf.data(), 100);
  bool too_large = false;
  for (char c : up)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame)
      too_large |= small.frame(parser) == framed::SceneCollector::kTooLarge;
  CHECK(too_large);
}

// Course (both byte orders) and framed, P3 and P6, through `sim_binary`
// running `board`: each image must equal the host's float/portable render.
// `program` is sent in course mode ("" sends none: the firmware renders).
static void check_course_and_framed(const std::string& sim_binary, const std::string& board, const std::string& size,
                                    const std::string& program) {
  hs_test::TempDir dir;
  for (const char* proto : {"course", "framed"}) {
    for (const char* format : {"p3", "p6"}) {
      for (const char* endian : {"little", "big"}) {
        if (std::string(proto) == "framed" && std::string(endian) == "big") continue;
        const std::string out = dir.file(std::string(proto) + format + endian + ".ppm");
        std::vector<std::string> argv{HS_HOST_SEND, "--sim-binary", sim_binary, "--sim", board, "--protocol", proto,
                                      "--size", size, "--format", format, ball(), "-o", out};
        if (std::string(proto) == "course") {
          argv.insert(argv.end(), {"--endian", endian});
          if (!program.empty()) argv.insert(argv.end(), {"--program", program});
        }
        const auto r = hs_test::run(argv);
        INFO(proto << " " << format << " " << endian << "\n" << r.err);
        REQUIRE(r.status == 0);
        CHECK(hs_test::read_file(out) == hs_test::reference_image(ball(), size, format));
      }
    }
  }
}

TEST_CASE("course and framed end to end against the stand-in board", "[e2e][course][framed]") {
  check_course_and_framed(HS_STANDIN, HS_STANDIN, "32x24", ball());  // the stand-in drops the program
}

// The scene error host-send reports: what follows "the board reported an
// error: " (raw, framed) or "scene rejected before sending: " (course, whose
// words are made by the same SLD reader on the host).
static std::string scene_error(const std::string& err) {
  for (const char* prefix : {"the board reported an error: ", "scene rejected before sending: "}) {
    const std::size_t at = err.find(prefix);
    if (at != std::string::npos) {
      const std::size_t from = at + std::strlen(prefix);
      return err.substr(from, err.find('\n', from) - from);
    }
  }
  return "";
}

// Bad scenes over raw, course and framed through `sim_binary` running
// `board`: status 3, no image, and the same message over every protocol.
static void check_scene_errors(const std::string& sim_binary, const std::string& board) {
  hs_test::TempDir dir;
  for (const char* name : {"nan-value", "too-many-objects", "non-numeric-token", "truncated-object"}) {
    const std::string scene = hs_test::shared_dir() + "/bad/" + name + ".sld";
    std::string first;
    for (const char* proto : {"raw", "course", "framed"}) {
      const std::string out = dir.file("x.ppm");
      const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", sim_binary, "--sim", board, "--protocol", proto,
                                   "--size", "16x16", scene, "-o", out, "--first-byte-timeout", "20"});
      INFO(proto << " " << scene << "\n" << r.err);
      CHECK(r.status == 3);
      const std::string message = scene_error(r.err);
      CHECK_FALSE(message.empty());
      if (first.empty()) first = message;
      CHECK(message == first);
      CHECK_FALSE(hs_test::file_exists(out));
    }
  }
}

TEST_CASE("course and framed report scene errors", "[e2e][course][framed][bad]") {
  check_scene_errors(HS_STANDIN, HS_STANDIN);
  hs_test::TempDir dir;
  // Truncated scenes are caught by the course converter before sending.
  const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", HS_STANDIN, "--sim", HS_STANDIN, "--protocol", "course",
                               hs_test::shared_dir() + "/bad/truncated-object.sld", "-o", dir.file("y.ppm")});
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::Contains("scene rejected before sending"));
}

TEST_CASE("framed mode reports a plain error line from a board that does not frame", "[e2e][framed]") {
  // A raw-only board takes the frames for SLD text and rejects them.
  minrt::send::SimLauncher board;
  hs_test::start_standin(board, "16x16", "p6", "raw");
  hs_test::TempDir dir;
  const auto r = hs_test::run({HS_HOST_SEND, "--no-handshake", "--port", board.pty_path(), "--protocol", "framed", "--size", "16x16",
                               "--format", "p6", ball(), "-o", dir.file("x.ppm"), "--first-byte-timeout", "10"});
  INFO(r.err);
  CHECK(r.status == 3);
  CHECK_THAT(r.err, Catch::Contains("the board reported an error: 1:1:"));
  CHECK_FALSE(hs_test::file_exists(dir.file("x.ppm")));
}

TEST_CASE("course and framed end to end against firmware-sim running the firmware", "[e2e][course][framed][firmware]") {
  HS_NEEDS_FIRMWARE();
  check_course_and_framed(HS_FIRMWARE_SIM, HS_FIRMWARE_ELF, "32x32", "");
}

TEST_CASE("course mode against the firmware at 115200 921600 and 3000000 baud", "[e2e][course][firmware]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  for (const char* baud : {"115200", "921600", "3000000"}) {
    const std::string out = dir.file(std::string("course-") + baud + ".ppm");
    const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF,
                                 "--protocol", "course", "--baud", baud, "--size", "24x16", "--format", "p6",
                                 ball(), "-o", out});
    INFO(baud << "\n" << r.err);
    REQUIRE(r.status == 0);
    CHECK(hs_test::read_file(out) == hs_test::reference_image(ball(), "24x16", "p6"));
  }
}

TEST_CASE("course and framed scene errors from the firmware", "[e2e][course][framed][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  check_scene_errors(HS_FIRMWARE_SIM, HS_FIRMWARE_ELF);
}

TEST_CASE("a 0x04 inside the scene is refused before sending over raw, with minrt's message", "[e2e][bad]") {
  // The board takes 0x04 as the end of a raw scene: here it would read the
  // final -1 and render, where minrt reads the token "-1\x04" + "1" and
  // refuses the file.
  hs_test::TempDir dir;
  const std::string scene = dir.file("eot.sld");
  {
    std::ofstream f(scene, std::ios::binary);
    f << "0 0 -100 0 0\n1 0.5 -0.5 255\n0 1 0 0  1 1 1  0 0 0  1  0.5 0.5  255 0 0\n"
         "-1\n0 -1\n-1\n99 0 -1\n-1\x04" "1\n";
  }
  const auto minrt = hs_test::run({HS_MINRT, "--precision", "float", "--shims", "portable", scene, "-o",
                                   dir.file("minrt.ppm")});
  REQUIRE(minrt.status == 2);
  // "FILE:LINE:COL: error: MESSAGE" -> "LINE:COL: MESSAGE"
  const std::string located = minrt.err.substr(scene.size() + 1);
  const std::string expected =
      located.substr(0, located.find(": error: ")) + ": " + located.substr(located.find(": error: ") + 9);
  for (const char* proto : {"raw", "course", "framed"}) {
    const std::string out = dir.file(std::string(proto) + ".ppm");
    const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", HS_STANDIN, "--sim", HS_STANDIN, "--protocol", proto,
                                 "--size", "16x16", scene, "-o", out});
    INFO(proto << "\n" << r.err);
    CHECK(r.status == 3);
    CHECK_FALSE(hs_test::file_exists(out));
    CHECK(scene_error(r.err) + "\n" == expected);
  }
}

TEST_CASE("a scene of exactly 60 objects renders over raw, course and framed on the firmware",
          "[e2e][course][framed][firmware]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string scene = hs_test::shared_dir() + "/bad/sixty-objects-fifty-and-nets.sld";
  const std::string reference = hs_test::reference_image(scene, "16x16", "p6");
  REQUIRE_FALSE(reference.empty());
  for (const char* proto : {"raw", "course", "framed"}) {
    const std::string out = dir.file(std::string(proto) + ".ppm");
    const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF, "--protocol",
                                 proto, "--size", "16x16", "--format", "p6", scene, "-o", out});
    INFO(proto << "\n" << r.err);
    REQUIRE(r.status == 0);
    CHECK(hs_test::read_file(out) == reference);
  }
}
