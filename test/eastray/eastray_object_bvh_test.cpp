// The hierarchy over EASTRAY objects (render/general/csg_object_bvh.hpp)
// and the bounds it is built from (csg_bounds.hpp): every crossing of
// every primitive kind under random moves lies in the primitive's bound;
// a scene of assorted objects and CSG blocks renders the same bytes with
// and without the hierarchy in double and in the board's float; equally
// near hits keep the first object in the list.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/base/arena.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "render/general/csg_bounds.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "render/general/render.hpp"

namespace {

using namespace minrt;

struct Lcg {
  uint64_t s;
  double next() {  // [0, 1)
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) / 9007199254740992.0;
  }
  double in(double lo, double hi) { return lo + (hi - lo) * next(); }
};

std::string num(double v) { return std::to_string(v); }

// One primitive of `kind` at (x, y, z) with a random axis and size, as the
// text of an object statement (colour `mat`, sign `sign`).
std::string primitive(Lcg& g, int kind, double x, double y, double z, const std::string& mat, int sign) {
  const std::string c = num(x) + " " + num(y) + " " + num(z) + " ";
  const std::string axis = num(g.in(-1, 1)) + " " + num(g.in(0.2, 1)) + " " + num(g.in(-1, 1)) + " ";
  const std::string head = std::to_string(kind) + " " + mat + " " + std::to_string(sign) + " ";
  const double r = g.in(0.2, 0.5), h = g.in(0.2, 0.6);
  switch (kind) {
    case 0:  // an ellipsoid with cross terms about (x, y, z), then a saddle (open)
      return g.next() < 0.7 ? head + c + "4 5 6 1.5 -1 0.8 0 0 0 -1 ;" : head + c + "1 -1 0 0 0 0 0 0 1 0 ;";
    case 1: return head + c + axis + ";";
    case 2: return head + c + num(r) + " ;";
    case 3: return head + c + num(r) + " " + num(h) + " " + num(g.in(0.2, 0.5)) + " ;";
    case 4: case 5: return head + c + axis + num(r) + " ;";
    case 6: return head + c + axis + num(h) + " " + num(r) + " ;";
    case 7: return head + c + axis + num(g.in(0.3, 1.5)) + " " + num(r) + " ;";
    case 8: return head + c + axis + num(g.in(0.5, 1.5)) + " " + num(r * 0.5) + " ;";
    case 10: case 11: case 15: return head + c + axis + num(r) + " " + num(h) + " ;";
    case 12: case 13: return head + c + axis + num(g.in(0.5, 1.5)) + " " + num(h * 0.5) + " " + num(h) + " ;";
    case 14: return head + c + axis + num(g.in(0.3, 1.5)) + " " + num(r * 0.5) + " " + num(h) + " ;";
    default: return head + c + num(r) + " " + num(h) + " " + num(g.in(0.2, 0.5)) + " ;";  // 16
  }
}

constexpr int kKinds[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16};

std::string moves(Lcg& g) {
  return ":rx " + num(g.in(-90, 90)) + " :ry " + num(g.in(-90, 90)) + " :sx " + num(g.in(0.6, 1.4)) + " ";
}

const char* kHeader =
    "display 64 48  0 0 63 47  1 1  1 ;\n"
    "condition 4 0.01 0.00001 0 ;\n"
    "camera 0 4 12  0 0 0  0 10 0  30 0 ;\n"
    "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\n"
    "e_light [ -1 1.5 1  0.8 0.8 0.8  0 1 ; ]\n"
    "color [\n"
    "  red 0.9 0.1 0.1  0 0 0  0 0 0  1 1  0  0 0.4 20 ;\n"
    "  blue 0.1 0.2 0.9  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
    "  mirror 0.1 0.1 0.1  0.7 0.7 0.7  0 0 0  1 1  0  0 0.5 30 ;\n"
    "  glass 0 0 0  0.1 0.1 0.1  0.8 0.8 0.8  1.5 2  0  0 0 1 ;\n"
    "]\n";

