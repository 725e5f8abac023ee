// Sparse textures (MINRT_TEXTURES_SPARSE_MARKER): host-send records the
// texels its own render reads and sends only their tiles. In memory: the
// preamble against both board readers (every tile sent exact, the rest the
// unsent colour, cuts and damage refused), and when it stays whole; then
// end to end against the firmware in firmware-sim over every protocol, the
// board catching a read of a texel not sent (forced), and a scene without
// textures sent as before.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "png_io.hpp"
#include "protocol/texel_filter.hpp"
#include "protocol/texture_blobs.hpp"
#include "scene_upload.hpp"
#include "sim_launcher.hpp"
#include "test_support.hpp"
#include "texel_record.hpp"
#include "texture_files.hpp"
#include "texture_preamble.hpp"

using hs_test::joined;
using hs_test::write_texture;
using hs_test::run;
using hs_test::RunResult;
using hs_test::send_sim;
using namespace minrt::send;
using Bytes = std::vector<std::uint8_t>;

namespace {

struct Fixture {
  hs_test::TempDir dir;
  std::string scene = "png 8 8 out.png\ntexture a.png\nsphere 0 0 -2 1\ntexture b.png\nsphere 1 0 -2 1\nsun 1 1 1\n";
  std::vector<Bytes> texels;  // what load_png_texture gives, in order
  TexelMarks marks;
  Fixture() {
    write_texture(dir.file("a.png"), 64, 40, 1, 3, 5, 27);
    write_texture(dir.file("b.png"), 5, 300, 2, 3, 5, 27);
    std::string error;
    for (const char* name : {"a.png", "b.png"}) {
      minrt::host::RgbTexture t;
      REQUIRE(minrt::host::load_png_texture(dir.path + "/", name, t, error));
      texels.emplace_back(t.rgb.begin(), t.rgb.end());
    }
    // a.png: a few texels read, two of them neighbours; b.png: none.
    marks["a.png"].assign(64 * 40, 0);
    for (int at : {5 * 64 + 10, 5 * 64 + 11, 30 * 64 + 40, 39 * 64 + 63}) marks["a.png"][at] = 1;
    marks["b.png"].assign(5 * 300, 0);
  }
  std::string build(const TexelMarks* m, TexelCount* count = nullptr) const {
    std::string pre, error;
    INFO(error);
    REQUIRE(build_texture_preamble(scene, "s.txt", dir.path + "/", 1u << 30, pre, error, m, count));
    return pre;
  }
};

// Every texel of `r` either the texture's own (all those of tiles sent,
// and every texel `read` marks) or the unsent colour (all others).
void check_sparse_texture(const textures::Received& r, const Bytes& want, const Bytes& read) {
  REQUIRE(r.form >= 1);
  REQUIRE(r.tiles != nullptr);
  const int shift = r.form - 1;
  const minrt::TileMask m{r.tiles, minrt::tiles_along(static_cast<std::size_t>(r.width), shift), shift};
  std::size_t sent = 0;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * r.width + x;
      const std::uint8_t* got = r.rgb + 3 * i;
      INFO(r.name << " texel " << x << "," << y);
      if (m.has(x, y)) {
        ++sent;
        CHECK(std::memcmp(got, want.data() + 3 * i, 3) == 0);
      } else {
        CHECK(read[i] == 0);
        CHECK(std::memcmp(got, texel_filter::kUnsent, 3) == 0);
      }
    }
  CHECK(sent == r.sent);
}

void check_table(const textures::Table& table, const Fixture& f) {
  REQUIRE(table.count == 2);
  CHECK(table.sparse);
  check_sparse_texture(table.items[0], f.texels[0], f.marks.at("a.png"));
  check_sparse_texture(table.items[1], f.texels[1], f.marks.at("b.png"));
  CHECK(table.items[1].sent == 0);
}

std::string error_of(const minrt::Diagnostic& d) { return std::string(d.message, d.length); }

}  // namespace

