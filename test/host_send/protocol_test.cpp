// The shared course and framed protocol code, and both protocols end to end
// over a pty against the stand-in board.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "protocol/protocol_course.hpp"
#include "protocol_course_host.hpp"
#include "protocol/protocol_framed.hpp"
#include "protocol_framed_host.hpp"
#include "test_support.hpp"

using namespace minrt::send;

namespace {

std::string ball() { return hs_test::shared_dir() + "/scenes/ball.sld"; }

void append_fn(void* ctx, const uint8_t* d, size_t n) { static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(d), n); }

// Runs a SceneTextSource over the words and returns the text it produces.
std::string words_to_text(const std::string& words, course::Endian e) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(words.data()), words.size()};
  course::SceneTextSource text(mem.source(), e);
  std::string out;
  for (int c; (c = text.source().get()) >= 0;) out.push_back(static_cast<char>(c));
  return out;
}

}  // namespace

TEST_CASE("exact float text reads back as the same float", "[course]") {
  std::mt19937 rng(7);
  std::vector<uint32_t> cases = {0x00000000u, 0x80000000u, 0x00000001u, 0x007FFFFFu, 0x00800000u, 0x7F7FFFFFu,
                                 0x3F800000u, 0xBF800000u, 0x3DCCCCCDu, 0x42C80000u, 0xC2C80000u, 0x4B000001u};
  for (int i = 0; i < 20000; ++i) {
    uint32_t b = rng();
    if (((b >> 23) & 0xFF) == 0xFF) continue;
    cases.push_back(b);
  }
  char text[200];
  for (uint32_t bits : cases) {
    const size_t n = course::format_float_exact(bits, text);
    REQUIRE(n < 190);
    text[n] = 0;
    const float back = std::strtof(text, nullptr);
    uint32_t got;
    std::memcpy(&got, &back, 4);
    INFO(text);
    CHECK(got == bits);
  }
  size_t n = course::format_float_exact(0x3F800000u, text);
  CHECK(std::string(text, n) == "1");
  n = course::format_float_exact(0xBFC00000u, text);
  CHECK(std::string(text, n) == "-1.5");
  n = course::format_float_exact(0x7F800000u, text);
  CHECK(std::string(text, n) == "inf");
}

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
  // The board side turns the words back into text the SLD reader takes.
  const std::string text = words_to_text(words, course::Endian::kLittle);
  CHECK_THAT(text, Catch::StartsWith("0\n0\n-100\n0\n0\n1\n0.5\n-0.5\n255\n0\n2\n0\n1\n"));
  CHECK_THAT(text, Catch::EndsWith("-1\n0\n-1\n-1\n99\n0\n-1\n-1\n"));
  CHECK(words_to_text(big, course::Endian::kBig) == text);
}

TEST_CASE("the course converter refuses what it cannot encode", "[course]") {
  std::string words, err;
  CHECK_FALSE(sld_to_course_words("0 0 -100 0 0\n1.5 0 0 0\n", false, words, err));
  CHECK_THAT(err, Catch::Contains("token 6 '1.5' should be an integer"));
  CHECK_FALSE(sld_to_course_words("0 0 -100 abc 0\n", false, words, err));
  CHECK_THAT(err, Catch::Contains("should be a number"));
  CHECK_FALSE(sld_to_course_words("0 0 -100 0 0\n1 0 0 0\n-1\n", false, words, err));
  CHECK_THAT(err, Catch::Contains("truncated"));
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

TEST_CASE("RowFramer turns P6 output into H and D frames and re-sends rows", "[framed]") {
  std::string wire;
  std::vector<uint8_t> store(4 * 3 * 3);
  framed::RowFramer framer(minrt::ByteSink{&append_fn, &wire}, store.data(), store.size());
  std::string ppm = "P6\n4 3 255\n";
  for (int i = 0; i < 36; ++i) ppm.push_back(static_cast<char>(i));
  framer.sink().put(reinterpret_cast<const uint8_t*>(ppm.data()), ppm.size());
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

// Two bad scenes in course and framed mode through `sim_binary` running
// `board`: the board's error (status 3), no image.
static void check_scene_errors(const std::string& sim_binary, const std::string& board) {
  hs_test::TempDir dir;
  const std::string bad = hs_test::shared_dir() + "/bad/nan-value.sld";
  const std::string bad2 = hs_test::shared_dir() + "/bad/too-many-objects.sld";
  for (const char* proto : {"course", "framed"}) {
    for (const auto& scene : {bad, bad2}) {
      const std::string out = dir.file("x.ppm");
      const auto r = hs_test::run({HS_HOST_SEND, "--sim-binary", sim_binary, "--sim", board, "--protocol", proto,
                                   "--size", "16x16", scene, "-o", out, "--first-byte-timeout", "20"});
      INFO(proto << " " << scene << "\n" << r.err);
      CHECK(r.status == 3);
      CHECK_THAT(r.err, Catch::Contains("the board reported an error: "));
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
  const auto r = hs_test::run({HS_HOST_SEND, "--port", board.pty_path(), "--protocol", "framed", "--size", "16x16",
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
