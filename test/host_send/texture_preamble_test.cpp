// The compressed texture preamble end to end in memory: host-send's
// build_texture_preamble (filter, deflate, lead) against the board's
// receive_compressed (from the line) and unpack (in place below a held
// upload, or into the arena's bottom), damage and cuts refused, and the
// limit on decoded size named before anything is sent.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "png_io.hpp"
#include "protocol/texel_filter.hpp"
#include "protocol/texture_blobs.hpp"
#include "test_support.hpp"
#include "texture_files.hpp"
#include "texture_preamble.hpp"

using namespace minrt::send;
using hs_test::write_texture;
using Bytes = std::vector<std::uint8_t>;

namespace {

struct Fixture {
  hs_test::TempDir dir;
  std::string scene = "png 8 8 out.png\ntexture a.png\nsphere 0 0 -2 1\ntexture b.png\nsphere 1 0 -2 1\nsun 1 1 1\n";
  std::string preamble;
  std::vector<Bytes> texels;  // what load_png_texture gives, in order
  Fixture() {
    write_texture(dir.file("a.png"), 61, 37, 1, 5, 7, 29);
    write_texture(dir.file("b.png"), 5, 300, 2, 5, 7, 29);
    std::string error;
    REQUIRE(build_texture_preamble(scene, "s.txt", dir.path + "/", 1u << 30, preamble, error));
    for (const char* name : {"a.png", "b.png"}) {
      minrt::host::RgbTexture t;
      REQUIRE(minrt::host::load_png_texture(dir.path + "/", name, t, error));
      texels.emplace_back(t.rgb.begin(), t.rgb.end());
    }
  }
  const std::uint8_t* data() const { return reinterpret_cast<const std::uint8_t*>(preamble.data()); }
};

void check_texels(const textures::Table& table, const std::vector<Bytes>& want) {
  REQUIRE(table.count == 2);
  CHECK(table.find("a.png") == 0);
  CHECK(table.find("b.png") == 1);
  for (int i = 0; i < 2; ++i) {
    const textures::Received& r = table.items[i];
    REQUIRE(static_cast<std::size_t>(r.width) * r.height * 3 == want[i].size());
    CHECK(std::memcmp(r.rgb, want[i].data(), want[i].size()) == 0);
  }
}

std::uint32_t le32(const std::uint8_t* p) { return p[0] | p[1] << 8 | p[2] << 16 | static_cast<std::uint32_t>(p[3]) << 24; }

}  // namespace

TEST_CASE("texture preamble: filtered and deflated texels come back from the line exactly", "[textures]") {
  Fixture f;
  REQUIRE(static_cast<std::uint8_t>(f.preamble[0]) == MINRT_TEXTURES_DEFLATE_MARKER);
  CHECK(f.preamble[1] == 2);
  CHECK(f.preamble.size() < f.texels[0].size() + f.texels[1].size());
  minrt::MemorySource line{f.data() + 1, f.preamble.size() - 1};
  std::vector<std::uint8_t> mem(1 << 20);
  minrt::Arena arena(mem.data(), mem.size());
  textures::Table table{};
  minrt::Diagnostic error;
  REQUIRE(textures::receive_compressed(line.source(), arena, table, error));
  CHECK(line.pos == line.size);
  check_texels(table, f.texels);
  CHECK(arena.top_mark() == mem.size());  // the inflater's scratch went back
}

TEST_CASE("texture preamble: a held upload is decoded in place, the lead's bytes below it", "[textures]") {
  Fixture f;
  const std::string text = "png 8 8 out.png\n";
  for (std::size_t ahead : {std::size_t{0}, std::size_t{12}}) {  // raw, or behind a text-scene header
    INFO("header ahead " << ahead);
    std::vector<std::uint8_t> mem(1 << 20);
    minrt::Arena arena(mem.data(), mem.size());
    const std::size_t size = ahead + f.preamble.size() + text.size();
    std::uint8_t* upload = arena.alloc_top<std::uint8_t>(size);
    REQUIRE(upload != nullptr);
    std::memcpy(upload + ahead, f.preamble.data(), f.preamble.size());
    std::memcpy(upload + ahead + f.preamble.size(), text.data(), text.size());
    const std::uint8_t* data = upload + ahead;
    textures::Table table{};
    minrt::Diagnostic error;
    std::size_t used = 0;
    const std::size_t bottom = arena.used();
    const std::uint32_t lead = le32(data + 2);  // the texels overwrite it
    REQUIRE(textures::unpack(data, size - ahead, arena, table, used, error));
    CHECK(used == f.preamble.size());
    check_texels(table, f.texels);
    CHECK(arena.top_mark() == static_cast<std::size_t>(upload - mem.data()) - lead);  // taken just below
    CHECK(table.items[0].rgb == upload - lead);  // the header ahead is overwritten too
    CHECK(arena.used() == bottom);  // nothing from the bottom end
    CHECK(std::memcmp(data + used, text.data(), text.size()) == 0);  // the text is untouched
  }
}

