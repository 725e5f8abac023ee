// CS418 and Jaworski scenes over the course and framed protocols
// (protocol/text_scene_upload.hpp): the header and the in-place texture
// view as units; then end to end against firmware-sim running the firmware,
// image for image against the raw protocol and the host float model, and
// every broken file over every protocol.
#include <catch2/catch.hpp>

#include "formats/registry.hpp"

#include <dirent.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "core/base/bit_cast.hpp"
#include "png_io.hpp"
#include "protocol/text_scene_upload.hpp"
#include "protocol/texture_blobs.hpp"
#include "protocol/protocol_framed.hpp"
#include "protocol_course_host.hpp"
#include "protocol_framed_host.hpp"
#include "sim_launcher.hpp"
#include "test_support.hpp"

using hs_test::joined;
using hs_test::run;
using hs_test::RunResult;
using hs_test::send_sim;
using hs_test::text_protocols;
using namespace minrt::send;

namespace {

std::vector<std::string> files_in(const std::string& dir, const std::string& ext) {
  std::vector<std::string> out;
  if (DIR* d = ::opendir(dir.c_str())) {
    while (const dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > ext.size() && n.compare(n.size() - ext.size(), ext.size(), ext) == 0) out.push_back(dir + "/" + n);
    }
    ::closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The host float model's image (what the board must reproduce).
void host_model(const std::string& scene, const std::string& out) {
  const RunResult r = run({HS_MINRT, "-q", "--precision", "float", "--shims", "portable", scene, "-o", out});
  INFO(r.err);
  REQUIRE(r.status == 0);
}

}  // namespace

TEST_CASE("text-scene header: its marker is a NaN in either byte order and it frames the bytes", "[course][framed]") {
  for (auto e : {course::Endian::kLittle, course::Endian::kBig}) {
    uint8_t h[text::kHeaderBytes];
    text::put_header(h, minrt::formats::format_of(minrt::formats::FormatId::kJaworski).wire_tag, 1234, e);
    CHECK(text::is_marker(h, e));
    const float f = minrt::bit_cast<float>(course::get_u32(h, e));
    CHECK(f != f);  // the SLD reader refuses it as a first value
    CHECK(course::get_u32(h + 4, e) == minrt::formats::format_of(minrt::formats::FormatId::kJaworski).wire_tag);
    CHECK(course::get_u32(h + 8, e) == 1234u);
  }
  // Course words: padded to whole words, the bytes unchanged in between.
  const std::string words = text_scene_course_words(minrt::formats::format_of(minrt::formats::FormatId::kCs418).wire_tag, "png 1 1 a.png\n", true);
  CHECK(words.size() == 12 + 16);
  CHECK(words.substr(12, 14) == "png 1 1 a.png\n");
  CHECK(words.substr(26) == std::string(2, '\0'));

  // Framed: an SLD text is not taken for a header; a sound header is viewed
  // in place; a wrong length or format is refused with the reason.
  text::TextScene scene;
  minrt::Diagnostic d;
  bool ok = true;
  const std::string sld = "0 0 -100 0 0\n";
  CHECK_FALSE(text::view_framed(reinterpret_cast<const uint8_t*>(sld.data()), sld.size(), scene, ok, d));
  std::string up(text::kHeaderBytes, '\0');
  text::put_header(reinterpret_cast<uint8_t*>(up.data()), minrt::formats::format_of(minrt::formats::FormatId::kCs418).wire_tag, 5, course::Endian::kLittle);
  up += "hello";
  REQUIRE(text::view_framed(reinterpret_cast<const uint8_t*>(up.data()), up.size(), scene, ok, d));
  CHECK(ok);
  CHECK(scene.format == minrt::formats::format_of(minrt::formats::FormatId::kCs418).wire_tag);
  CHECK(std::string(reinterpret_cast<const char*>(scene.bytes), scene.size) == "hello");
  REQUIRE(text::view_framed(reinterpret_cast<const uint8_t*>(up.data()), up.size() - 1, scene, ok, d));
  CHECK_FALSE(ok);
  CHECK(std::string(d.message, d.length) == "scene upload: header says 5 bytes, 4 arrived");
  // A tag no format can have is refused by the protocol itself; one the
  // registry does not know, by the board (runtime/board_formats.cpp).
  text::put_header(reinterpret_cast<uint8_t*>(up.data()), MINRT_SCENE_FORMAT_TAG_LIMIT, 5, course::Endian::kLittle);
  minrt::Diagnostic d2;
  REQUIRE(text::view_framed(reinterpret_cast<const uint8_t*>(up.data()), up.size(), scene, ok, d2));
  CHECK_FALSE(ok);
  CHECK(std::string(d2.message, d2.length) == "scene upload: unknown scene format 256");
}

TEST_CASE("course text scene on the board side: bytes into the arena's top, the padding read, a cut reported",
          "[course]") {
  const std::string words = text_scene_course_words(minrt::formats::format_of(minrt::formats::FormatId::kJaworski).wire_tag, "abcde", false);
  std::vector<unsigned char> mem(4096);
  for (size_t cut : {words.size(), words.size() - 1}) {
    minrt::Arena arena(mem.data(), mem.size());
    minrt::MemorySource src{reinterpret_cast<const uint8_t*>(words.data()) + 4, cut - 4};  // after the marker
    text::TextScene scene;
    bool too_large = false;
    minrt::Diagnostic d;
    const bool ok = text::read_course(src.source(), course::Endian::kLittle, arena, scene, too_large, d);
    if (cut == words.size()) {
      REQUIRE(ok);
      CHECK(std::string(reinterpret_cast<const char*>(scene.bytes), scene.size) == "abcde");
      CHECK(src.pos == src.size);  // the three padding bytes are consumed
      CHECK(arena.top_mark() == mem.size() - 5);
    } else {
      CHECK_FALSE(ok);
      CHECK_FALSE(too_large);
      CHECK(std::string(d.message, d.length) == "course: scene ended early, 1 of 8 bytes missing");
    }
  }
  // More than the arena holds: refused before any scene byte is stored.
  minrt::Arena small(mem.data(), 4);
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(words.data()) + 4, words.size() - 4};
  text::TextScene scene;
  bool too_large = false;
  minrt::Diagnostic d;
  CHECK_FALSE(text::read_course(src.source(), course::Endian::kLittle, small, scene, too_large, d));
  CHECK(too_large);
  CHECK(std::string(d.message, d.length) == "scene of 5 bytes does not fit in the board's memory (4 bytes free)");
}