// Assorted objects, AND / OR / difference blocks and a RANGE, all kinds.
std::string assorted_scene(uint64_t seed) {
  Lcg g{seed};
  std::string s = kHeader;
  s += "obj [\n  1 blue 1  0 -1.5 0  0 1 0 ;\n";
  const char* mats[] = {"red", "blue", "mirror", "glass"};
  for (int i = 0; i < 48; ++i) {
    const double x = g.in(-5, 5), y = g.in(-1, 2), z = g.in(-4, 2);
    const std::string m = mats[i % 4];
    const int kind = kKinds[i % 16];
    switch (i % 5) {
      case 0: s += "  [ " + moves(g) + primitive(g, kind, x, y, z, m, 1) + " ]\n"; break;
      case 1:
        s += "  { " + primitive(g, kind, x, y, z, m, 1) + " " + primitive(g, 2, x, y, z, "red", 1) + " }\n";
        break;
      case 2:
        s += "  { " + primitive(g, 16, x, y, z, m, 1) + " " + primitive(g, kind, x, y, z, "blue", -1) + " }\n";
        break;
      case 3:
        s += "  [ ( 2 " + num(x) + " " + num(y) + " " + num(z) + " 2 ; " + primitive(g, 2, x, y, z, m, 1) + " " +
             primitive(g, 16, x + 0.3, y, z, "red", 1) + " ) ]\n";
        break;
      default: s += "  " + primitive(g, kind, x, y, z, m, 1) + "\n"; break;
    }
  }
  return s + "]\n";
}

template <class M>
struct Loaded {
  using R = typename M::real;
  std::vector<unsigned char> storage;
  std::unique_ptr<Arena> arena;
  eastray::Scene<R> scene;

  explicit Loaded(const std::string& text) {
    const auto caps = eastray::Scene<R>::Capacities::for_text(text.size());
    const size_t bytes = eastray::Scene<R>::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() +
                         4 * general::object_bvh_bytes<R>(static_cast<uint32_t>(caps.nodes)) + 4096;
    storage.resize(bytes);
    arena = std::make_unique<Arena>(storage.data(), bytes);
    REQUIRE(scene.allocate(*arena, caps));
    auto reader = std::make_unique<eastray::Reader<M>>(text.data(), text.size(), scene, *arena);
    Diagnostic d;
    INFO(d.message);
    REQUIRE(reader->read(d));
  }

  // RGB bytes through the general renderer, with the hierarchy over the
  // objects or with the plain walk over the tree; its set-up takes from
  // `room` (the scene's own arena when null).
  std::vector<uint8_t> image(bool hierarchy = true, Arena* room = nullptr, uint32_t* bvh_nodes = nullptr) {
    model::EastrayShading<R> shading;
    model::Scene<R> model;
    eastray::to_model(scene, shading, model);
    general::Renderer<M> renderer;
    REQUIRE(renderer.setup(model, room != nullptr ? *room : *arena, 1));
    if (bvh_nodes != nullptr) *bvh_nodes = renderer.bvh().node_count;
    REQUIRE(renderer.path() == general::kPathEastray);
    if (hierarchy) {
      if (room == nullptr) REQUIRE(renderer.objects().unbounded != nullptr);
    } else {
      renderer.drop_object_bvh();
    }
    std::vector<uint8_t> row(4 * static_cast<size_t>(scene.width));
    std::vector<uint8_t> out;
    for (int y = 0; y < scene.height; ++y) {
      renderer.render_row(y, row.data());
      for (int x = 0; x < scene.width; ++x) out.insert(out.end(), row.begin() + 4 * x, row.begin() + 4 * x + 3);
    }
    return out;
  }
};

template <class M>
void check_same_image(const std::string& text) {
  Loaded<M> plain(text);
  const std::vector<uint8_t> before = plain.image(false);
  const std::vector<uint8_t> after = plain.image(true);
  REQUIRE(before.size() == after.size());
  size_t differing = 0;
  for (size_t i = 0; i < before.size(); ++i) differing += before[i] != after[i];
  CHECK(differing == 0);
}

}  // namespace

