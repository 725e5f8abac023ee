// The miniRT reader and the general tracer's miniRT paths on arbitrary
// bytes: the reader accepts or refuses with a message, never crashes; an
// accepted scene renders a tiny image (double and portable float) without
// reading out of bounds. Every texture name resolves to one small built-in
// texture, so `spt` lines reach the texture and bump code.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "reader_fuzzing.hpp"
#include "render/general/render.hpp"

namespace {

constexpr int kWidth = 8, kHeight = 6;
const uint8_t kTexels[3 * 3 * 2] = {0, 0, 0, 255, 255, 255, 10, 200, 30, 90, 90, 90, 250, 0, 0, 0, 0, 250};

template <class M>
void read_one(const uint8_t* data, size_t size) {
  using R = typename M::real;
  fuzzing::GeneralInput<M> in{.mem = {data, size}};
  minrt::minirt::Reader<M> reader(in.mem.source(), in.builder,
                                  minrt::minirt::TextureResolver{&fuzzing::any_texture, nullptr});
  minrt::model::Scene<R> scene;
  minrt::minirt::View<R> view;
  minrt::Diagnostic d;
  if (reader.read(scene, view, d) != minrt::minirt::ReadStatus::kOk) {
    fuzzing::require_message(d, false);
    return;
  }
  if (!in.builder.finish(scene)) return;
  const minrt::model::Texture texture{3, 2, kTexels};
  scene.textures = &texture;
  scene.texture_count = 1;
  scene.width = kWidth;
  scene.height = kHeight;
  scene.camera = minrt::minirt::place_camera<M>(view, kWidth, kHeight);
  minrt::general::Renderer<M> renderer;
  if (!renderer.setup(scene, in.arena, 1)) return;
  uint8_t row[4 * kWidth];
  for (int y = 0; y < kHeight; ++y) {
    renderer.render_row(y, row);
    for (int x = 0; x < kWidth; ++x)
      if (row[4 * x + 3] != 255) std::abort();  // miniRT pixels are opaque
  }
}

}  // namespace

MINRT_FUZZ_BOTH_POLICIES(read_one)