TEST_CASE("the texture preamble read in place points into the upload, and a cut one is refused", "[course][framed]") {
  // Two textures: 2x1 and 1x1.
  std::string pre;
  pre += static_cast<char>(2);
  pre += static_cast<char>(1);
  pre += "a";
  pre += std::string("\x02\x00\x01\x00", 4);
  pre += "RGBrgb";
  pre += static_cast<char>(3);
  pre += "bcd";
  pre += std::string("\x01\x00\x01\x00", 4);
  pre += "xyz";
  const auto* data = reinterpret_cast<const uint8_t*>(pre.data());
  textures::Table table;
  size_t used = 0;
  minrt::Diagnostic d;
  REQUIRE(textures::view(data, pre.size(), table, used, d));
  CHECK(used == pre.size());
  CHECK(table.count == 2);
  CHECK(table.find("bcd") == 1);
  CHECK(table.items[0].width == 2);
  CHECK(table.items[0].rgb == data + 7);  // count, name length, name, size
  CHECK(table.items[1].rgb == data + pre.size() - 3);
  for (size_t n = 0; n < pre.size(); ++n) {
    textures::Table t;
    minrt::Diagnostic e;
    INFO("cut at " << n);
    CHECK_FALSE(textures::view(data, n, t, used, e));
    CHECK(e.length > 0);
  }
}

TEST_CASE("CS418 scenes over course and framed: the firmware's PNG is the raw protocol's, pixels the host float model's",
          "[e2e][firmware][cs418]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string cs418 = hs_test::shared_dir() + "/formats/cs418/";
  // ray-tex: two 1000x500 textures (3 MB of texels) travel ahead of the text.
  for (const char* name : {"ray-sphere", "ray-shadow-plane", "ray-trans3", "ray-tri", "ray-tex"}) {
    INFO(name);
    hs_test::check_png_on_every_protocol(dir, cs418 + name + ".txt", {});
  }
}

