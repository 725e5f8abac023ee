#include "minirt_board.hpp"

#include "board_math.hpp"
#include "core/image/png_writer.hpp"
#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "render/general/render.hpp"

namespace minrt::fw {

namespace {

int32_t find_texture(void* ctx, const char* name, Diagnostic& error) {
  const auto* table = static_cast<const send::textures::Table*>(ctx);
  const int32_t i = table != nullptr ? table->find(name) : -1;
  if (i < 0) error.text(name).text(": not sent ahead of the scene (host-send sends the ones it names)");
  return i;
}

bool same(const char* a, const char* b) {
  while (*a != 0 && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

}  // namespace

bool is_minirt_start(const char* first_word) {
  static constexpr const char* kWords[] = {"a", "c", "l", "sp", "pl", "cy", "co", "plc", "spt"};
  for (const char* w : kWords)
    if (same(first_word, w)) return true;
  return false;
}

MinirtResult render_minirt(ByteSource in, ByteSink out, Arena& arena, int width, int height, bool all_features,
                           const send::textures::Table* textures, Diagnostic& error) {
  PngStoredWriter png(out);
  return render_minirt_rows(in, rgba_row_sink_of(png), arena, width, height, all_features, textures, error);
}

MinirtResult render_minirt_rows(ByteSource in, RgbaRowSink rows, Arena& arena, int width, int height,
                                bool all_features, const send::textures::Table* textures, Diagnostic& error) {
  using R = Math::real;
  model::SceneBuilder<R> builder(arena);
  minirt::Reader<Math> reader(
      in, builder, minirt::TextureResolver{&find_texture, const_cast<send::textures::Table*>(textures)});
  model::Scene<R> scene;
  minirt::View<R> view;
  switch (reader.read(scene, view, error)) {
    case minirt::ReadStatus::kOk: break;
    case minirt::ReadStatus::kOutOfMemory: return MinirtResult::kOutOfMemory;
    case minirt::ReadStatus::kSceneError: return MinirtResult::kSceneError;
  }
  scene.width = width;
  scene.height = height;
  scene.camera = minirt::place_camera<Math>(view, width, height);
  general::Renderer<Math> renderer;
  uint8_t* row = nullptr;
  model::Texture* table = nullptr;
  const int count = textures != nullptr ? textures->count : 0;
  if (count > 0 && (table = arena.alloc_zeroed<model::Texture>(static_cast<size_t>(count))) != nullptr) {
    for (int i = 0; i < count; ++i)
      table[i] = model::Texture{textures->items[i].width, textures->items[i].height, textures->items[i].rgb};
    scene.textures = table;
    scene.texture_count = static_cast<uint32_t>(count);
  }
  if ((count > 0 && table == nullptr) || !builder.finish(scene) || !renderer.setup(scene, arena, 1, all_features) ||
      (row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(width))) == nullptr) {
    error.text("scene does not fit in the board's memory (").number(static_cast<int64_t>(arena.capacity())).text(
        " bytes)");
    return MinirtResult::kOutOfMemory;
  }
  renderer.render(rows, row);
  return MinirtResult::kOk;
}

}  // namespace minrt::fw