TEST_CASE("eastray object bounds hold every crossing of every kind under moves", "[eastray][bvh]") {
  using M = LibmDouble;
  using V = Vec3<double>;
  Lcg g{7};
  std::string text = kHeader;
  text += "obj [\n";
  for (int i = 0; i < 64; ++i)
    text += "  [ " + moves(g) + primitive(g, kKinds[i % 16], g.in(-2, 2), g.in(-2, 2), g.in(-2, 2), "red", 1) + " ]\n";
  text += "]\n";
  Loaded<M> l(text);
  REQUIRE(l.scene.primitive_count == 64);
  int bounded = 0, crossings_seen = 0;
  for (int32_t p = 0; p < l.scene.primitive_count; ++p) {
    const eastray::Primitive<double>& prim = l.scene.primitives[p];
    const general::OpenBox<double> b = general::primitive_box<M>(prim);
    INFO("primitive " << p << " kind " << int(prim.kind));
    const bool open = prim.kind == 1 || prim.kind == 4 || prim.kind == 5 || prim.kind == 7 || prim.kind == 8 ||
                      (prim.kind == 0 && prim.q[9] == 0.0);
    CHECK(b.finite() == !open);  // every closed kind gets a finite bound
    if (!b.finite()) continue;
    ++bounded;
    for (int r = 0; r < 400; ++r) {
      const V o{g.in(-8, 8), g.in(-8, 8), g.in(-8, 8)};
      const V target{g.in(b.lo[0], b.hi[0]), g.in(b.lo[1], b.hi[1]), g.in(b.lo[2], b.hi[2])};  // through the box
      const V d = normalize<M>(target - o);
      eastray::Crossing<double> c[4];
      const int k = eastray::crossings<M>(prim, o, d, 0.0, 1e30, c);
      for (int i = 0; i < k; ++i) {
        const V h = o + d * c[i].t;
        ++crossings_seen;
        CHECK((h.x >= b.lo[0] && h.x <= b.hi[0] && h.y >= b.lo[1] && h.y <= b.hi[1] && h.z >= b.lo[2] &&
               h.z <= b.hi[2]));
      }
    }
  }
  CHECK(bounded >= 40);
  CHECK(crossings_seen > 1000);
}

TEST_CASE("eastray object bounds: a NaN or overflowing solid is unbounded, and so is an OR holding it", "[eastray][bvh]") {
  using M = PortableFloat;
  model::Quadric<float> q{};
  q.shape = model::QuadricShape::kQuadric;
  q.q[0] = q.q[1] = q.q[2] = 1.0f;
  q.q[9] = -1.0f;
  CHECK(general::primitive_box<M>(q).finite());  // the unit sphere
  q.q[9] = __builtin_nanf("");
  CHECK_FALSE(general::primitive_box<M>(q).finite());
  q.q[9] = -1.0f;
  q.to_local.m[0] = __builtin_nanf("");  // a singular or NaN map
  CHECK_FALSE(general::primitive_box<M>(q).finite());
  Loaded<M> l(std::string(kHeader) + "obj [ [ 2 red 1  0 0 0  1 ;  2 red 1  5 0 0  1e25 ; ] 2 red 1  0 0 0  1 ; ]\n");
  const general::CsgScene<float> csg{l.scene.nodes, l.scene.primitives};
  const int32_t block = l.scene.nodes[l.scene.root].first_child;
  CHECK_FALSE(general::node_box<M>(csg, block).finite());                 // radius squared overflows
  CHECK(general::node_box<M>(csg, l.scene.nodes[block].next).finite());  // the plain sphere
}

TEST_CASE("eastray object hierarchy: the same image as the plain walk", "[eastray][bvh]") {
  for (uint64_t seed : {1u, 2u, 3u}) {
    INFO("seed " << seed);
    const std::string text = assorted_scene(seed);
    check_same_image<LibmDouble>(text);
    check_same_image<PortableFloat>(text);
  }
}

