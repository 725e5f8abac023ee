// The CS418 reader: what it builds from each keyword, and a located error for
// each malformed line (SPEC.md 1.2).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "core/math/math_libm.hpp"
#include "formats/cs418/cs418_reader.hpp"

namespace {

struct Parsed {
  minrt::cs418::ReadStatus status;
  minrt::Diagnostic error;
  minrt::cs418::Header header;
  minrt::model::Scene<double> scene;
  std::vector<std::string> warnings;
  std::vector<unsigned char> storage = std::vector<unsigned char>(1 << 20);
};

void keep_warning(void* ctx, const minrt::Diagnostic& d) {
  static_cast<std::vector<std::string>*>(ctx)->push_back(std::to_string(d.pos.line) + ":" +
                                                          std::to_string(d.pos.col) + ": " + d.message);
}

int32_t fake_texture(void*, const char* name, minrt::Diagnostic& error) {
  if (std::string(name) == "earth.png") return 0;
  error.text("texture ").text(name).text(": No such file or directory");
  return -1;
}

std::unique_ptr<Parsed> parse(const std::string& text) {
  auto p = std::make_unique<Parsed>();
  minrt::Arena arena(p->storage.data(), p->storage.size());
  minrt::model::SceneBuilder<double> builder(arena);
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::cs418::Reader<minrt::LibmDouble> reader(mem.source(), builder, {&fake_texture, nullptr},
                                                 {&keep_warning, &p->warnings});
  p->status = reader.read(p->header, p->scene, p->error);
  if (p->status == minrt::cs418::ReadStatus::kOk) REQUIRE(builder.finish(p->scene));
  return p;
}

std::string where(const Parsed& p) {
  return std::to_string(p.error.pos.line) + ":" + std::to_string(p.error.pos.col) + ": " + p.error.message;
}

}  // namespace

TEST_CASE("cs418 reader: keywords build the scene", "[cs418][reader]") {
  const auto p = parse(
      "png 20 10 out.png\n"
      "\n"
      "color 1 0.5 0\n"
      "shininess 0.1 0.2 0.3\n"
      "sphere 1 2 3 4\n"
      "sun 0 0 1\n"
      "bulb 1 1 1\n"
      "plane 0 2 0 -4\n"
      "texcoord 0.25 0.75\n"
      "xyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n"
      "tri 1 -2 3\n"
      "texture earth.png\n"
      "tri -1 -2 -3\n"
      "bounces 7\naa 3\ngi 2\nexpose 1.5\ndof 4 0.1\nfisheye\n");
  REQUIRE(p->status == minrt::cs418::ReadStatus::kOk);
  const auto& s = p->scene;
  CHECK(p->header.width == 20);
  CHECK(p->header.height == 10);
  CHECK(std::string(p->header.output_name) == "out.png");
  REQUIRE(s.sphere_count == 1);
  CHECK(s.spheres[0].radius == 4.0);
  const auto& m = s.materials[s.spheres[0].material];
  CHECK(m.color.y == 0.5);
  CHECK(m.shininess.z == 0.3);
  REQUIRE(s.light_count == 2);
  CHECK(s.lights[0].kind == minrt::model::LightKind::kSun);
  CHECK(s.lights[1].kind == minrt::model::LightKind::kBulb);
  CHECK(s.lights[1].color.y == 0.5);  // lights capture the current colour
  REQUIRE(s.plane_count == 1);
  CHECK(s.planes[0].point.y == 2.0);  // -D (A,B,C) / |(A,B,C)|^2
  REQUIRE(s.triangle_count == 2);
  CHECK(s.triangles[0].u[0] == 0.25);
  CHECK(s.triangles[0].p1.x == 1.0);  // -2 of 3 vertices is the second
  CHECK(s.materials[s.triangles[1].material].texture == 0);
  CHECK(s.triangles[1].order > s.triangles[0].order);
  CHECK(s.bounces == 7);
  CHECK(s.samples == 3);
  CHECK(s.gi_depth == 2);
  CHECK(s.exposure);
  CHECK(s.camera.depth_of_field);
  CHECK(s.camera.projection == minrt::model::Projection::kFisheye);
}

TEST_CASE("cs418 reader: trif is a flat triangle and trit a textured one", "[cs418][reader]") {
  const std::string verts = "png 4 4 o.png\ncolor 0.25 0.5 1\ntexcoord 0.5 1\nxyz 0 0 0\nxyz 1 0 0\nxyz 0 1 0\n";
  const auto tri = parse(verts + "tri 1 -2 3\n");
  const auto trif = parse(verts + "texture earth.png\ntrif 1 -2 3\ntrit 1 -2 3\nsphere 0 0 -1 0.5\n");
  REQUIRE(tri->status == minrt::cs418::ReadStatus::kOk);
  REQUIRE(trif->status == minrt::cs418::ReadStatus::kOk);
  REQUIRE(trif->scene.triangle_count == 2);
  const auto& a = tri->scene.triangles[0];
  for (uint32_t k = 0; k < 2; ++k) {
    const auto& b = trif->scene.triangles[k];
    CHECK(b.p0.x == a.p0.x);
    CHECK(b.p1.x == a.p1.x);  // -2 of 3 vertices is the second, as for tri
    CHECK(b.p2.y == a.p2.y);
    CHECK(b.u[0] == a.u[0]);
  }
  const auto& s = trif->scene;
  const auto& flat = s.materials[s.triangles[0].material];
  CHECK(flat.texture == minrt::model::kNoTexture);  // the current colour, not the texture
  CHECK(flat.color.y == 0.5);
  CHECK(s.materials[s.triangles[1].material].texture == 0);
  REQUIRE(s.sphere_count == 1);
  CHECK(s.materials[s.spheres[0].material].texture == 0);  // the state keeps its texture
  CHECK(trif->warnings.empty());
}

