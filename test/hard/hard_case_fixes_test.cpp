// What the hard cases (test/hard/scenes) found, each pinned where it was
// caused, in double and in the board's float.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <tuple>
#include <string>
#include <vector>

#include "core/base/arena.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "core/base/byte_io.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "format_sides/host_formats.hpp"
#include "render/general/quadric_shape.hpp"

namespace {

using namespace minrt;

// An axis-aligned ellipsoid with semi-axes (1, thin, 1) at the origin, as
// EASTRAY's kind 3 is in its local frame: x^2 + y^2/thin^2 + z^2 - 1 < 0.
template <class R>
model::Quadric<R> thin_ellipsoid(R thin) {
  model::Quadric<R> s{};
  s.shape = model::QuadricShape::kQuadric;
  s.q[0] = R(1), s.q[1] = R(1) / (thin * thin), s.q[2] = R(1), s.q[9] = R(-1);
  return s;
}

template <class M>
int crossings_of(const model::Quadric<typename M::real>& s, Vec3<typename M::real> o, Vec3<typename M::real> d) {
  general::Crossing<typename M::real> out[4];
  return general::crossings<M>(s, o, d, typename M::real(0), typename M::real(1e30), out);
}

template <class M>
void check_thin_ellipsoid(typename M::real thin) {
  using R = typename M::real;
  const auto s = thin_ellipsoid<R>(thin);
  // Through the disc's plane outside its rim (x = 3 at y = 0): no crossing,
  // at any slope. The discriminant b^2 - 4ac of these rays cancels terms of
  // 1/thin^2 times the origin's size squared; only a form without that
  // cancellation says "miss".
  for (const R slope : {R(0.001), R(0.1), R(0.7), R(3)}) {
    INFO("slope " << slope);
    CHECK(crossings_of<M>(s, Vec3<R>{R(3) - R(2) * slope, R(2), R(0.5)}, Vec3<R>{slope, R(-1), R(0)}) == 0);
    CHECK(crossings_of<M>(s, Vec3<R>{R(-5), R(2) * slope, R(2)}, Vec3<R>{R(1), -slope, R(0)}) == 0);
  }
  // Through its middle: two crossings, about thin apart along y.
  general::Crossing<R> out[4];
  REQUIRE(general::crossings<M>(s, Vec3<R>{R(0.2), R(2), R(0.1)}, Vec3<R>{R(0), R(-1), R(0)}, R(0), R(1e30), out) == 2);
  CHECK(out[0].t == Approx(2 - thin * 0.97468).epsilon(1e-3));
  CHECK(out[1].t == Approx(2 + thin * 0.97468).epsilon(1e-3));
}

// The world-to-local map of the only object of an EASTRAY scene's main obj,
// or false with the reader's message.
template <class M>
bool eastray_object(const std::string& object, model::Affine<typename M::real>& to_local, std::string& error) {
  using R = typename M::real;
  const std::string text = "display 8 8  0 0 7 7  1 1  1 ;\ncamera 0 0 9  0 0 0  0 9 0  25 0 ;\n"
                           "color [ grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\nobj [ " + object + " ]\n";
  const auto caps = eastray::Scene<R>::Capacities::for_text(text.size());
  const size_t bytes = eastray::Scene<R>::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() + 4096;
  std::vector<unsigned char> storage(bytes);
  Arena arena(storage.data(), bytes);
  eastray::Scene<R> scene;
  REQUIRE(scene.allocate(arena, caps));
  auto reader = std::make_unique<eastray::Reader<M>>(text.data(), text.size(), scene, arena);
  Diagnostic d;
  if (!reader->read(d)) {
    error = d.message;
    return false;
  }
  REQUIRE(scene.primitive_count == 1);
  to_local = scene.primitives[0].to_local;
  return true;
}

// An axis given by a vector whose squared length under- or overflows the
// real type still names its direction: the local z axis is that direction.
template <class M>
void check_axis(const char* axis, double x, double y, double z) {
  using R = typename M::real;
  model::Affine<R> to_local;
  std::string error;
  INFO(axis << ": " << error);
  REQUIRE(eastray_object<M>(std::string("5 grey 1  0 0 0  ") + axis + "  0.5 ;", to_local, error));
  const Vec3<R> w = to_local.transposed(Vec3<R>{R(0), R(0), R(1)});  // local z in the world
  CHECK(static_cast<double>(w.x) == Approx(x).margin(1e-6));
  CHECK(static_cast<double>(w.y) == Approx(y).margin(1e-6));
  CHECK(static_cast<double>(w.z) == Approx(z).margin(1e-6));
}

// The plane Ax + By + Cz + D = 0 as the builder stores it: a point on it
// and a normal along (A, B, C).
template <class R>
model::Plane<R> built_plane(Vec3<R> abc, R d) {
  std::vector<unsigned char> storage(1 << 16);
  Arena arena(storage.data(), storage.size());
  model::SceneBuilder<R> builder(arena);
  REQUIRE(builder.add_plane(abc, d));
  model::Scene<R> scene;
  REQUIRE(builder.finish(scene));
  REQUIRE(scene.plane_count == 1);
  return scene.planes[0];
}

template <class R>
void check_plane(Vec3<R> abc, R d, Vec3<R> point, Vec3<R> unit_normal) {
  const model::Plane<R> p = built_plane(abc, d);
  INFO(abc.x << " " << abc.y << " " << abc.z << " " << d);
  CHECK(p.point.x == Approx(point.x).margin(1e-6));
  CHECK(p.point.y == Approx(point.y).margin(1e-6));
  CHECK(p.point.z == Approx(point.z).margin(1e-6));
  const R len = std::sqrt(dot(p.normal, p.normal));
  REQUIRE(len > R(0));
  CHECK(p.normal.x / len == Approx(unit_normal.x).margin(1e-6));
  CHECK(p.normal.y / len == Approx(unit_normal.y).margin(1e-6));
  CHECK(p.normal.z / len == Approx(unit_normal.z).margin(1e-6));
}

// The unit normal Jaworski's float reader keeps for `plane 0 0 5 NORMAL`.
template <class M>
Vec3<typename M::real> jaworski_plane_normal(const std::string& normal) {
  using R = typename M::real;
  const std::string text = "imWidth 4 imHeight 4 canvWidth 4 canvHeight 4 depth 4\nlights\nobjects\nplane 0 0 5 " +
                           normal + " diffusive 1 1 1\n";
  std::vector<unsigned char> storage(1 << 16);
  Arena arena(storage.data(), storage.size());
  jaworski::Scene<R> scene;
  REQUIRE(scene.allocate(arena, 4));
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  jaworski::Reader<M> reader(mem.source(), scene);
  Diagnostic d;
  INFO(d.message);
  REQUIRE(reader.read(d));
  REQUIRE(scene.object_count == 1);
  return scene.objects[0].normal;
}

// The scene a CS418 text sets up, in M's precision.
template <class M>
model::Scene<typename M::real> cs418_scene(const std::string& text, std::vector<unsigned char>& storage) {
  using R = typename M::real;
  storage.assign(1 << 16, 0);
  Arena arena(storage.data(), storage.size());
  model::SceneBuilder<R> builder(arena);
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  cs418::Reader<M> reader(mem.source(), builder, cs418::TextureResolver{}, WarningSink{});
  cs418::Header header;
  model::Scene<R> scene;
  Diagnostic d;
  INFO(d.message);
  REQUIRE(reader.read(header, scene, d) == cs418::ReadStatus::kOk);
  REQUIRE(builder.finish(scene));
  return scene;
}

template <class M>
model::Camera<typename M::real> cs418_camera(const std::string& text) {
  std::vector<unsigned char> storage;
  return cs418_scene<M>(text, storage).camera;
}

template <class R>
void check_unit(const Vec3<R>& v, double x, double y, double z) {
  CHECK(static_cast<double>(v.x) == Approx(x).margin(1e-6));
  CHECK(static_cast<double>(v.y) == Approx(y).margin(1e-6));
  CHECK(static_cast<double>(v.z) == Approx(z).margin(1e-6));
}

}  // namespace