TEST_CASE("texture preamble: an upload that is not the top block is decoded into the arena", "[textures]") {
  Fixture f;
  std::vector<std::uint8_t> mem(1 << 20);
  minrt::Arena arena(mem.data(), mem.size());
  textures::Table table{};
  minrt::Diagnostic error;
  std::size_t used = 0;
  REQUIRE(textures::unpack(f.data(), f.preamble.size(), arena, table, used, error));
  check_texels(table, f.texels);
  CHECK(arena.used() >= f.texels[0].size() + f.texels[1].size());
  // Without room for the texels: one line, no crash.
  std::vector<std::uint8_t> small(4000);
  minrt::Arena tight(small.data(), small.size());
  textures::Table t2{};
  minrt::Diagnostic e2;
  CHECK_FALSE(textures::unpack(f.data(), f.preamble.size(), tight, t2, used, e2));
  CHECK(std::string(e2.message, e2.length).find("do not fit in the board's memory") != std::string::npos);
}

TEST_CASE("texture preamble: damage and cuts are refused with the texture's name", "[textures]") {
  Fixture f;
  // Offsets: marker, count, lead (4), then a.png's name length, name, size,
  // compressed size, CRC-32, stream.
  const std::size_t a_crc = 6 + 1 + 5 + 4 + 4;
  const std::size_t a_stream = a_crc + 4;
  const std::uint32_t a_size = le32(f.data() + a_crc - 4);
  std::string crc = f.preamble;
  crc[a_crc] ^= 1;
  CHECK(hs_test::unpack_textures_error(crc) == "texture a.png: texels damaged (CRC-32 mismatch)");
  int named = 0;
  for (std::uint32_t i = 0; i < a_size; ++i) {
    std::string bad = f.preamble;
    bad[a_stream + i] ^= 0x21;
    const std::string e = hs_test::unpack_textures_error(bad);
    INFO("byte " << i << ": " << e);
    CHECK(!e.empty());
    if (e.rfind("texture a.png: ", 0) == 0) ++named;
  }
  CHECK(named == static_cast<int>(a_size));
  for (std::size_t n = 0; n < f.preamble.size(); ++n) {
    INFO("cut at " << n);
    CHECK(!hs_test::unpack_textures_error(f.preamble.substr(0, n)).empty());
    minrt::MemorySource line{f.data() + 1, n == 0 ? 0 : n - 1};
    std::vector<std::uint8_t> mem(1 << 20);
    minrt::Arena arena(mem.data(), mem.size());
    textures::Table table{};
    minrt::Diagnostic error;
    CHECK_FALSE(textures::receive_compressed(line.source(), arena, table, error));
  }
}

TEST_CASE("texture preamble: the texture that takes the decoded size over the board's limit is named", "[textures]") {
  Fixture f;
  const std::size_t a = f.texels[0].size();
  std::string out, error;
  CHECK_FALSE(build_texture_preamble(f.scene, "s.txt", f.dir.path + "/", a + 10, out, error));
  CHECK(error == "s.txt:4:9: error: texture b.png (5x300) takes the textures to " + std::to_string(a + 4500) +
                     " bytes decoded, over the " + std::to_string(a + 10) +
                     " bytes the board has for them (firmware-sim: --sim-ram-size to give the simulated board more)");
  CHECK(out.empty());
  CHECK(build_texture_preamble(f.scene, "s.txt", f.dir.path + "/", a + 4500, out, error));
}

TEST_CASE("texel filter: residuals of any texels undo exactly, grey ones leave two planes zero", "[textures]") {
  const std::size_t w = 13, h = 7;
  Bytes rgb(w * h * 3), grey(w * h * 3);
  std::uint32_t x = 9;
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>((x = x * 69069u + 1u) >> 24);
  for (std::size_t i = 0; i < w * h; ++i) grey[3 * i] = grey[3 * i + 1] = grey[3 * i + 2] = static_cast<std::uint8_t>(i * 3);
  for (const Bytes* src : {&rgb, &grey}) {
    Bytes res(src->size()), scratch(3 * w);
    texel_filter::filter(src->data(), w, h, res.data());
    if (src == &grey)
      for (std::size_t y = 0; y < h; ++y)
        for (std::size_t i = w; i < 3 * w; ++i) CHECK(res[y * 3 * w + i] == 0);
    texel_filter::unfilter(res.data(), w, h, scratch.data());
    CHECK(res == *src);
  }
}

TEST_CASE("textured scene through host-send and the firmware: compressed on every protocol, the host float model's image",
          "[e2e][firmware][textures]") {
  HS_NEEDS_FIRMWARE();
  hs_test::TempDir dir;
  write_texture(dir.file("a.png"), 61, 37, 1, 5, 7, 29);
  write_texture(dir.file("b.png"), 5, 300, 2, 5, 7, 29);
  const std::string scene = dir.file("tex.txt");
  {
    std::FILE* f = std::fopen(scene.c_str(), "w");
    REQUIRE(f != nullptr);
    std::fputs("png 24 16 out.png\nsun 1 1 1\ntexture a.png\nsphere -0.5 0 -2 0.6\ntexture b.png\n"
               "sphere 0.6 0 -2 0.5\ntexture none\nsphere 0 -0.6 -2 0.2\n", f);
    std::fclose(f);
  }
  // Checked raw, course (both byte orders) and framed: decoded in place.
  hs_test::check_png_on_every_protocol(dir, scene, {});
  // Unchecked raw: inflated from the line as it arrives.
  const std::string streamed = dir.file("streamed.png");
  const hs_test::RunResult r = hs_test::send_sim(scene, streamed, {"--no-check"});
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(hs_test::read_file(streamed) == hs_test::read_file(dir.file("raw.png")));
}
