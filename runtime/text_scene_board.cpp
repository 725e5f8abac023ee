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

namespace {

TextSceneResult result_of(MinirtResult r) {
  switch (r) {
    case MinirtResult::kOk: return TextSceneResult::kOk;
    case MinirtResult::kSceneError: return TextSceneResult::kSceneError;
    case MinirtResult::kOutOfMemory: return TextSceneResult::kOutOfMemory;
  }
  return TextSceneResult::kSceneError;
}

TextSceneResult result_of(EastrayResult r) {
  switch (r) {
    case EastrayResult::kOk: return TextSceneResult::kOk;
    case EastrayResult::kSceneError: return TextSceneResult::kSceneError;
    case EastrayResult::kOutOfMemory: return TextSceneResult::kOutOfMemory;
  }
  return TextSceneResult::kSceneError;
}

}  // namespace

TextSceneResult render_text_scene_rows(const send::text::TextScene& scene, RgbaRowSink rows, Arena& arena, int width,
                                       int height, bool all_features, Diagnostic& error) {
  if (scene.format == MINRT_SCENE_FORMAT_JAWORSKI) {
    MemorySource text{scene.bytes, scene.size};
    switch (render_jaworski_rows(text.source(), rows, arena, error)) {
      case JaworskiResult::kOk: return TextSceneResult::kOk;
      case JaworskiResult::kSceneError: return TextSceneResult::kSceneError;
      case JaworskiResult::kOutOfMemory: return TextSceneResult::kOutOfMemory;
    }
    return TextSceneResult::kSceneError;
  }
  if (scene.format == MINRT_SCENE_FORMAT_EASTRAY)
    return result_of(render_eastray_rows(reinterpret_cast<const char*>(scene.bytes), scene.size, rows, arena, error));
  // CS418, miniRT: the textures, when the scene names any, come first (the preamble
  // the raw protocol sends too), read where they lie.
  send::textures::Table* textures = nullptr;
  size_t at = 0;
  if (scene.size > 0 && scene.bytes[0] == MINRT_TEXTURES_MARKER) {
    textures = arena.alloc_zeroed<send::textures::Table>(1);
    if (textures == nullptr) {
      error.text("no room for the texture table");
      return TextSceneResult::kOutOfMemory;
    }
    size_t used = 0;
    if (!send::textures::view(scene.bytes + 1, scene.size - 1, *textures, used, error))
      return TextSceneResult::kSceneError;
    at = 1 + used;
  }
  MemorySource text{scene.bytes + at, scene.size - at};
  if (scene.format == MINRT_SCENE_FORMAT_MINIRT)
    return result_of(render_minirt_rows(text.source(), rows, arena, width, height, all_features, textures, error));
  switch (render_cs418_rows(text.source(), rows, arena, all_features, textures, error)) {
    case Cs418Result::kOk: return TextSceneResult::kOk;
    case Cs418Result::kSceneError: return TextSceneResult::kSceneError;
    case Cs418Result::kOutOfMemory: return TextSceneResult::kOutOfMemory;
  }
  return TextSceneResult::kSceneError;
}

TextSceneResult stream_text_scene(const send::text::TextScene& scene, ByteSink out, Arena& arena, int width,
                                  int height, bool all_features, Diagnostic& error) {
  if (scene.format == MINRT_SCENE_FORMAT_JAWORSKI) {
    BmpWriter bmp(out);
    return render_text_scene_rows(scene, rgba_row_sink_of(bmp), arena, width, height, all_features, error);
  }
  PngStoredWriter png(out);
  return render_text_scene_rows(scene, rgba_row_sink_of(png), arena, width, height, all_features, error);
}

}  // namespace minrt::fw