TEST_CASE("sparse textures: the tiles read come back exactly from the line and in memory, the rest unsent", "[textures]") {
  Fixture f;
  TexelCount count;
  const std::string pre = f.build(&f.marks, &count);
  REQUIRE(static_cast<std::uint8_t>(pre[0]) == MINRT_TEXTURES_SPARSE_MARKER);
  CHECK(count.texels == 64 * 40 + 5 * 300);
  CHECK(count.sent >= 4);
  CHECK(count.sent < 64 * 40 / 4);
  CHECK(pre.size() < f.build(nullptr).size() / 4);
  const auto* data = reinterpret_cast<const std::uint8_t*>(pre.data());
  {
    minrt::MemorySource line{data + 1, pre.size() - 1};
    std::vector<std::uint8_t> mem(1 << 20);
    minrt::Arena arena(mem.data(), mem.size());
    textures::Table table{};
    minrt::Diagnostic error;
    INFO(error_of(error));
    REQUIRE(textures::receive_compressed(line.source(), arena, table, error, MINRT_TEXTURES_SPARSE_MARKER));
    CHECK(line.pos == line.size);
    check_table(table, f);
    CHECK(arena.top_mark() == mem.size());  // the inflater's scratch went back
  }
  {
    // Held behind a text-scene header at the arena's top, as course and
    // framed hold it: decoded into the bottom end, never in place.
    std::vector<std::uint8_t> mem(1 << 20);
    minrt::Arena arena(mem.data(), mem.size());
    std::uint8_t* upload = arena.alloc_top<std::uint8_t>(12 + pre.size());
    REQUIRE(upload != nullptr);
    std::memcpy(upload + 12, pre.data(), pre.size());
    textures::Table table{};
    minrt::Diagnostic error;
    std::size_t used = 0;
    INFO(error_of(error));
    REQUIRE(textures::unpack(upload + 12, pre.size(), arena, table, used, error));
    CHECK(used == pre.size());
    check_table(table, f);
    CHECK(std::memcmp(upload + 12, pre.data(), pre.size()) == 0);  // the upload is untouched
  }
}

TEST_CASE("sparse textures: cuts and damage are refused with the texture's name", "[textures]") {
  Fixture f;
  const std::string pre = f.build(&f.marks);
  // Marker, count, lead (4), then a.png's name length, name, size (4),
  // compressed size, CRC-32, form, texels sent.
  const std::size_t a_crc = 6 + 1 + 5 + 4 + 4;
  const std::size_t a_form = a_crc + 4;
  const std::size_t a_sent = a_form + 1;
  std::string bad = pre;
  bad[a_crc] ^= 1;
  CHECK(hs_test::unpack_textures_error(bad) == "texture a.png: texels damaged (CRC-32 mismatch)");
  bad = pre;
  bad[a_form] = MINRT_TEXTURES_MAX_TILE_FORM + 1;
  CHECK(hs_test::unpack_textures_error(bad) == "texture a.png: bad form");
  bad = pre;
  bad[a_sent] = static_cast<char>(bad[a_sent] + 1);  // one texel more than the tiles hold
  CHECK(hs_test::unpack_textures_error(bad).rfind("texture a.png: ", 0) == 0);
  for (std::size_t n = 0; n < pre.size(); ++n) {
    INFO("cut at " << n);
    CHECK(!hs_test::unpack_textures_error(pre.substr(0, n)).empty());
    minrt::MemorySource line{reinterpret_cast<const std::uint8_t*>(pre.data()) + 1, n == 0 ? 0 : n - 1};
    std::vector<std::uint8_t> mem(1 << 20);
    minrt::Arena arena(mem.data(), mem.size());
    textures::Table table{};
    minrt::Diagnostic error;
    CHECK_FALSE(textures::receive_compressed(line.source(), arena, table, error, MINRT_TEXTURES_SPARSE_MARKER));
  }
  // The compressed form keeps its message for a header cut after the size.
  CHECK(hs_test::unpack_textures_error(pre.substr(0, a_crc)) == "texture preamble cut off in the header of a.png");
}

