// The miniRT reader on its own: boundary values the subject allows, the
// lexical freedoms of the shared scenes (CRLF, tabs, trailing blanks, no
// final newline, any order), normalised orientations, the cylinder's
// centre, the exactness of the range checks in float and double, and what
// --mandatory accepts and refuses.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/minirt/minirt_reader.hpp"

namespace {

template <class M>
struct Parsed {
  using R = typename M::real;
  std::vector<unsigned char> storage = std::vector<unsigned char>(1 << 20);
  minrt::model::Scene<R> scene;
  minrt::minirt::View<R> view;
  bool ok = false;
  std::string error;  // "LINE: message" or the message
};

int32_t no_texture(void*, const char*, minrt::Diagnostic& d) {
  d.text("no textures in this test");
  return -1;
}

template <class M = minrt::LibmDouble>
std::unique_ptr<Parsed<M>> parse(const std::string& text, minrt::minirt::ReaderOptions options = {}) {
  auto p = std::make_unique<Parsed<M>>();
  minrt::Arena arena(p->storage.data(), p->storage.size());
  minrt::model::SceneBuilder<typename M::real> builder(arena);
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::minirt::Reader<M> reader(mem.source(), builder, minrt::minirt::TextureResolver{&no_texture, nullptr},
                                   options);
  minrt::Diagnostic d;
  p->ok = reader.read(p->scene, p->view, d) == minrt::minirt::ReadStatus::kOk && builder.finish(p->scene);
  if (!p->ok) p->error = (d.has_pos ? std::to_string(d.pos.line) + ": " : std::string()) + d.message;
  return p;
}

const std::string kA = "A 0.2 255,255,255\n";
const std::string kC = "C 0,0,10 0,0,-1 70\n";
const std::string kL = "L 0,5,5 0.8 255,255,255\n";
const std::string kSp = "sp 0,0,0 2 255,0,0\n";

}  // namespace

TEST_CASE("miniRT reader: the subject's boundary values are accepted", "[minirt][reader]") {
  for (const char* text : {
           "A 0 0,0,0\nC 0,0,0 -1,-1,-1 0\nL 0,0,0 0 0,0,0\nsp 0,0,0 1 0,0,0\n",
           "A 1 255,255,255\nC 0,0,0 1,1,1 180\nL 0,0,0 1 255,255,255\nsp 0,0,0 1 255,255,255\n",
           "A 1.0 +255,0,0\nC 0,0,0 0,0,1.000 180.0\nL 0,0,0 1.0 0,0,0\nsp 0,0,0 0.0001 0,0,0\n",
           "A -0 0,0,0\nC -0.0,+0,0 0,-0,1 +90\nL 0,0,0 -0.000 0,0,0\npl 0,0,0 0,-1,0 0,0,0\n",
           "A 000.333 100,100,100\nC 0,0,0 0,0,1 45\nL 0,0,0 0.8 255,255,255\ncy 0,0,0 0,1,0 500.2 5000 0,143,3\n",
       }) {
    INFO(text);
    const auto p = parse(text);
    CHECK(p->ok);
    CHECK(p->error.empty());
  }
}

TEST_CASE("miniRT reader: CRLF, tabs, blanks, no final newline, any order, several lights", "[minirt][reader]") {
  const auto crlf = parse("A 0.2 255,255,255\r\n\r\nC 0,0,10 0,0,-1 70\r\nL 0,5,5 0.8 255,255,255\r\nsp 0,0,0 2 255,0,0\r\n");
  CHECK(crlf->ok);
  const auto tabs = parse("\tA\t0.2   255,255,255   \n  C 0,0,10\t0,0,-1 70 \n\n\n L 0,5,5 0.8 255,255,255\nsp 0,0,0 2 255,0,0");
  CHECK(tabs->ok);
  const auto order = parse(kSp + kL + kC + kL + kA + kL);
  REQUIRE(order->ok);
  CHECK(order->scene.light_count == 3);
  CHECK(order->scene.sphere_count == 1);
}

