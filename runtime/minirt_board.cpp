#include "minirt_board.hpp"

#include "board_math.hpp"
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
  return render_general_scene(builder, scene, textures, rows, arena, all_features, error);
}

}  // namespace minrt::fw
