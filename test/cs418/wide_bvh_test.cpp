// The wide BVH (render/general/wide_node.hpp) and its vector walks change
// only the speed: the binary tree's walk, the wide walk with 16-byte
// vectors and, on a CPU with AVX2, the AVX2 copy give the same bytes, in
// double and in float, on scenes of spheres, triangles and planes with
// reflection, refraction, roughness, shadows from suns and bulbs.
#include <catch2/catch.hpp>

#include <cstdint>
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

// A deterministic cloud of spheres of the given radius, a floor and a
// fan of triangles through it.
std::string cloud_scene(int spheres, double radius) {
  std::ostringstream s;
  s << "png 48 40 x.png\naa 3\nbounces 6\ndof 2.5 0.02\n"
    << "color 1 1 1\nsun 1 2 1\ncolor 0.4 0.3 0.2\nsun -1 0.5 0.3\ncolor 2 2 2\nbulb 0 1.5 -2\n"
    << "shininess 0.5\nroughness 0.05\ncolor 0.3 0.5 0.1\nplane 0 1 0 1.25\n";
  uint32_t state = 12345u;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  for (int i = 0; i < spheres; ++i) {
    const double kind = next();
    s << "color " << next() << ' ' << next() << ' ' << next() << '\n';
    s << "shininess " << (kind < 0.3 ? 0.6 : 0.1) << "\ntransparency " << (kind > 0.85 ? 0.8 : 0.0)
      << "\nroughness " << (kind > 0.6 && kind < 0.7 ? 0.1 : 0.0) << '\n';
    s << "sphere " << next() * 3.5 - 1.75 << ' ' << next() * 2.5 - 1.75 << ' ' << next() * 2.5 - 4.0 << ' '
      << radius * (0.5 + next()) << '\n';
  }
  s << "shininess 0.2\ntransparency 0\nroughness 0\ncolor 0.8 0.2 0.2\n";
  test::append_triangle_fan(s, 40, 0.157, 0.5);
  return s.str();
}

template <class M>
struct Rendered {
  std::vector<uint8_t> rgba;
  bool wide = false;
  bool avx2 = false;
  bool sun_grids = false;
};

enum class Walk { kBinary, kWide16, kWidest, kWidestNoSunGrids };

// The scene a CS418 text sets up, laid out in `arena`.
template <class M>
Rendered<M> render(const std::string& text, Walk walk) {
  test::SceneInArena<M> in(text);
  Arena& arena = in.arena;
  const auto& scene = in.scene;
  general::Renderer<M> renderer;
  REQUIRE(renderer.setup(scene, arena, 7));
  if (walk == Walk::kBinary) renderer.drop_wide_bvh();
  if (walk == Walk::kWide16) renderer.use_16_byte_vectors();
  if (walk == Walk::kWidestNoSunGrids) renderer.drop_sun_grids();
  Rendered<M> out;
  out.wide = renderer.wide_walk();
  out.avx2 = renderer.avx2_walk();
  out.sun_grids = renderer.sun_grids();
  out.rgba.resize(static_cast<size_t>(scene.width) * scene.height * 4);
  for (int y = 0; y < scene.height; ++y) renderer.render_row(y, out.rgba.data() + static_cast<size_t>(y) * scene.width * 4);
  return out;
}

template <class M>
void check_walks(const std::string& text) {
  const auto binary = render<M>(text, Walk::kBinary);
  const auto wide16 = render<M>(text, Walk::kWide16);
  const auto widest = render<M>(text, Walk::kWidest);
  const auto no_grids = render<M>(text, Walk::kWidestNoSunGrids);
  CHECK_FALSE(binary.wide);
  CHECK_FALSE(binary.sun_grids);
  CHECK_FALSE(no_grids.sun_grids);
  CHECK(no_grids.rgba == binary.rgba);
  if (general::kWideBvh) {
    CHECK(wide16.wide);
    CHECK_FALSE(wide16.avx2);
    CHECK(widest.avx2 == general::cpu_has_avx2());
  }
  CHECK(wide16.rgba == binary.rgba);
  CHECK(widest.rgba == binary.rgba);
}

}  // namespace