TEST_CASE("miniRT reader: values land in the model as SPEC.md 2.3 says", "[minirt][reader]") {
  const auto p = parse("A 0.5 255,51,0\nC 1,2,3 0,0,-0.5 70\nL 0,5,5 0.5 255,255,0\nsp 0,0,0 4 255,0,0\n"
                       "cy 5,0,-3 0,0.5,0 2 4 0,255,0\npl 0,-1,0 0,0.5,0 1,2,3\nco 0,0,0 0,1.1,0 45 3 1,1,1\n");
  INFO(p->error);
  REQUIRE(p->ok);
  const auto& s = p->scene;
  CHECK(s.finish == minrt::model::Finish::kMinirt);
  CHECK(s.ambient.x == Approx(0.5));
  CHECK(s.ambient.y == Approx(0.1));
  CHECK(s.ambient.z == 0.0);
  CHECK(p->view.position.z == 3.0);
  CHECK(p->view.direction.z == -1.0);  // normalised after the range check
  CHECK(p->view.fov_degrees == 70.0);
  REQUIRE(s.light_count == 1);
  CHECK(s.lights[0].kind == minrt::model::LightKind::kPoint);
  CHECK(s.lights[0].color.x == Approx(0.5));
  CHECK(s.lights[0].color.z == 0.0);
  REQUIRE(s.sphere_count == 1);
  CHECK(s.spheres[0].radius == 2.0);  // diameter 4
  REQUIRE(s.solid_count == 2);
  // The cylinder's point is its centre: it spans y = -2 .. 2.
  CHECK(s.solids[0].base.y == -2.0);
  CHECK(s.solids[0].axis.y == 1.0);
  CHECK(s.solids[0].height == 4.0);
  CHECK(s.solids[0].radius == 1.0);
  CHECK(s.solids[0].slope == 0.0);
  // The cone: radius at the base h * tan(angle), shrinking to the tip.
  CHECK(s.solids[1].radius == Approx(3.0));
  CHECK(s.solids[1].slope == Approx(-1.0));
  CHECK(s.solids[1].axis.y == 1.0);  // 0,1.1,0 is not range-checked, and normalised
  REQUIRE(s.plane_count == 1);
  CHECK(s.planes[0].normal.y == 1.0);
  CHECK(s.planes[0].point.y == -1.0);
  CHECK(s.materials[s.planes[0].material].color.z == Approx(3.0 / 255));
}

TEST_CASE("miniRT reader: range checks are exact on the text, the same in float and double", "[minirt][reader]") {
  // 1.00000001 rounds to 1 in float, yet it is above 1: both builds refuse it.
  for (const char* ratio : {"1.00000001", "1.000000000000000000001", "-0.000000000000000000001"}) {
    const std::string text = std::string("A ") + ratio + " 255,255,255\n" + kC + kL + kSp;
    const auto d = parse<minrt::LibmDouble>(text);
    const auto f = parse<minrt::PortableFloat>(text);
    CHECK_FALSE(d->ok);
    CHECK_FALSE(f->ok);
    CHECK(d->error == f->error);
    CHECK(d->error.find("is outside [0,1]") != std::string::npos);
  }
  const std::string exact = "A 1.000000000000000000000 255,255,255\n" + kC + kL + kSp;
  CHECK(parse<minrt::LibmDouble>(exact)->ok);
  CHECK(parse<minrt::PortableFloat>(exact)->ok);
}

TEST_CASE("miniRT reader: the first error in file order wins, then the missing elements", "[minirt][reader]") {
  const auto p = parse("A 2.0 300,255,255\nC 0,3,10 0,-0.1,-1 200\n");
  CHECK(p->error == "1: ambient light ratio \"2.0\" is outside [0,1]");
  const auto order = parse("sp 0,0,0 2 255,0,0\n");
  CHECK(order->error.rfind("no ambient light", 0) == 0);
  const auto objects = parse(kA + kC + kL);
  CHECK(objects->error.rfind("no object", 0) == 0);
  // Messages quote what was found, escaping bytes a terminal would show badly.
  const auto bytes = parse(kA + kC + kL + "sp 0,0,0 2\x1b[31m 255,0,0\n");
  CHECK(bytes->error == "4: sphere diameter \"2\\x1b[31m\" is not a number");
}

