#include "text_scene_board.hpp"

#include <minrt/serial_protocol.h>

#include "core/image/bmp_writer.hpp"
#include "core/image/png_writer.hpp"
#include "cs418_board.hpp"
#include "eastray_board.hpp"
#include "jaworski_board.hpp"
#include "minirt_board.hpp"
#include "protocol/texture_blobs.hpp"

namespace minrt::fw {

SceneResult render_text_scene_rows(const send::text::TextScene& scene, RgbaRowSink rows, Arena& arena, int width,
                                   int height, bool all_features, Diagnostic& error) {
  if (scene.format == MINRT_SCENE_FORMAT_JAWORSKI) {
    MemorySource text{scene.bytes, scene.size};
    return render_jaworski_rows(text.source(), rows, arena, error);
  }
  // CS418, miniRT, EASTRAY: the textures, when the scene names any, come first (the preamble
  // the raw protocol sends too), read where they lie.
  send::textures::Table* textures = nullptr;
  size_t at = 0;
  if (scene.size > 0 && scene.bytes[0] == MINRT_TEXTURES_MARKER) {
    textures = arena.alloc_zeroed<send::textures::Table>(1);
    if (textures == nullptr) {
      error.text("no room for the texture table");
      return SceneResult::kOutOfMemory;
    }
    size_t used = 0;
    if (!send::textures::view(scene.bytes + 1, scene.size - 1, *textures, used, error))
      return SceneResult::kSceneError;
    at = 1 + used;
  }
  if (scene.format == MINRT_SCENE_FORMAT_EASTRAY)
    return render_eastray_rows(reinterpret_cast<const char*>(scene.bytes + at), scene.size - at, rows, arena, textures,
                               error);
  MemorySource text{scene.bytes + at, scene.size - at};
  if (scene.format == MINRT_SCENE_FORMAT_MINIRT)
    return render_minirt_rows(text.source(), rows, arena, width, height, all_features, textures, error);
  return render_cs418_rows(text.source(), rows, arena, all_features, textures, error);
}

SceneResult stream_text_scene(const send::text::TextScene& scene, ByteSink out, Arena& arena, int width,
                              int height, bool all_features, Diagnostic& error) {
  if (scene.format == MINRT_SCENE_FORMAT_JAWORSKI) {
    BmpWriter bmp(out);
    return render_text_scene_rows(scene, rgba_row_sink_of(bmp), arena, width, height, all_features, error);
  }
  PngStoredWriter png(out);
  return render_text_scene_rows(scene, rgba_row_sink_of(png), arena, width, height, all_features, error);
}

}  // namespace minrt::fw