// The cloud without its triangles, at 64x48: a scene of spheres alone
// with enough samples a sphere for its suns to get grids (sun_grid.hpp).
std::string sphere_cloud(int spheres, double radius) {
  std::string text = cloud_scene(spheres, radius);
  text = text.substr(0, text.find("shininess 0.2\ntransparency 0\nroughness 0\ncolor 0.8 0.2 0.2\n"));
  return "png 64 48 x.png" + text.substr(text.find('\n'));
}

TEST_CASE("wide BVH: binary, 16-byte and widest walks give the same bytes", "[general][bvh]") {
  for (const auto& [spheres, radius] : {std::pair{600, 0.05}, std::pair{3000, 0.02}, std::pair{40, 0.6}}) {
    DYNAMIC_SECTION(spheres << " spheres of radius about " << radius) {
      const std::string text = cloud_scene(spheres, radius);
      check_walks<LibmDouble>(text);
      check_walks<LibmFloat>(text);
      check_walks<PortableFloat>(text);
    }
  }
}

// A sphere whose squared radius overflows float makes the lane arithmetic
// of a leaf's triangle lanes NaN, and a NaN compare "meets" every lane; the
// walk must still offer only spheres (it once read a sphere at a triangle's
// index and crashed).
TEST_CASE("wide BVH: a sphere too large for float beside triangles", "[general][bvh]") {
  const std::string text =
      "png 12 10 x.png\nshininess 1\nxyz 0 0 2\nxyz 1 0 2\nxyz 1 1 2\ntri 1 2 3\n"
      "xyz -1 0 -3\nxyz 0 1 -3\nxyz 1 0 -3\ntri -3 -2 -1\nsun 0 1 1\nsphere 0 2 1 22222222222222222220\n"
      "color 1 0 0\nsphere 0 0 -2 0.5\n";
  check_walks<LibmDouble>(text);
  check_walks<LibmFloat>(text);
  check_walks<PortableFloat>(text);
}

// Every sphere of a cloud twice, at the same place in another colour: each
// hit is a tie of distance, which the later sphere wins (SPEC.md 1.3). The
// wide walk reads a sphere's file order only for such ties; it must pick
// the binary walk's winner whichever leaf or lane holds either copy.
TEST_CASE("wide BVH: coincident spheres, the later one wins in every walk", "[general][bvh]") {
  std::string text = sphere_cloud(300, 0.08);
  std::istringstream lines(text.substr(text.find("color 1 1 1")));
  std::ostringstream twice;
  twice << text.substr(0, text.find("color 1 1 1"));
  std::string line, sphere;
  for (int k = 0; std::getline(lines, line); ++k) {
    twice << line << '\n';
    if (line.rfind("sphere ", 0) != 0) continue;
    twice << "color " << (k % 3 == 0 ? "1 0 0" : k % 3 == 1 ? "0 1 0" : "0 0 1") << '\n' << line << '\n';
  }
  text = twice.str();
  check_walks<LibmDouble>(text);
  check_walks<LibmFloat>(text);
  // The later copy's colour shows: not the image of the cloud drawn once.
  CHECK(render<LibmDouble>(text, Walk::kWidest).rgba != render<LibmDouble>(sphere_cloud(300, 0.08), Walk::kWidest).rgba);
}

