#include "jaworski_board.hpp"

#include "board_math.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "render/jaworski/tracer.hpp"

namespace minrt::fw {

namespace {

// Items (objects, lights, surfaces, mixture parts) a scene may have on the
// board: about 0.4 MB of arena in float.
constexpr int32_t kCapacity = 4096;

}  // namespace


SceneResult render_jaworski_rows(ByteSource in, RgbaRowSink rows, Arena& arena, Diagnostic& error) {
  using R = Math::real;
  jaworski::Scene<R> scene;
  if (!scene.allocate(arena, kCapacity)) {
    error.text("no room for the scene tables");
    return SceneResult::kOutOfMemory;
  }
  jaworski::Reader<Math> reader(in, scene);
  if (!reader.read(error)) return SceneResult::kSceneError;
  uint8_t* row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width));
  if (row == nullptr) {
    error.text("image row does not fit in the board's memory");
    return SceneResult::kOutOfMemory;
  }
  const jaworski::Tracer<Math> tracer(scene, arena);
  if (!tracer.ready()) {
    error.text("no room for the sphere hierarchy");
    return SceneResult::kOutOfMemory;
  }
  tracer.render(rows, row);
  return SceneResult::kOk;
}


}  // namespace minrt::fw