TEST_CASE("Jaworski scenes over course and framed: the firmware's BMP is the host float model's, byte for byte",
          "[e2e][firmware][jaworski]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string jw = hs_test::shared_dir() + "/formats/jaworski/";
  for (const char* name : {"basic-diffuse-sphere", "mixed-nested-deep", "syntax-case-comments", "reflective-spheres",
                           "spherical-light-falloff"}) {
    const std::string scene = jw + name + ".txt";
    const std::string host = dir.file(std::string(name) + "-host.bmp");
    host_model(scene, host);
    const std::string want = hs_test::read_file(host);
    for (const auto& protocol : text_protocols()) {
      const std::string got = dir.file(std::string(name) + "-got.bmp");
      const RunResult p = send_sim(scene, got, protocol);
      INFO(name << " " << joined(protocol) << "\n" << p.err);
      REQUIRE(p.status == 0);
      CHECK(hs_test::read_file(got) == want);
    }
  }
}

TEST_CASE("every broken CS418 and Jaworski file gets its located error over every protocol, and no file",
          "[e2e][firmware][bad]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  std::vector<std::string> bad = files_in(std::string(HS_SOURCE_DIR) + "/test/cs418/bad", ".txt");
  const std::vector<std::string> jw = files_in(hs_test::shared_dir() + "/formats/jaworski/bad", ".txt");
  bad.insert(bad.end(), jw.begin(), jw.end());
  REQUIRE(bad.size() >= 9);
  for (const std::string& scene : bad) {
    // minrt's message, "minrt: FILE:LINE:COL: error: MESSAGE" (or without
    // the prefix): the board says "LINE:COL: MESSAGE"; what host-send must
    // refuse itself (an unusable png line, a texture it cannot read) it
    // reports as minrt does.
    const RunResult m = run({HS_MINRT, "--precision", "float", "--shims", "portable", scene, "-o", dir.file("m.out")});
    REQUIRE(m.status != 0);
    std::string line = m.err.substr(0, m.err.find('\n'));
    if (line.rfind("minrt: ", 0) == 0) line = line.substr(7);
    REQUIRE(line.rfind(scene + ":", 0) == 0);
    const std::string located = line.substr(scene.size() + 1);  // LINE:COL: error: MESSAGE
    const std::size_t e = located.find(": error: ");
    REQUIRE(e != std::string::npos);
    const std::string board = located.substr(0, e) + ": " + located.substr(e + 9);
    for (const auto& protocol : std::vector<std::vector<std::string>>{{}, text_protocols()[0], text_protocols()[2]}) {
      const std::string out = dir.file("out.img");
      const RunResult r = send_sim(scene, out, protocol);
      INFO(scene << " " << joined(protocol) << "\n" << r.err << "minrt: " << line);
      CHECK(r.status == 3);
      CHECK((r.err.find("the board reported an error: " + board + "\n") != std::string::npos ||
             r.err.find("scene rejected before sending: " + line + "\n") != std::string::npos));
      CHECK_FALSE(hs_test::file_exists(out));
    }
  }
}