// Shadow rays toward a sun through its grid answer as the walk does: the
// same bytes with and without the grids, on clouds of small and of large
// overlapping spheres, in double and in float.
TEST_CASE("sun grids: the same bytes as the shadow walk", "[general][bvh]") {
  for (const auto& [spheres, radius] : {std::pair{1100, 0.03}, std::pair{400, 0.4}, std::pair{5, 3.0}}) {
    DYNAMIC_SECTION(spheres << " spheres of radius about " << radius) {
      const std::string text = sphere_cloud(spheres, radius);
      if (general::kWideBvh) CHECK(render<LibmDouble>(text, Walk::kWidest).sun_grids);
      check_walks<LibmDouble>(text);
      check_walks<LibmFloat>(text);
      check_walks<PortableFloat>(text);
    }
  }
}

// Each origin's cell lists every sphere that blocks a ray from it toward the
// sun (found here by testing them all), from points on and between spheres.
TEST_CASE("sun grids: a cell lists every sphere that blocks its rays", "[general][bvh]") {
  using R = double;
  const std::string text = sphere_cloud(800, 0.08);
  const size_t bytes = size_t{64} << 20;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  const model::Scene<R> scene = test::read_scene<LibmDouble>(text, arena);
  const Vec3<R> dir = normalize<LibmDouble>(Vec3<R>{1, 2, 1});
  general::SunGrid<R> grid;
  REQUIRE(general::build_sun_grid<LibmDouble>(scene, dir, arena, grid));
  uint32_t state = 99u;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  const R eps = 1e-4;
  int blocked = 0;
  for (int k = 0; k < 20000; ++k) {
    // Half the origins on a sphere's surface, as shading makes them.
    Vec3<R> o{next() * 4.0 - 2.0, next() * 3.0 - 2.0, next() * 3.0 - 4.5};
    if (k % 2 == 0) {
      const auto& sp = scene.spheres[static_cast<uint32_t>(next() * scene.sphere_count) % scene.sphere_count];
      const Vec3<R> n = normalize<LibmDouble>(Vec3<R>{next() - 0.5, next() - 0.5, next() - 0.5});
      o = sp.center + n * sp.radius;
    }
    const general::Ray<R> ray{o, dir};
    bool any = false;
    for (uint32_t i = 0; i < scene.sphere_count && !any; ++i) {
      const R t = general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps);
      any = t > eps;
    }
    REQUIRE(general::sun_grid_covers(grid, ray));
    const bool by_grid = general::sun_grid_any(grid, o, [&](uint32_t i) {
      return general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps) > eps;
    });
    CHECK(by_grid == any);
    blocked += any ? 1 : 0;
  }
  CHECK(blocked > 1000);  // the rays are not all free
  CHECK(blocked < 19000);
}

namespace {

// Every item of every cell: its sphere's index, a level at or above its far
// side's (by the arithmetic the look-up uses), levels not rising along a
// list, and each sphere in at least one cell.
template <class M>
void check_sun_grid_levels(const std::string& text, const Vec3<typename M::real>& sun) {
  using R = typename M::real;
  const size_t bytes = size_t{64} << 20;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  const model::Scene<R> scene = test::read_scene<M>(text, arena);
  const Vec3<R> dir = normalize<M>(sun);
  general::SunGrid<R> grid;
  REQUIRE(general::build_sun_grid<M>(scene, dir, arena, grid));
  REQUIRE(grid.index_bits >= 1);
  REQUIRE((scene.sphere_count - 1) >> grid.index_bits == 0);
  REQUIRE(grid.far_scale > R(0));
  const uint32_t mask = (1u << grid.index_bits) - 1u;
  std::vector<bool> listed(scene.sphere_count, false);
  uint32_t top_level = 0, items = 0;
  for (size_t c = 0; c < static_cast<size_t>(grid.nu) * grid.nv; ++c) {
    uint32_t previous = 0xffffffffu;
    for (uint32_t k = grid.start[c]; k < grid.start[c + 1]; ++k, ++items) {
      const uint32_t i = grid.items[k] & mask, level = grid.items[k] >> grid.index_bits;
      REQUIRE(i < scene.sphere_count);
      listed[i] = true;
      const model::Sphere<R>& sp = scene.spheres[i];
      const R r = sp.radius < R(0) ? -sp.radius : sp.radius;
      const float far = general::sun_grid_detail::float_up(dot(sp.center, dir) + r + grid.margin);
      CHECK(static_cast<R>(level) >= (static_cast<R>(far) - grid.far0) * grid.far_scale);
      CHECK(level <= previous);
      previous = level;
      if (level > top_level) top_level = level;
    }
  }
  CHECK(items >= scene.sphere_count);
  for (uint32_t i = 0; i < scene.sphere_count; ++i) CHECK(listed[i]);
  CHECK(top_level > 1000);  // the levels tell the far sides apart
  CHECK(top_level < (1u << general::kSunGridLevelBits));
}

}  // namespace

