#include "cs418_board.hpp"

#include "core/image/png_writer.hpp"
#include "core/math/math_portable.hpp"
#include "core/math/math_rv32f.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "render/general/render.hpp"

namespace minrt::fw {

namespace {

#if MINRT_FW_HW_SQRT
using Math = PortableFloatHwSqrt;
#else
using Math = PortableFloat;
#endif

int32_t no_textures(void*, const char* name, Diagnostic& error) {
  error.text("texture ").text(name).text(": textures reach the board only over the framed protocol (not yet)");
  return -1;
}

}  // namespace

Cs418Result render_cs418(ByteSource in, ByteSink out, Arena& arena, bool all_features, Diagnostic& error) {
  using R = Math::real;
  model::SceneBuilder<R> builder(arena);
  cs418::Reader<Math> reader(in, builder, cs418::TextureResolver{&no_textures, nullptr}, WarningSink{});
  cs418::Header header;
  model::Scene<R> scene;
  switch (reader.read(header, scene, error)) {
    case cs418::ReadStatus::kOk: break;
    case cs418::ReadStatus::kOutOfMemory: return Cs418Result::kOutOfMemory;
    case cs418::ReadStatus::kSceneError: return Cs418Result::kSceneError;
  }
  general::Renderer<Math> renderer;
  uint8_t* row = nullptr;
  if (!builder.finish(scene) || !renderer.setup(scene, arena, 1, all_features) ||
      (row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width))) == nullptr) {
    error.text("scene does not fit in the board's memory (").number(static_cast<int64_t>(arena.capacity())).text(
        " bytes)");
    return Cs418Result::kOutOfMemory;
  }
  PngStoredWriter png(out);
  renderer.render(rgba_row_sink_of(png), row);
  return Cs418Result::kOk;
}

}  // namespace minrt::fw