TEST_CASE("CS418: a forward or up too short or long to square still gives a camera", "[hard][cs418]") {
  auto check = [](auto policy) {
    using M = decltype(policy);
    // forward 1e-30 long (a very wide view), then up along it (kept right).
    auto c = cs418_camera<M>("png 8 8 x.png\nforward 0 0 -1e-30\nup 0 0 -1\n");
    check_unit(c.right, 1, 0, 0);
    check_unit(c.up, 0, 1, 0);
    c = cs418_camera<M>("png 8 8 x.png\nup 0 1e-30 1e-30\n");
    check_unit(c.right, 1, 0, 0);
    check_unit(c.up, 0, 1, 0);
    c = cs418_camera<M>("png 8 8 x.png\nforward 3e38 0 0\n");
    check_unit(c.right, 0, 0, 1);
    check_unit(c.up, 0, 1, 0);
  };
  check(LibmDouble{});
  check(PortableFloat{});
}

TEST_CASE("CS418: a sun direction too short or long to square still lights", "[hard][cs418]") {
  auto check = [](auto policy) {
    using M = decltype(policy);
    using R = typename M::real;
    std::vector<unsigned char> storage;
    const auto s = cs418_scene<M>("png 8 8 x.png\nsun 1e-30 1e-30 0\nsun 0 0 3e38\nsphere 0 0 -3 1\n", storage);
    REQUIRE(s.light_count == 2);
    const Vec3<R> a = normalize<M>(s.lights[0].vector), b = normalize<M>(s.lights[1].vector);
    check_unit(a, 0.70710678, 0.70710678, 0);
    check_unit(b, 0, 0, 1);
  };
  check(LibmDouble{});
  check(PortableFloat{});
}

