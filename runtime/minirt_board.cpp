#include "minirt_board.hpp"

#include "board_math.hpp"
#include "same_text.hpp"
#include "core/image/png_writer.hpp"
#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "general_board.hpp"

namespace minrt::fw {

namespace {

int32_t find_texture(void* ctx, const char* name, Diagnostic& error) {
  const auto* table = static_cast<const send::textures::Table*>(ctx);
  const int32_t i = table != nullptr ? table->find(name) : -1;
  if (i < 0) error.text(name).text(": not sent ahead of the scene (host-send sends the ones it names)");
  return i;
}

}  // namespace

bool is_minirt_start(const char* first_word) {
  static constexpr const char* kWords[] = {"a", "c", "l", "sp", "pl", "cy", "co", "plc", "spt"};
  for (const char* w : kWords)
    if (same_text(first_word, w)) return true;
  return false;
}

SceneResult render_minirt(ByteSource in, ByteSink out, Arena& arena, int width, int height, bool all_features,
                          const send::textures::Table* textures, Diagnostic& error) {
  PngStoredWriter png(out);
  return render_minirt_rows(in, rgba_row_sink_of(png), arena, width, height, all_features, textures, error);
}

SceneResult render_minirt_rows(ByteSource in, RgbaRowSink rows, Arena& arena, int width, int height,
                               bool all_features, const send::textures::Table* textures, Diagnostic& error) {
  using R = Math::real;
  model::SceneBuilder<R> builder(arena);
  minirt::Reader<Math> reader(
      in, builder, minirt::TextureResolver{&find_texture, const_cast<send::textures::Table*>(textures)});
  model::Scene<R> scene;
  minirt::View<R> view;
  switch (reader.read(scene, view, error)) {
    case minirt::ReadStatus::kOk: break;
    case minirt::ReadStatus::kOutOfMemory: return SceneResult::kOutOfMemory;
    case minirt::ReadStatus::kSceneError: return SceneResult::kSceneError;
  }
  scene.width = width;
  scene.height = height;
  scene.camera = minirt::place_camera<Math>(view, width, height);
  if (!render_general_scene(builder, scene, textures, rows, arena, all_features, error)) return SceneResult::kOutOfMemory;
  return SceneResult::kOk;
}

}  // namespace minrt::fw
