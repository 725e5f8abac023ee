#include "cs418_board.hpp"

#include "board_math.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "general_board.hpp"

namespace minrt::fw {

namespace {

int32_t find_texture(void* ctx, const char* name, Diagnostic& error) {
  const auto* table = static_cast<const send::textures::Table*>(ctx);
  const int32_t i = table != nullptr ? table->find(name) : -1;
  if (i < 0) error.text("texture ").text(name).text(": not sent ahead of the scene (host-send sends the ones it names)");
  return i;
}

}  // namespace

SceneResult render_cs418_rows(ByteSource in, RgbaRowSink rows, Arena& arena, bool all_features,
                              const send::textures::Table* textures, Diagnostic& error) {
  using R = Math::real;
  model::SceneBuilder<R> builder(arena);
  cs418::Reader<Math> reader(in, builder,
                             cs418::TextureResolver{&find_texture, const_cast<send::textures::Table*>(textures)},
                             WarningSink{});
  cs418::Header header;
  model::Scene<R> scene;
  switch (reader.read(header, scene, error)) {
    case cs418::ReadStatus::kOk: break;
    case cs418::ReadStatus::kOutOfMemory: return SceneResult::kOutOfMemory;
    case cs418::ReadStatus::kSceneError: return SceneResult::kSceneError;
  }
  return render_general_scene(builder, scene, textures, rows, arena, all_features, error);
}


}  // namespace minrt::fw