// The four-byte items: double and float grids, over small spheres and
// over a few large ones whose far sides spread widely.
TEST_CASE("sun grids: an item's level is never below its sphere's far side", "[general][bvh]") {
  for (const auto& [spheres, radius] : {std::pair{800, 0.08}, std::pair{3000, 0.01}, std::pair{40, 2.0}}) {
    DYNAMIC_SECTION(spheres << " spheres of radius about " << radius) {
      const std::string text = sphere_cloud(spheres, radius);
      check_sun_grid_levels<LibmDouble>(text, Vec3<double>{1, 2, 1});
      check_sun_grid_levels<LibmDouble>(text, Vec3<double>{-1, 0.5, 0.3});
      check_sun_grid_levels<LibmFloat>(text, Vec3<float>{1, 2, 1});
      check_sun_grid_levels<PortableFloat>(text, Vec3<float>{-1, 0.5, 0.3});
    }
  }
}

// Spheres whose far sides coincide (equal radii, centres level across the
// sun) have no scale for levels: every ray reads its list to the end and
// finds what testing every sphere finds.
TEST_CASE("sun grids: far sides all equal, no ray stops early", "[general][bvh]") {
  using R = double;
  std::ostringstream text;
  text << "png 64 48 x.png\naa 40\ncolor 1 1 1\nsun 0 1 0\n";
  for (int i = 0; i < 200; ++i) text << "sphere " << (i % 20) * 0.3 - 3.0 << " -1 " << (i / 20) * 0.3 - 4.0 << " 0.1\n";
  const size_t bytes = size_t{16} << 20;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  const model::Scene<R> scene = test::read_scene<LibmDouble>(text.str(), arena);
  const Vec3<R> dir{0, 1, 0};
  general::SunGrid<R> grid;
  REQUIRE(general::build_sun_grid<LibmDouble>(scene, dir, arena, grid));
  CHECK(grid.far_scale == 0.0);
  const R eps = 1e-4;
  int blocked = 0;
  for (int k = 0; k < 4000; ++k) {
    // Below, between and on the spheres, and above them.
    const Vec3<R> o{(k % 80) * 0.08 - 3.3, (k / 80 % 5) * 0.05 - 1.2, (k / 400) * 0.3 - 4.05};
    const general::Ray<R> ray{o, dir};
    bool any = false;
    for (uint32_t i = 0; i < scene.sphere_count && !any; ++i)
      any = general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps) > eps;
    REQUIRE(general::sun_grid_covers(grid, ray));
    CHECK(general::sun_grid_any(grid, o, [&](uint32_t i) {
            return general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps) > eps;
          }) == any);
    blocked += any ? 1 : 0;
  }
  CHECK(blocked > 100);
  CHECK(blocked < 3900);
}

