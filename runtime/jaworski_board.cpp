#include "jaworski_board.hpp"

#include "core/image/bmp_writer.hpp"
#include "board_math.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "render/jaworski/tracer.hpp"

namespace minrt::fw {

namespace {

// Items (objects, lights, surfaces, mixture parts) a scene may have on the
// board: about 0.4 MB of arena in float.
constexpr int32_t kCapacity = 4096;

bool same(const char* a, const char* b) {
  while (*a != 0 && *a == *b) ++a, ++b;
  return *a == *b;
}

}  // namespace

bool is_jaworski_start(int first_byte, const char* first_word) {
  if (first_byte == '#') return true;  // neither SLD nor CS418 has comments
  static constexpr const char* kWords[] = {"imwidth", "imheight", "canvwidth", "canvheight", "depth",
                                           "bgcolor", "raydepth", "lights",    "objects"};
  for (const char* w : kWords)
    if (same(first_word, w)) return true;
  return false;
}

JaworskiResult render_jaworski_rows(ByteSource in, RgbaRowSink rows, Arena& arena, Diagnostic& error) {
  using R = Math::real;
  jaworski::Scene<R> scene;
  if (!scene.allocate(arena, kCapacity)) {
    error.text("no room for the scene tables");
    return JaworskiResult::kOutOfMemory;
  }
  jaworski::Reader<Math> reader(in, scene);
  if (!reader.read(error)) return JaworskiResult::kSceneError;
  uint8_t* row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width));
  if (row == nullptr) {
    error.text("image row does not fit in the board's memory");
    return JaworskiResult::kOutOfMemory;
  }
  const jaworski::Tracer<Math> tracer(scene, arena);
  if (!tracer.ready()) {
    error.text("no room for the sphere hierarchy");
    return JaworskiResult::kOutOfMemory;
  }
  tracer.render(rows, row);
  return JaworskiResult::kOk;
}

JaworskiResult render_jaworski(ByteSource in, ByteSink out, Arena& arena, Diagnostic& error) {
  BmpWriter bmp(out);
  return render_jaworski_rows(in, rgba_row_sink_of(bmp), arena, error);
}

}  // namespace minrt::fw