TEST_CASE("miniRT reader: --cylinder-base makes the point the base centre", "[minirt][reader]") {
  minrt::minirt::ReaderOptions base;
  base.cylinder_point = minrt::minirt::CylinderPoint::kBase;
  const std::string text = kA + kC + kL + "cy 1,2,3 0,0,-1 2 4 255,255,255\nco 1,2,3 0,1,0 45 3 1,1,1\n";
  const auto centre = parse(text);
  const auto based = parse(text, base);
  REQUIRE(centre->ok);
  REQUIRE(based->ok);
  CHECK(centre->scene.solids[0].base.z == 5.0);  // 3 + 4/2 against the axis 0,0,-1
  CHECK(based->scene.solids[0].base.z == 3.0);
  // The cone's point is its base centre either way (SPEC.md 2.1).
  CHECK(centre->scene.solids[1].base.y == 2.0);
  CHECK(based->scene.solids[1].base.y == 2.0);
}

namespace {

minrt::minirt::ReaderOptions mandatory() {
  minrt::minirt::ReaderOptions o;
  o.mandatory = true;
  return o;
}

}  // namespace

TEST_CASE("miniRT reader --mandatory: what the subject allows is accepted", "[minirt][reader][mandatory]") {
  struct Case {
    const char* why;
    std::string text;
  };
  for (const Case& c : {
           Case{"A, C, L, sp, pl, cy once each", kA + kC + kL + kSp + "pl 0,0,0 0,1,0 1,2,3\ncy 0,0,0 0,1,0 1 2 3,4,5\n"},
           Case{"L without its colour (unused in the mandatory part)", kA + kC + "L 0,5,5 0.8\n" + kSp},
           Case{"no light: A, C and L are bounded to one, not required", kA + kC + kSp},
           Case{"no ambient light", kC + kL + kSp},
           Case{"no object: the subject asks for none", kA + kC + kL},
           Case{"only a camera", kC},
       }) {
    INFO(c.why);
    const auto p = parse(c.text, mandatory());
    INFO(p->error);
    CHECK(p->ok);
  }
  // The light is white at its brightness whatever colour is written, and
  // there is no specular term.
  const auto p = parse(kA + kC + "L 0,5,5 0.5 255,0,0\n" + kSp, mandatory());
  REQUIRE(p->ok);
  CHECK(p->scene.lights[0].color.y == 0.5);
  CHECK(p->scene.lights[0].color.z == 0.5);
  CHECK_FALSE(p->scene.specular);
  CHECK(parse(kA + kC + kL + kSp)->scene.specular);
}

TEST_CASE("miniRT reader --mandatory: what the subject forbids is refused, located", "[minirt][reader][mandatory]") {
  struct Case {
    std::string text, error;
  };
  const std::string head = kA + kC + kL;
  for (const Case& c : {
           Case{head + "co 0,0,0 0,1,0 30 2 1,1,1\n",
                "4: cone 'co' is a bonus element: the mandatory part has A, C, L, sp, pl and cy only"},
           Case{head + "plc 0,0,0 0,1,0 1,1,1\n",
                "4: checkered plane 'plc' is a bonus element: the mandatory part has A, C, L, sp, pl and cy only"},
           Case{head + "spt 0,0,0 1 1,1,1 earth.ppm\n",
                "4: textured sphere 'spt' is a bonus element: the mandatory part has A, C, L, sp, pl and cy only"},
           Case{head + "L 1,1,1 0.5 255,255,255\n",
                "4: second light 'L': the first is on line 3 and there may be only one"},
           Case{head + "A 0.1 1,1,1\n", "4: second ambient light 'A': the first is on line 1 and there may be only one"},
           Case{kA + kC + "L 0,5,5 0.8 300,0,0\n", "3: light colour \"300,0,0\": red \"300\" is outside [0,255]"},
           Case{kA + kC + "L 0,5,5\n", "3: light has too few fields: expected 'L X,Y,Z BRIGHTNESS [R,G,B]', got 1 field"},
           Case{kA + kC + "L 0,5,5 0.8 1,1,1 x\n",
                "3: light has too many fields: expected 'L X,Y,Z BRIGHTNESS [R,G,B]', got 4 fields"},
           Case{kA + kL + kSp, "no camera: the scene needs one 'C X,Y,Z NX,NY,NZ FOV' line"},
           Case{"", "the scene is empty: it needs at least a camera 'C X,Y,Z NX,NY,NZ FOV'"},
           Case{head + "tr 0,0,0 1,1,1 2,2,2 1,1,1\n", "4: unknown element \"tr\" (expected A, C, L, sp, pl or cy)"},
       }) {
    INFO(c.text);
    const auto p = parse(c.text, mandatory());
    CHECK_FALSE(p->ok);
    CHECK(p->error == c.error);
  }
}
