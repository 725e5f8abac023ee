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
#include "scene_result.hpp"

namespace minrt::fw {

// kOutOfMemory when the arena is too small; kSceneError when the scene
// read a texel of a sparse texture that was not sent (MINRT_UNSENT_TEXEL_ERROR:
// the rows before it went out, the rest do not); the message in `error`.
inline SceneResult render_general_scene(model::SceneBuilder<Math::real>& builder, model::Scene<Math::real>& scene,
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
  // Sparse textures: every texel read is checked against the tiles sent
  // (a scene off the path that has the check reads no texel).
  general::TexelWatch watch;
  if (count > 0 && textures->sparse)
    watch.entries = arena.alloc_zeroed<general::TexelWatch::Entry>(static_cast<size_t>(count));
  if ((count > 0 && table == nullptr) || (count > 0 && textures->sparse && watch.entries == nullptr) ||
      !builder.finish(scene) || !renderer.setup(scene, arena, 1, all_features) ||
      (row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width))) == nullptr) {
    error.text("scene does not fit in the board's memory (").number(static_cast<int64_t>(arena.capacity())).text(
        " bytes)");
    return SceneResult::kOutOfMemory;
  }
  if (watch.entries == nullptr) {
    renderer.render(rows, row);
    return SceneResult::kOk;
  }
  // Only the full path checks its reads; host-send chose the tiles on that
  // path, so another one here means the two disagree: ask for every texel.
  if (!renderer.can_watch_texels()) {
    error.text(MINRT_UNSENT_TEXEL_ERROR).text("sparse textures need the full render path");
    return SceneResult::kSceneError;
  }
  for (int i = 0; i < count; ++i) {
    const send::textures::Received& r = textures->items[i];
    const int32_t shift = r.form > 0 ? r.form - 1 : 0;
    watch.entries[i] = general::TexelWatch::Entry{
        r.rgb, r.width, nullptr, TileMask{r.tiles, tiles_along(static_cast<size_t>(r.width), shift), shift}};
  }
  watch.count = count;
  general::g_texel_watch = &watch;
  rows.begin(scene.width, scene.height);
  for (int y = 0; y < scene.height; ++y) {
    renderer.render_row_watched(y, row);
    if (watch.missed) {
      general::g_texel_watch = nullptr;
      error.text(MINRT_UNSENT_TEXEL_ERROR)
          .text("texture ")
          .text(textures->items[watch.miss_entry].name)
          .text(" at ")
          .number(watch.miss_col)
          .text(",")
          .number(watch.miss_row)
          .text(", row ")
          .number(y)
          .text(" of the image");
      return SceneResult::kSceneError;
    }
    rows.row(y, row);
  }
  rows.end();
  general::g_texel_watch = nullptr;
  return SceneResult::kOk;
}

}  // namespace minrt::fw