TEST_CASE("sparse textures: textures read whole, or no record, go in the compressed preamble as before", "[textures]") {
  Fixture f;
  TexelMarks all = f.marks;
  for (auto& m : all) m.second.assign(m.second.size(), 1);
  const std::string whole = f.build(nullptr);
  REQUIRE(static_cast<std::uint8_t>(whole[0]) == MINRT_TEXTURES_DEFLATE_MARKER);
  CHECK(f.build(&all) == whole);
  // A scene without textures: its text alone, recorded or not.
  Upload up;
  std::string error;
  const UploadRequest request{f.dir.file("plain.txt"), f.dir.path + "/", 1u << 30, 0, 0, true};
  const std::string plain = "png 8 8 plain.png\nsphere 0 0 -2 1\nsun 1 1 1\n";
  REQUIRE(upload_format(minrt::formats::FormatId::kCs418).prepare(request, plain, up, error));
  CHECK(up.bytes == plain);
  CHECK_FALSE(up.sparse);
  CHECK(up.note.empty());
}

TEST_CASE("sparse textures: the host's render records the texels of the textures it shows", "[textures]") {
  Fixture f;
  // a.png on a sphere that fills the view; b.png on one behind the camera.
  const std::string scene =
      "png 16 16 out.png\ntexture a.png\nsphere 0 0 -1.5 1\ntexture b.png\nsphere 0 0 5 1\nsun 1 1 1\n";
  TexelMarks marks;
  REQUIRE(record_cs418_texels(scene, f.dir.path + "/", marks));
  REQUIRE(marks.size() == 2);
  std::size_t a = 0, b = 0;
  for (std::uint8_t v : marks.at("a.png")) a += v;
  for (std::uint8_t v : marks.at("b.png")) b += v;
  CHECK(a > 16);        // about one texel a pixel on the sphere
  CHECK(a <= 16 * 16);  // one look-up a pixel at most: no reflections
  CHECK(b == 0);
  // A scene error is left to the board: nothing recorded.
  CHECK_FALSE(record_cs418_texels("png 8 8 x.png\nsphere 0 0\n", f.dir.path + "/", marks));
}

namespace {

// The host float model's pixels.
minrt::host::RgbaImage model_of(const hs_test::TempDir& dir, const std::string& scene) {
  const std::string host = dir.file("host.png");
  const RunResult m = run({HS_MINRT, "-q", "--precision", "float", "--shims", "portable", scene, "-o", host});
  INFO(m.err);
  REQUIRE(m.status == 0);
  minrt::host::RgbaImage img;
  std::string why;
  REQUIRE(minrt::host::read_png(host, img, why));
  return img;
}

void check_pixels(const std::string& got, const minrt::host::RgbaImage& want) {
  minrt::host::RgbaImage img;
  std::string why;
  REQUIRE(minrt::host::read_png(got, img, why));
  CHECK(img.width == want.width);
  CHECK(img.height == want.height);
  CHECK(img.rgba == want.rgba);
}

const std::vector<std::vector<std::string>>& every_protocol() {
  static const std::vector<std::vector<std::string>> p = {{"--protocol", "raw"},
                                                          {"--protocol", "raw", "--no-check"},
                                                          {"--protocol", "course"},
                                                          {"--protocol", "course", "--endian", "big"},
                                                          {"--protocol", "framed"}};
  return p;
}

// Sets an environment variable for the scope (host-send inherits it).
struct ScopedEnv {
  const char* name;
  ScopedEnv(const char* n, const char* v) : name(n) { ::setenv(n, v, 1); }
  ~ScopedEnv() { ::unsetenv(name); }
};

}  // namespace