namespace {

// The nearest sphere along `ray` by the wide walk with kBytes vectors (the
// leaves tested sphere by sphere with the tracer's test and tie rule).
template <int kBytes>
[[gnu::always_inline]] inline void wide_nearest_spheres(const general::Bvh<double>& tree,
                                                        const model::Scene<double>& scene,
                                                        const general::Ray<double>& ray, double eps,
                                                        general::Hit<double>& h) {
  general::wide_nearest<kBytes>(
      tree.wide, ray, [&]() __attribute__((always_inline)) { return h.kind == general::HitKind::kNone ? 3.0e38 : h.t; },
      [&](uint32_t first, uint32_t count) __attribute__((always_inline)) {
        for (uint32_t k = 0; k < count; ++k) {
          const uint32_t i = tree.refs[first + k];
          const double t = general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps);
          if (t > eps) h.offer(t, general::HitKind::kSphere, i, scene.spheres[i].order);
        }
      });
}

#if MINRT_AVX2_DISPATCH
MINRT_TARGET_AVX2 void wide_nearest_spheres_avx2(const general::Bvh<double>& tree, const model::Scene<double>& scene,
                                                 const general::Ray<double>& ray, double eps,
                                                 general::Hit<double>& h) {
  wide_nearest_spheres<general::kAvx2BoxBytes>(tree, scene, ray, eps, h);
}
#endif

}  // namespace

// The walk has a copy for each octant of directions (wide_traversal.hpp):
// rays in every octant, along the axes with components of +0 and -0, and
// from inside boxes meet the sphere that testing every sphere finds (the
// same distance, and the later of two at the same distance).
TEST_CASE("wide BVH: every octant and axis-parallel rays find the nearest sphere", "[general][bvh]") {
  if (!general::kWideBvh) return;
  const std::string text = sphere_cloud(2000, 0.05);
  const size_t bytes = size_t{64} << 20;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  const model::Scene<double> scene = test::read_scene<LibmDouble>(text, arena);
  general::Bvh<double> tree;
  REQUIRE(general::build_bvh<LibmDouble>(scene, arena, tree));
  REQUIRE(general::build_wide_bvh(tree, arena, tree.wide));
  REQUIRE(tree.wide.node_count != 0);
  uint32_t state = 4321u;
  auto next = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / 16777216.0;
  };
  const double eps = 1e-4;
  const double z = 0.0, nz = -0.0;
  const Vec3<double> axis_dirs[] = {{1, z, z},  {-1, z, nz}, {nz, 1, z},  {z, -1, nz},
                                    {z, nz, 1}, {nz, z, -1}, {nz, nz, -1}, {-1, nz, nz}};
  int hits = 0, rays = 0;
  for (int k = 0; k < 6000; ++k) {
    const Vec3<double> o{next() * 4.0 - 2.0, next() * 3.0 - 2.0, next() * 3.0 - 4.5};
    Vec3<double> d = k % 3 == 0 ? axis_dirs[(k / 3) % 8]
                                : normalize<LibmDouble>(Vec3<double>{next() - 0.5, next() - 0.5, next() - 0.5});
    const general::Ray<double> ray{o, d};
    general::Hit<double> every;
    for (uint32_t i = 0; i < scene.sphere_count; ++i) {
      const double t = general::hit_sphere<LibmDouble>(scene.spheres[i], ray, eps);
      if (t > eps) every.offer(t, general::HitKind::kSphere, i, scene.spheres[i].order);
    }
    general::Hit<double> wide16;
    wide_nearest_spheres<16>(tree, scene, ray, eps, wide16);
    REQUIRE(wide16.kind == every.kind);
    if (every.kind != general::HitKind::kNone) {
      CHECK(wide16.index == every.index);
      CHECK(wide16.t == every.t);
      ++hits;
    }
#if MINRT_AVX2_DISPATCH
    if (general::cpu_has_avx2()) {
      general::Hit<double> widest;
      wide_nearest_spheres_avx2(tree, scene, ray, eps, widest);
      REQUIRE(widest.kind == every.kind);
      if (every.kind != general::HitKind::kNone) {
        CHECK(widest.index == every.index);
        CHECK(widest.t == every.t);
      }
    }
#endif
    ++rays;
  }
  CHECK(hits > rays / 4);  // most rays meet a sphere, not all
  CHECK(hits < rays);
}