// Pixels of a CS418 text rendered by minrt's CS418 side in `v` that are
// lit (any channel above 8).
long cs418_lit_pixels(const std::string& text, host::Variant v) {
  const host::SceneInput in{"scene.txt", "scene.txt", "", text};
  host::DriverOptions o;
  o.variant = v;
  o.threads = 1;
  std::string error;
  auto s = host::host_format(formats::FormatId::kCs418).prepare(in, o, WarningSink{}, error);
  INFO(error);
  REQUIRE(s != nullptr);
  std::vector<uint8_t> row(static_cast<size_t>(s->width) * 4);
  long lit = 0;
  for (int y = 0; y < s->height; ++y) {
    s->render_row(y, row.data());
    for (int x = 0; x < s->width; ++x)
      lit += row[4 * x] > 8 || row[4 * x + 1] > 8 || row[4 * x + 2] > 8;
  }
  return lit;
}

TEST_CASE("CS418: a roughness too large to square perturbs the normal, in float too", "[hard][cs418]") {
  // A rough floor filling the picture under a sun: the perturbed normals
  // point every way, so about half the pixels are lit, in double and in
  // float alike (float's square of the perturbed normal once overflowed to
  // a zero normal and a black floor).
  const std::string text = "png 32 32 x.png\ncolor 1 1 1\nsun 0 1 0\nroughness 1e30\nplane 0 1 0 0.3\n";
  const long pixels = 32 * 16;  // the floor's half of the picture
  const long in_double = cs418_lit_pixels(text, {host::Precision::kDouble, host::ShimSet::kLibm});
  const long in_float = cs418_lit_pixels(text, {host::Precision::kFloat, host::ShimSet::kPortable});
  CHECK(in_double > pixels / 4);
  CHECK(in_float > pixels / 4);
}

TEST_CASE("Jaworski in float: a plane normal too short or long to square keeps its direction",
          "[hard][jaworski]") {
  for (const auto& [text, x, y, z] : {std::tuple{"1e-30 1e-30 0", 0.70710678, 0.70710678, 0.0},
                                      std::tuple{"0 0 -3e38", 0.0, 0.0, -1.0}, std::tuple{"0 2 0", 0.0, 1.0, 0.0}}) {
    INFO(text);
    const Vec3<float> n = jaworski_plane_normal<PortableFloat>(text);
    CHECK(n.x == Approx(x).margin(1e-6));
    CHECK(n.y == Approx(y).margin(1e-6));
    CHECK(n.z == Approx(z).margin(1e-6));
  }
}

TEST_CASE("a plane whose (A, B, C) is too short or long to square lies where its equation says",
          "[hard][cs418][minirt]") {
  check_plane<float>({1e-30f, 0, 0}, 1e-30f, {-1, 0, 0}, {1, 0, 0});
  check_plane<float>({0, 3e38f, 0}, 3e38f, {0, -1, 0}, {0, 1, 0});
  check_plane<float>({0, 0, -2e-25f}, 4e-25f, {0, 0, 2}, {0, 0, -1});
  check_plane<float>({0, 2, 0}, 2, {0, -1, 0}, {0, 1, 0});
  check_plane<double>({1e-30, 0, 0}, 1e-30, {-1, 0, 0}, {1, 0, 0});
  check_plane<double>({0, 3e200, 0}, 3e200, {0, -1, 0}, {0, 1, 0});
}

TEST_CASE("an EASTRAY axis too short or too long to square still gives its direction", "[hard][eastray]") {
  for (int v = 0; v < 2; ++v) {
    auto check = [&](const char* axis, double x, double y, double z) {
      if (v == 0) check_axis<LibmDouble>(axis, x, y, z);
      else check_axis<PortableFloat>(axis, x, y, z);
    };
    check("1e-30 0 0", 1, 0, 0);
    check("0 3e-25 4e-25", 0, 0.6, 0.8);
    check("3e38 3e38 0", 0.70710678, 0.70710678, 0);
    check("0 1 0", 0, 1, 0);
  }
  model::Affine<double> to_local;
  std::string error;
  CHECK_FALSE(eastray_object<LibmDouble>("5 grey 1  0 0 0  0 0 0  0.5 ;", to_local, error));
  CHECK(error == "the object's axis vector is zero");
}

TEST_CASE("a thin quadric: no crossing where a ray passes its rim", "[hard][eastray]") {
  check_thin_ellipsoid<LibmDouble>(1e-8);
  check_thin_ellipsoid<LibmDouble>(1e-30);
  check_thin_ellipsoid<LibmFloat>(1e-4f);
  check_thin_ellipsoid<PortableFloat>(1e-4f);
  check_thin_ellipsoid<PortableFloat>(1e-3f);
}