TEST_CASE("sparse textures end to end: ray-tex sends the tiles it reads over every protocol, image the host's",
          "[e2e][firmware][cs418][textures]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string scene = hs_test::shared_dir() + "/formats/cs418/ray-tex.txt";
  const minrt::host::RgbaImage want = model_of(dir, scene);
  for (const auto& protocol : every_protocol()) {
    const std::string got = dir.file("got.png");
    const RunResult p = send_sim(scene, got, protocol);
    INFO(joined(protocol) << "\n" << p.err);
    REQUIRE(p.status == 0);
    CHECK(p.err.find(" of 1000000 texels sent, the tiles the render reads") != std::string::npos);
    CHECK(p.err.find("sending the textures whole") == std::string::npos);
    check_pixels(got, want);
  }
  // --full-textures: every texel, the same image.
  const std::string got = dir.file("full.png");
  const RunResult p = send_sim(scene, got, {"--full-textures"});
  INFO(p.err);
  REQUIRE(p.status == 0);
  CHECK(p.err.find("texels sent") == std::string::npos);
  check_pixels(got, want);
}

TEST_CASE("sparse textures end to end: a read of a texel not sent is caught, and the textures go whole",
          "[e2e][firmware][cs418][textures]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string scene = hs_test::shared_dir() + "/formats/cs418/ray-tex.txt";
  const minrt::host::RgbaImage want = model_of(dir, scene);
  // Test only: host-send sends no texel its render read.
  const ScopedEnv drop("MINRT_HOST_SEND_TEST_UNSENT_TEXELS", "1");
  for (const auto& protocol : every_protocol()) {
    const std::string got = dir.file("got.png");
    const RunResult p = send_sim(scene, got, protocol);
    INFO(joined(protocol) << "\n" << p.err);
    REQUIRE(p.status == 0);
    CHECK(p.err.find("host-send: warning: the board read a texel host-send did not send (" MINRT_UNSENT_TEXEL_ERROR
                     "texture ") != std::string::npos);
    CHECK(p.err.find("; sending the textures whole\n") != std::string::npos);
    check_pixels(got, want);
  }
  // A board on a port (firmware-sim on its pty, not started by host-send)
  // cannot be started again: one line, status 3, no file.
  SimLauncher board;
  SimConfig cfg;
  cfg.simulator = HS_FIRMWARE_SIM;
  cfg.firmware = HS_FIRMWARE_ELF;
  std::string why;
  REQUIRE(board.start(cfg, why));
  const std::string got = dir.file("port.png");
  const RunResult p = run({HS_HOST_SEND, "-q", "--no-handshake", "-p", board.pty_path(), scene, "-o", got});
  board.stop(2000);
  INFO(p.err);
  CHECK(p.status == 3);
  CHECK(p.err.rfind("host-send: error: the board read a texel host-send did not send (" MINRT_UNSENT_TEXEL_ERROR, 0) ==
        0);
  CHECK(p.err.find("); reset the board and send again with --full-textures\n") != std::string::npos);
  CHECK(std::count(p.err.begin(), p.err.end(), '\n') == 1);
  CHECK_FALSE(hs_test::file_exists(got));
}

TEST_CASE("sparse textures end to end: a scene without textures goes and comes back as before",
          "[e2e][firmware][cs418][textures]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  const std::string scene = hs_test::shared_dir() + "/formats/cs418/ray-sphere.txt";
  const minrt::host::RgbaImage want = model_of(dir, scene);
  const std::string a = dir.file("a.png"), b = dir.file("b.png");
  const RunResult p = send_sim(scene, a, {});
  const RunResult q = send_sim(scene, b, {"--full-textures"});
  INFO(p.err << q.err);
  REQUIRE(p.status == 0);
  REQUIRE(q.status == 0);
  CHECK(p.err.find("texels") == std::string::npos);
  CHECK(hs_test::read_file(a) == hs_test::read_file(b));
  check_pixels(a, want);
}
