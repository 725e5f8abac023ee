// The CS418 reader and the general tracer on arbitrary bytes: the reader
// accepts or refuses with a located message, never crashes; an accepted
// scene builds, and a small one renders (every texture name resolves to a
// 2x2 texture) without reading out of bounds or producing a bad alpha.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "formats/cs418/cs418_reader.hpp"
#include "reader_fuzzing.hpp"
#include "render/general/render.hpp"

namespace {

const uint8_t kTexels[12] = {0, 64, 128, 255, 255, 255, 10, 20, 30, 200, 100, 0};
const minrt::model::Texture kTexture{2, 2, kTexels};

template <class M>
void read_one(const uint8_t* data, size_t size) {
  fuzzing::GeneralInput<M> in{.mem = {data, size}};
  minrt::cs418::Reader<M> reader(in.mem.source(), in.builder, {&fuzzing::any_texture, nullptr}, {});
  minrt::cs418::Header header;
  minrt::model::Scene<typename M::real> scene;
  minrt::Diagnostic d;
  const auto st = reader.read(header, scene, d);
  if (st == minrt::cs418::ReadStatus::kSceneError) {
    fuzzing::require_message(d, false);
    return;
  }
  if (st != minrt::cs418::ReadStatus::kOk || !in.builder.finish(scene)) return;
  scene.textures = &kTexture;
  scene.texture_count = 1;
  minrt::general::Renderer<M> renderer;
  if (!renderer.setup(scene, in.arena, 1)) return;
  // Render only what stays quick: a few pixels, few samples, shallow trees.
  if (static_cast<int64_t>(scene.width) * scene.height * scene.samples > 256 || scene.bounces > 6 || scene.gi_depth > 2)
    return;
  std::vector<uint8_t> row(static_cast<size_t>(scene.width) * 4);
  for (int y = 0; y < scene.height; ++y) {
    renderer.render_row(y, row.data());
    for (int x = 0; x < scene.width; ++x)
      if (row[4 * x + 3] == 0 && (row[4 * x] | row[4 * x + 1] | row[4 * x + 2]) != 0) std::abort();
  }
}

}  // namespace

MINRT_FUZZ_BOTH_POLICIES(read_one)
