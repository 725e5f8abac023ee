// The miniRT reader on its own: boundary values the subject allows, the
// lexical freedoms of the shared scenes (CRLF, tabs, trailing blanks, no
// final newline, any order), normalised orientations, the base-centre
// cylinder, and the exactness of the range checks in float and double.
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
std::unique_ptr<Parsed<M>> parse(const std::string& text) {
  auto p = std::make_unique<Parsed<M>>();
  minrt::Arena arena(p->storage.data(), p->storage.size());
  minrt::model::SceneBuilder<typename M::real> builder(arena);
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::minirt::Reader<M> reader(mem.source(), builder, minrt::minirt::TextureResolver{&no_texture, nullptr});
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
  for (const std::string& text : {
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
  // The cylinder's point is its base centre: it spans y = 0 .. 4.
  CHECK(s.solids[0].base.y == 0.0);
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
