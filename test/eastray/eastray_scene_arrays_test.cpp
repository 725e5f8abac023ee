// The EASTRAY scene's arrays (formats/eastray/eastray_scene.hpp) are sized
// from the text for the worst case and not zeroed: the reader writes each
// item whole as it counts it. Checked from an arena full of a byte pattern:
// the capacity past every count is left untouched (set-up costs what the
// scene uses), and the image equals the one read from a zeroed arena, in
// double and in the board's float.
#include <catch2/catch.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/base/arena.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "render/general/csg_object_bvh.hpp"
#include "render/general/render.hpp"

namespace {

using namespace minrt;

constexpr uint8_t kFill = 0xa5;

// Every kind of item: colours, the three lights and an object light, CSG
// blocks, a RANGE, a part called twice, a smooth mesh with a face that
// folds to nothing (its triangle is skipped) before the last.
const char* kScene =
    "display 48 36  0 0 47 35  1 1  1 ;\n"
    "condition 4 0.01 0.00001 1 ;\n"
    "camera 0 3 10  0 0.5 0  0 10 0  30 0 ;\n"
    "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\n"
    "e_light [ -1 1.5 1  0.7 0.7 0.7  0 1 ; ]\n"
    "p_light [ 2 4 2  0.4 0.4 0.4  8 ; ]\n"
    "s_light [ -2 4 3  0 0 0  0.3 0.3 0.3  4 10 ; ]\n"
    "color [\n"
    "  red 0.9 0.1 0.1  0 0 0  0 0 0  1 1  0  0 0.4 20 ;\n"
    "  floor 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ;\n"
    "  mirror 0.1 0.1 0.1  0.7 0.7 0.7  0 0 0  1 1  0  0 0.5 30 ;\n"
    "  glass 0 0 0  0.1 0.1 0.1  0.8 0.8 0.8  1.5 2  0  0 0 1 ;\n"
    "]\n"
    "obj [\n"
    "  1 floor 1  0 -1 0  0 1 0 ;\n"
    "  -2 0 3 0  0.2 0.2 0.2  10 ;\n"
    "  { 2 red 1  -2 0 0  1 ; 16 red 1  -2 0 0  0.8 0.8 0.8 ; }\n"
    "  [ 16 mirror 1  2 0 -1  0.6 0.6 0.6 ; 5 mirror -1  2 0 -1  0 1 0  0.3 ; ]\n"
    "  ( 2  0 0 2  1.2 ; 2 glass 1  0 0 2  0.8 ; 2 red 1  0.5 0 2  0.5 ; )\n"
    "  ball ; :mx 1.5 :my 2 ball ;\n"
    "  20 red 1 < p 0 0 1 0  p 1 1 1 0  p 2 1 2 0  p 3 0 2 0  p 4 0.5 2.5 0.5\n"
    "    P 0 1 2 3 ; s  P 0 0 0 ; s  P 3 2 4 ; s > ;\n"
    "]\n"
    "obj ball [ 2 mirror 1  0 1 -2  0.4 ; ]\n";

template <class T>
bool untouched(const T* items, int32_t count, int32_t capacity) {
  const auto* b = reinterpret_cast<const uint8_t*>(items + count);
  const size_t n = static_cast<size_t>(capacity - count) * sizeof(T);
  for (size_t i = 0; i < n; ++i)
    if (b[i] != kFill) return false;
  return true;
}

template <class M>
struct Read {
  using R = typename M::real;
  std::vector<uint8_t> storage;
  std::unique_ptr<Arena> arena;
  eastray::Scene<R> scene;

  explicit Read(uint8_t fill) {
    const std::string text = kScene;
    const auto caps = eastray::Scene<R>::Capacities::for_text(text.size());
    const size_t bytes = eastray::Scene<R>::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() +
                         general::bvh_footprint<R>(static_cast<uint32_t>(caps.triangles)) +
                         general::object_bvh_bytes<R>(static_cast<uint32_t>(caps.nodes)) + 4096;
    storage.assign(bytes, fill);
    arena = std::make_unique<Arena>(storage.data(), bytes);
    REQUIRE(scene.allocate(*arena, caps));
    auto reader = std::make_unique<eastray::Reader<M>>(text.data(), text.size(), scene, *arena);
    Diagnostic d;
    const bool ok = reader->read(d);
    INFO(d.message);
    REQUIRE(ok);
  }

  std::vector<uint8_t> image() {
    model::EastrayShading<R> shading;
    model::Scene<R> model;
    eastray::to_model(scene, shading, model);
    general::Renderer<M> renderer;
    REQUIRE(renderer.setup(model, *arena, 1));
    std::vector<uint8_t> row(4 * static_cast<size_t>(scene.width)), out;
    for (int y = 0; y < scene.height; ++y) {
      renderer.render_row(y, row.data());
      out.insert(out.end(), row.begin(), row.end());
    }
    return out;
  }
};

template <class M>
void check() {
  Read<M> filled(kFill);
  const auto& s = filled.scene;
  // What the scene uses: the reader counted every kind.
  CHECK(s.light_count == 4);
  CHECK(s.material_count == 4);
  CHECK(s.primitive_count >= 10);
  CHECK(s.triangle_count == 3);  // 2 + 1; the folded face adds none
  CHECK(s.vertex_count == 5);
  // The rest of each array was never written.
  CHECK(untouched(s.lights, s.light_count, s.light_capacity));
  CHECK(untouched(s.materials, s.material_count, s.material_capacity));
  CHECK(untouched(s.primitives, s.primitive_count, s.primitive_capacity));
  CHECK(untouched(s.nodes, s.node_count, s.node_capacity));
  CHECK(untouched(s.triangles, s.triangle_count, s.triangle_capacity));
  CHECK(untouched(s.faces, s.triangle_count, s.triangle_capacity));
  CHECK(untouched(s.vertices, s.vertex_count, s.vertex_capacity));
  CHECK(untouched(s.vertex_normals, s.vertex_count, s.vertex_capacity));
  CHECK(untouched(s.vertex_ids, s.vertex_count, s.vertex_capacity));
  // And nothing read the pattern: the same image as from zeros.
  Read<M> zeroed(0);
  CHECK(filled.image() == zeroed.image());
}

}  // namespace

TEST_CASE("eastray: the scene arrays are written item by item, the unused capacity is left untouched", "[eastray]") {
  SECTION("double") { check<LibmDouble>(); }
  SECTION("float, portable shims") { check<PortableFloat>(); }
}
