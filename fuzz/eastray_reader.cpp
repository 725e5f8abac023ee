// The EASTRAY reader and tracer on arbitrary (already preprocessed) text:
// the reader accepts or refuses with a located message, never crashes or
// hangs; an accepted small scene renders without reading out of bounds and
// gives opaque pixels, walking the BVHs over its objects and triangles.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "formats/eastray/eastray_reader.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "reader_fuzzing.hpp"
#include "render/general/render.hpp"

namespace {

template <class M>
void read_one(const uint8_t* data, size_t size) {
  using R = typename M::real;
  using Scene = minrt::eastray::Scene<R>;
  constexpr typename Scene::Capacities kItems = Scene::Capacities::all(512);
  minrt::Arena arena = fuzzing::arena_once<M>(Scene::bytes_for(kItems) + minrt::eastray::Reader<M>::scratch_bytes() +
                                              minrt::general::object_bvh_bytes<R>(512) +
                                              minrt::general::bvh_footprint<R>(512) + 4096 * 4 + 4096);
  minrt::eastray::Scene<R> scene;
  if (!scene.allocate(arena, kItems)) std::abort();
  minrt::eastray::Reader<M> reader(reinterpret_cast<const char*>(data), size, scene, arena);
  minrt::Diagnostic d;
  if (!reader.read(d)) {
    fuzzing::require_message(d, true);
    return;
  }
  // The hierarchies over any accepted scene's objects and triangles (their
  // bounds meet every coefficient and move the reader lets through); the
  // render below walks them.
  minrt::model::EastrayShading<R> shading;
  minrt::model::Scene<R> model;
  minrt::eastray::to_model(scene, shading, model);
  minrt::general::Renderer<M> renderer;
  if (!renderer.setup(model, arena, 1)) std::abort();
  if (static_cast<int64_t>(scene.width) * scene.height > 64 || scene.max_depth > 4 || scene.anti > 2) return;
  std::vector<uint8_t> rgba(static_cast<size_t>(scene.width) * 4);
  struct Check {
    void begin(int, int) {}
    void row(int, const uint8_t*) {}
    void end() {}
  } check;
  renderer.render(minrt::rgba_row_sink_of(check), rgba.data());
  for (int x = 0; x < scene.width; ++x)
    if (rgba[4 * x + 3] != 255) std::abort();
}

}  // namespace

MINRT_FUZZ_BOTH_POLICIES(read_one)
