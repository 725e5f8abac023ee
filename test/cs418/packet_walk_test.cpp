// The packet walk (render/general/wide_packet.hpp, TracerCore::nearest_packet)
// gives each ray exactly the hit the single walk gives it: distance, kind,
// index, file order, barycentrics, for coherent packets, packets whose rays
// diverge, rays in several octants, rays that miss everything, partial
// packets and ties between coinciding objects; and CS418 rows rendered
// with packets are the bytes of the plain row loop.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "cs418_scene_text.hpp"
#include "render/general/render.hpp"

namespace {

using namespace minrt;

// A small deterministic generator: uniform in [0, 1).
struct Lcg {
  uint32_t state;
  double next() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  }
};

// Spheres in a box in front of the eye, every fifth one twice at the same
// place (a tie of distance that the later copy wins: spheres 6m and 6m+1),
// a fan of triangles through them, and a floor.
std::string packet_scene(int spheres, double radius, const char* camera) {
  std::ostringstream s;
  s << "png 41 23 x.png\naa 3\nbounces 2\ndof 2.4 0.03\n" << camera
    << "color 1 1 1\nsun 1 2 1\ncolor 0.4 0.3 0.2\nbulb 0 1.5 -2\n"
    << "shininess 0.4\nroughness 0.05\ncolor 0.3 0.5 0.1\nplane 0 1 0 1.25\n";
  Lcg rng{2024u};
  for (int i = 0; i < spheres; ++i) {
    s << "color " << rng.next() << ' ' << rng.next() << ' ' << rng.next() << '\n';
    std::ostringstream at;
    at << rng.next() * 3.5 - 1.75 << ' ' << rng.next() * 2.5 - 1.75 << ' ' << rng.next() * 2.5 - 4.0 << ' '
       << radius * (0.5 + rng.next());
    s << "sphere " << at.str() << '\n';
    if (i % 5 == 0) s << "color 1 0 0\nsphere " << at.str() << '\n';
  }
  s << "color 0.8 0.2 0.2\n";
  test::append_triangle_fan(s, 30, 0.2, 0.4);
  return s.str();
}

// The tracer with its single walk in reach.
template <class M, uint32_t F>
struct Probe : general::Cs418Shader<M, F> {
  using Base = general::Cs418Shader<M, F>;
  using Base::Base;
  using general::TracerCore<M, F>::nearest;
};

template <class R>
void check_same_hit(const general::Hit<R>& packet, const general::Hit<R>& single) {
  REQUIRE(packet.kind == single.kind);
  if (single.kind == general::HitKind::kNone) return;
  CHECK(packet.t == single.t);
  CHECK(packet.index == single.index);
  CHECK(packet.order == single.order);
  // Barycentrics and the solid's part belong to those kinds: on another
  // kind's hit they are left from a triangle or solid met before it,
  // which depends on the order of visits in any walk.
  if (single.kind == general::HitKind::kTriangle) {
    CHECK(packet.b1 == single.b1);
    CHECK(packet.b2 == single.b2);
  }
  if (single.kind == general::HitKind::kSolid) CHECK(packet.part == single.part);
}

struct Counts {
  int packets = 0, one_octant = 0, rays = 0, hits = 0, ties = 0;
};