TEST_CASE("framed mode delivers CS418 and Jaworski images exactly over a damaged line", "[fault][framed][firmware]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  // Small images: an RGBA row of a few hundred bytes crosses this line
  // intact about half the time, so the requests converge in a few rounds.
  const std::vector<std::string> scenes = {hs_test::shared_dir() + "/formats/cs418/ray-sphere.txt",
                                           hs_test::shared_dir() + "/formats/jaworski/raydepth-zero.txt"};
  int seed = 10;
  for (const std::string& scene : scenes) {
    const bool png = scene.find("/cs418/") != std::string::npos;
    const std::string ref = dir.file(png ? "ref.png" : "ref.bmp");
    RunResult r0 = send_sim(scene, ref, {});
    REQUIRE(r0.status == 0);
    for (int k = 0; k < 2; ++k, ++seed) {
      SimLauncher board, relay;
      SimConfig cfg;
      cfg.simulator = HS_FIRMWARE_SIM;
      cfg.firmware = HS_FIRMWARE_ELF;
      cfg.firmware_args = {"--protocol=framed"};
      std::string err;
      REQUIRE(board.start(cfg, err));
      SimConfig rc;
      rc.exact_args = {HS_FAULT_RELAY, "--seed",  std::to_string(seed), "--drop",     "0.0005", "--flip",
                       "0.0005",       "--dup",   "0.0005",             "--stall",    "0.0005", "--stall-ms",
                       "200",          "--delay", "0.001",              board.pty_path()};
      REQUIRE(relay.start(rc, err));
      const std::string out = dir.file(png ? "got.png" : "got.bmp");
      const RunResult r = run({HS_HOST_SEND, "--no-handshake", "--port", relay.pty_path(), "--protocol", "framed", scene, "-o", out,
                               "--idle-timeout", "20"});
      INFO(scene << " seed " << seed << "\n" << r.err << relay.output());
      CHECK(r.status == 0);
      CHECK(hs_test::read_file(out) == hs_test::read_file(ref));
      relay.stop(3000);
      board.stop(3000);
    }
  }
}

TEST_CASE("RowFramer with 4 bytes a pixel: RGBA rows, a store attached late, re-sent rows, the host's PNG from them",
          "[framed]") {
  std::string wire;
  auto append = [](void* ctx, const uint8_t* d, size_t n) {
    static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(d), n);
  };
  framed::RowFramer framer(minrt::ByteSink{append, &wire}, nullptr, 0);
  framer.set_pixel_bytes(4);
  std::vector<uint8_t> store(2 * 3 * 4);
  framer.attach_store(store.data(), store.size());
  uint8_t pixels[24];
  for (int i = 0; i < 24; ++i) pixels[i] = static_cast<uint8_t>(10 + i);
  framer.begin(2, 3);
  for (int y = 0; y < 3; ++y) framer.row(y, pixels + 8 * y);
  framer.send_end();
  CHECK(framer.stored());
  uint8_t buf[64];
  framed::FrameParser parser(buf, sizeof buf);
  std::vector<std::vector<uint8_t>> rows;
  std::string types;
  for (char c : wire)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) {
      types.push_back(static_cast<char>(parser.type()));
      if (parser.type() == framed::kRow) {
        CHECK(parser.length() == 8);
        CHECK(parser.seq() == rows.size());
        rows.emplace_back(parser.payload(), parser.payload() + parser.length());
      }
    }
  CHECK(types == "HDDDZ");
  // A request for row 2: the stored RGBA bytes come again.
  std::string req;
  const uint8_t list[] = {2, 0};
  framed::write_frame(minrt::ByteSink{append, &req}, framed::kRequest, 0, list, 2);
  for (char c : req)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame) {
      wire.clear();
      framer.answer_request(parser);
    }
  for (char c : wire)
    if (parser.feed(static_cast<uint8_t>(c)) == framed::FrameParser::kFrame && parser.type() == framed::kRow)
      CHECK(std::vector<uint8_t>(parser.payload(), parser.payload() + 8) == rows[2]);
  // The host's image from the rows: the PNG decodes to them.
  const std::string png = framed_rgba_image(FramedImage::kPng, 2, 3, rows);
  hs_test::TempDir dir;
  {
    std::FILE* f = std::fopen(dir.file("r.png").c_str(), "wb");
    std::fwrite(png.data(), 1, png.size(), f);
    std::fclose(f);
  }
  minrt::host::RgbaImage img;
  std::string why;
  REQUIRE(minrt::host::read_png(dir.file("r.png"), img, why));
  CHECK(img.rgba == std::vector<uint8_t>(pixels, pixels + 24));
  // BMP: 54-byte header, rows as they came (the tracer's bottom row first), BGRA.
  const std::string bmp = framed_rgba_image(FramedImage::kBmp, 2, 3, rows);
  REQUIRE(bmp.size() == 54 + 24);
  CHECK(static_cast<uint8_t>(bmp[54]) == pixels[2]);
  CHECK(static_cast<uint8_t>(bmp[56]) == pixels[0]);
}