TEST_CASE("cs418 reader: trif and trit lines give tri's errors under their own names", "[cs418][reader][errors]") {
  const auto few = parse("png 4 4 o.png\nxyz 0 0 0\ntrif 1 1\n");
  REQUIRE(few->status == minrt::cs418::ReadStatus::kSceneError);
  CHECK(where(*few).find("trif I1 I2 I3") != std::string::npos);
  const auto past = parse("png 4 4 o.png\nxyz 0 0 0\ntrit 1 1 -2\n");
  REQUIRE(past->status == minrt::cs418::ReadStatus::kSceneError);
  CHECK(where(*past) == "3:10: vertex -2 is not defined (1 vertex so far)");
}

TEST_CASE("cs418 reader: up and forward act in file order on the current basis", "[cs418][reader]") {
  const auto p = parse("png 4 4 o.png\nforward 0 0 -2\nup 1 1 0\n");
  REQUIRE(p->status == minrt::cs418::ReadStatus::kOk);
  const auto& c = p->scene.camera;
  CHECK(c.forward.z == -2.0);
  CHECK(c.right.x == Approx(std::sqrt(0.5)));
  CHECK(c.right.y == Approx(-std::sqrt(0.5)));
  CHECK(c.up.x == Approx(std::sqrt(0.5)));
  CHECK(c.up.y == Approx(std::sqrt(0.5)));
}

TEST_CASE("cs418 reader: unknown keywords are skipped with a warning", "[cs418][reader]") {
  const auto p = parse("png 4 4 o.png\nwibble 1 2\nsphere 0 0 -1 0.5\n");
  REQUIRE(p->status == minrt::cs418::ReadStatus::kOk);
  REQUIRE(p->warnings.size() == 1);
  CHECK(p->warnings[0] == "2:1: unknown keyword 'wibble' skipped");
  CHECK(p->scene.sphere_count == 1);
}

TEST_CASE("cs418 reader: malformed lines give located errors", "[cs418][reader][errors]") {
  struct Case {
    const char* text;
    const char* expected;
  };
  const Case cases[] = {
      {"", "0:0: empty scene: no 'png WIDTH HEIGHT FILE.png' line"},
      {"sphere 0 0 0 1\n", "1:1: the first line must be 'png WIDTH HEIGHT FILE.png'"},
      {"png 10 x o.png\n", "1:8: image height must be an integer, got 'x'"},
      {"png 0 10 o.png\n", "1:5: image width must be in 1..4096, got 0"},
      {"png 100000 10 o.png\n", "1:5: image width must be in 1..4096, got 100000"},
      {"png 10 10\n", "1:8: expected 'png WIDTH HEIGHT FILE.png', got 2 fields"},
      {"png 1 1 o.png\nsphere 1 2 abc 4\n", "2:12: not a number: 'abc'"},
      {"png 1 1 o.png\nsphere 1 2 3\n", "2:12: expected 'sphere X Y Z R', got 3 fields"},
      {"png 1 1 o.png\ncolor 1 1 1e999\n", "2:11: number out of range: '1e999'"},
      {"png 1 1 o.png\nxyz 0 0 0\nxyz 1 0 0\ntri 1 2 3\n", "4:9: vertex 3 is not defined (2 vertices so far)"},
      {"png 1 1 o.png\nxyz 0 0 0\ntri 1 1 -2\n", "3:9: vertex -2 is not defined (1 vertex so far)"},
      {"png 1 1 o.png\nxyz 0 0 0\ntri 0 1 1\n", "3:5: vertex 0 is not defined (1 vertex so far)"},
      {"png 1 1 o.png\ntexture moon.png\n", "2:9: texture moon.png: No such file or directory"},
      {"png 1 1 o.png\nbounces -1\n", "2:9: bounces must be at least 0, got -1"},
      {"png 1 1 o.png\naa 0\n", "2:4: aa samples must be at least 1, got 0"},
      {"png 1 1 o.png\naa 3000000000\n", "2:4: aa samples must be at most 2147483647, got 3000000000"},
      {"png 1 1 o.png\nplane 0 0 0 1\n", "2:7: plane normal (A, B, C) is zero"},
      {"png 1 1 o.png\nup 0 0 0\n", "2:4: zero vector"},
      {"png 1 1 o.png\nior 0\n", "2:5: ior must be positive"},
      {"png 1 1 o.png\nshininess\n", "2:1: expected 'shininess S | shininess R G B', got 0 fields"},
      {"png 1 1 o.png\npng 1 1 o.png\n", "2:1: a second 'png' line"},
      {"png 1 1 o.png\nsph\x00re\n", "2:4: NUL byte in the scene (not a text file?)"},
  };
  for (const Case& c : cases) {
    std::string text(c.text);
    if (std::string(c.expected).find("NUL") != std::string::npos) text = std::string("png 1 1 o.png\nsph\0re\n", 21);
    const auto p = parse(text);
    INFO(c.text);
    CHECK(p->status == minrt::cs418::ReadStatus::kSceneError);
    const std::string got = p->error.has_pos ? where(*p) : "0:0: " + std::string(p->error.message);
    CHECK(got == c.expected);
  }
}

TEST_CASE("cs418 reader: a line longer than the bound is an error, not a truncation", "[cs418][reader][errors]") {
  const auto p = parse("png 1 1 o.png\ncolor 1 1 " + std::string(5000, '1') + "\n");
  CHECK(p->status == minrt::cs418::ReadStatus::kSceneError);
  CHECK(where(*p) == "2:4097: line longer than 4096 bytes");
}
