// The general tracer on the board, as the CS418 and miniRT boards run it
// once their reader has parsed the scene: the textures host-send sent ahead
// (protocol/texture_blobs.hpp) become the scene's texture table, the scene
// is finished, the tracer set up, and every row rendered through one RGBA
// row buffer in the arena.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "board_math.hpp"
#include "core/base/arena.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "formats/model/scene_builder.hpp"
#include "protocol/texture_blobs.hpp"
#include "render/general/render.hpp"

namespace minrt::fw {

// False when the arena is too small, with the message in `error`.
inline bool render_general_scene(model::SceneBuilder<Math::real>& builder, model::Scene<Math::real>& scene,
                                 const send::textures::Table* textures, RgbaRowSink rows, Arena& arena,
                                 bool all_features, Diagnostic& error) {
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
      (row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width))) == nullptr) {
    error.text("scene does not fit in the board's memory (").number(static_cast<int64_t>(arena.capacity())).text(
        " bytes)");
    return false;
  }
  renderer.render(rows, row);
  return true;
}

}  // namespace minrt::fw