// Packets of P rays of each kind, through the packet walk and ray by ray
// through the single walk.
template <class M, uint32_t F, int P>
void check_packets(const Probe<M, F>& tracer, const model::Scene<typename M::real>& scene, Counts& n) {
  using R = typename M::real;
  Lcg rng{77u + P};
  auto unit = [&](R x, R y, R z) { return normalize<M>(Vec3<R>{x, y, z}); };
  for (int p = 0; p < 1500; ++p) {
    general::Ray<R> rays[P];
    const int kind = p % 6;
    // Neighbouring rays from near the eye (coherent), rays from anywhere
    // in one octant (divergent), any direction (several octants), rays
    // leaving the scene (misses), axis-parallel rays with signed zeros, and
    // rays toward a sphere that is there twice.
    const Vec3<R> eye{R(rng.next() * 0.02), R(rng.next() * 0.02), R(0)};
    const R cx = R(rng.next() * 2 - 1), cy = R(rng.next() * 1.4 - 0.9);
    const int octant = static_cast<int>(rng.next() * 8);
    const Vec3<R> twin = scene.spheres[6 * static_cast<uint32_t>(rng.next() * 200)].center;
    for (int r = 0; r < P; ++r) {
      general::Ray<R>& ray = rays[r];
      switch (kind) {
        case 0:
          ray.origin = eye;
          ray.dir = unit(cx + R(r) * R(0.004) + R(rng.next() * 0.004), cy + R(rng.next() * 0.004), R(-1));
          break;
        case 1: {
          ray.origin = {R(rng.next() * 4 - 2), R(rng.next() * 3 - 2), R(rng.next() * 3 - 4.5)};
          const R x = R(rng.next() + 0.01), y = R(rng.next() + 0.01), z = R(rng.next() + 0.01);
          ray.dir = unit((octant & 1) != 0 ? -x : x, (octant & 2) != 0 ? -y : y, (octant & 4) != 0 ? -z : z);
          break;
        }
        case 2:
          ray.origin = {R(rng.next() * 4 - 2), R(rng.next() * 3 - 2), R(rng.next() * 3 - 4.5)};
          ray.dir = unit(R(rng.next() - 0.5), R(rng.next() - 0.5), R(rng.next() - 0.5));
          break;
        case 3:
          ray.origin = {R(rng.next() * 4 - 2), R(3), R(rng.next() * 4 - 5)};
          ray.dir = unit(R(rng.next() * 0.2 - 0.1), R(1), R(rng.next() * 0.2 - 0.1));
          break;
        case 4: {
          const R z = R(0), nz = R(-0.0);
          const Vec3<R> dirs[] = {{R(1), z, nz}, {R(-1), nz, z}, {z, nz, R(-1)}, {nz, z, R(-1)}};
          ray.origin = {R(rng.next() * 4 - 2), R(rng.next() * 2.5 - 1.75), R(rng.next() * 2 - 2.5)};
          ray.dir = dirs[(p / 6 + (r & 1)) % 4];
          break;
        }
        default:
          ray.origin = eye;
          ray.dir = normalize<M>(twin - eye + Vec3<R>{R(rng.next() * 0.06 - 0.03), R(rng.next() * 0.06 - 0.03), R(0)});
          break;
      }
    }
    // Every ray, or some (a row's last packet, a fisheye's rays outside
    // its circle).
    uint32_t active = (1u << P) - 1u;
    if (p % 4 == 3) active = static_cast<uint32_t>(rng.next() * (1u << P));
    const R eps = p % 2 == 0 ? R(0) : R(1e-4);
    general::Hit<R> packet[P] = {};
    tracer.template nearest_packet<P>(rays, active, eps, packet);
    general::PacketRay<P> lanes;
    ++n.packets;
    if (active != 0 && general::make_packet_ray<P>(rays, active, lanes)) ++n.one_octant;
    for (int r = 0; r < P; ++r) {
      general::Hit<R> single{};
      if ((active >> r & 1u) == 0) {
        CHECK(packet[r].kind == general::HitKind::kNone);  // untouched
        continue;
      }
      tracer.nearest(rays[r], eps, single);
      check_same_hit(packet[r], single);
      ++n.rays;
      if (single.kind != general::HitKind::kNone) ++n.hits;
      // A hit on the later of two coinciding spheres: a tie the order decided.
      if (single.kind == general::HitKind::kSphere && single.index % 6 == 1 && single.index < 1200) ++n.ties;
    }
  }
}

template <class M>
void check_walks(const std::string& text) {
  test::SceneInArena<M> in(text);
  Arena& arena = in.arena;
  const auto& scene = in.scene;
  general::Renderer<M> renderer;
  REQUIRE(renderer.setup(scene, arena, 7));
  REQUIRE(renderer.wide_walk());
  REQUIRE(renderer.packets());
  const Probe<M, general::kPathFull> tracer(scene, renderer.bvh(), nullptr, typename M::real(0));
  REQUIRE(scene.spheres[6].center.x == scene.spheres[7].center.x);  // the twins are where packet_scene puts them
  for (const bool widest : {true, false}) {
    if (!widest) renderer.use_16_byte_vectors();
    Counts n4, n8;
    check_packets<M, general::kPathFull, 4>(tracer, scene, n4);
    check_packets<M, general::kPathFull, 8>(tracer, scene, n8);
    for (const Counts& n : {n4, n8}) {
      CHECK(n.one_octant > n.packets / 2);  // most packets take the packet walk
      CHECK(n.one_octant < n.packets);      // some are split by octant
      CHECK(n.hits > n.rays / 4);
      CHECK(n.hits < n.rays);
      CHECK(n.ties > 100);
    }
  }
}

// The bytes of the scene's rows with packets and with the plain loop.
template <class M>
void check_rows(const std::string& text) {
  test::SceneInArena<M> in(text);
  Arena& arena = in.arena;
  const auto& scene = in.scene;
  general::Renderer<M> renderer;
  REQUIRE(renderer.setup(scene, arena, 11));
  REQUIRE(renderer.packets());
  const size_t row = static_cast<size_t>(scene.width) * 4;
  auto image = [&] {
    std::vector<uint8_t> rgba(row * static_cast<size_t>(scene.height));
    for (int y = 0; y < scene.height; ++y) renderer.render_row(y, rgba.data() + row * static_cast<size_t>(y));
    return rgba;
  };
  const auto packets = image();
  renderer.use_16_byte_vectors();
  const auto packets16 = image();
  renderer.drop_packets();
  const auto plain = image();
  CHECK(packets == plain);
  CHECK(packets16 == plain);
}

}  // namespace

TEST_CASE("packet walk: each ray's hit is the single walk's", "[general][bvh][packet]") {
  if (!general::kWideBvh) return;
  const std::string text = packet_scene(1500, 0.05, "");
  check_walks<LibmDouble>(text);
  check_walks<LibmFloat>(text);
}

TEST_CASE("packet rows: the bytes of the plain row loop", "[general][bvh][packet]") {
  if (!general::kWideBvh) return;
  for (const char* camera : {"", "fisheye\n", "panorama\neye 0 0.5 -2.5\n"}) {
    DYNAMIC_SECTION("camera: " << (*camera != 0 ? camera : "flat")) {
      const std::string text = packet_scene(800, 0.06, camera);
      check_rows<LibmDouble>(text);
      check_rows<LibmFloat>(text);
      check_rows<PortableFloat>(text);
    }
  }
}