TEST_CASE("eastray object hierarchy: equally near hits keep the first object", "[eastray][bvh]") {
  // A red box and, after it, a thin blue one whose front face is the red
  // one's, so both are hit at the same t; a small sphere hidden in the red
  // box makes the hierarchy split them, blue in the box nearer the eye,
  // tested first. The plain walk shows red; so must the hierarchy.
  std::string text = kHeader;
  text += "obj [\n";
  for (int i = 0; i < 6; ++i) {
    const std::string x = num(-4 + 1.6 * i);
    text += "  16 red 1  " + x + " 0 0  0.6 0.6 0.6 ;\n";
    text += "  16 blue 1  " + x + " 0 0.4  0.6 0.6 0.2 ;\n";
    text += "  2 red 1  " + x + " 0 -0.3  0.05 ;\n";
  }
  text += "]\n";
  Loaded<LibmDouble> l(text);
  const std::vector<uint8_t> img = l.image(true);
  int red = 0, blue = 0;
  for (size_t i = 0; i + 2 < img.size(); i += 3) {
    if (img[i] > 2 * img[i + 2] && img[i] > 40) ++red;
    if (img[i + 2] > 2 * img[i] && img[i + 2] > 40 && !(img[i] == 51 && img[i + 1] == 102)) ++blue;
  }
  CHECK(red > 100);
  CHECK(blue == 0);
  check_same_image<LibmDouble>(text);
  check_same_image<PortableFloat>(text);
}

TEST_CASE("eastray meshes: the general BVH gives the image of every triangle in order, ties to the first face",
          "[eastray][bvh]") {
  // A smooth sphere of 960 faces over a flat square whose two faces are
  // listed twice, red first, then blue at the same place: equally near
  // faces keep the first, so no blue shows, with the hierarchy (the
  // renderer's own arena) or without it (an arena with no room for it, as
  // on a board short of memory: every triangle in order).
  std::string text = kHeader;
  text += "obj [\n  20 red 1 <\n";
  const int rings = 16, segs = 32;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segs; ++j) {
      const double th = 3.14159265358979 * i / rings, ph = 2 * 3.14159265358979 * j / segs;
      text += "    p " + std::to_string(i * segs + j) + " " + num(1.5 * std::sin(th) * std::cos(ph)) + " " +
              num(1.5 * std::cos(th)) + " " + num(1.5 * std::sin(th) * std::sin(ph)) + "\n";
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segs; ++j) {
      const int a = i * segs + j, b = i * segs + (j + 1) % segs, c = (i + 1) * segs + (j + 1) % segs,
                d = (i + 1) * segs + j;
      text += "    P " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + " ; s\n";
      text += "    P " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + " ; s\n";
    }
  text += "  > ;\n  20 red 1 <\n    p 1 -5 -1.6 5  p 2 5 -1.6 5  p 3 5 -1.6 -5  p 4 -5 -1.6 -5\n"
          "    P 1 2 3 4 ;\n    P 1 2 3 4 ;  c blue\n  > ;\n]\n";
  auto check = [&](auto math) {
    using M = decltype(math);
    Loaded<M> l(text);
    REQUIRE(l.scene.triangle_count > 900);  // the poles' slivers are dropped
    std::vector<unsigned char> big(1 << 22), small(256);
    Arena with_room(big.data(), big.size()), without_room(small.data(), small.size());
    uint32_t nodes_with = 0, nodes_without = 0;
    const std::vector<uint8_t> a = l.image(true, &with_room, &nodes_with);
    const std::vector<uint8_t> b = l.image(true, &without_room, &nodes_without);
    CHECK(nodes_with > 1);
    CHECK(nodes_without == 0);
    REQUIRE(a.size() == b.size());
    size_t differing = 0, blue = 0, red = 0;
    for (size_t i = 0; i < a.size(); ++i) differing += a[i] != b[i];
    for (size_t i = 0; i + 2 < a.size(); i += 3) {
      if (a[i + 2] > 2 * a[i] && a[i + 2] > 40 && !(a[i] == 51 && a[i + 1] == 102)) ++blue;
      if (a[i] > 2 * a[i + 2] && a[i] > 40) ++red;
    }
    CHECK(differing == 0);
    CHECK(blue == 0);
    CHECK(red > 500);
  };
  check(LibmDouble{});
  check(PortableFloat{});
}
