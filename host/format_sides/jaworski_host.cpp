// Jaworski's keyword scenes on the host: read with the original's rules,
// traced operation for operation (render/jaworski), written as the
// original's BMP under the scene's name with .bmp unless -o says otherwise.
#include "jaworski_host.hpp"

#include <cstdint>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "image_file_output.hpp"
#include "math_policy_dispatch.hpp"
#include "render/jaworski/tracer.hpp"
#include "scene_memory.hpp"

namespace minrt::host {

namespace {

template <class M>
class JaworskiScene final : public PreparedScene {
 public:
  using R = typename M::real;
  void render_row(int y, uint8_t* rgba) const override {
    tracer->render_row(height - 1 - y, rgba);  // the tracer counts rows from the bottom, as the BMP stores them
  }
  ArenaStorage storage;
  jaworski::Scene<R> scene;
  std::unique_ptr<jaworski::Tracer<M>> tracer;
};

template <class M>
std::unique_ptr<PreparedScene> prepare_with(const SceneInput& in, std::string& error) {
  using R = typename M::real;
  // Every item takes at least two bytes that are neither blank nor in a
  // comment (a guess too small grows below).
  int64_t capacity = static_cast<int64_t>(content_bytes_outside_comments(in.text, '#') / 2 + 4);
  for (int growth = 0;; ++growth, capacity *= 2) {
    if (capacity > INT32_MAX / 2) capacity = INT32_MAX / 2;
    const auto n = static_cast<int32_t>(capacity);
    auto s = std::make_unique<JaworskiScene<M>>();
    const std::size_t bytes = static_cast<std::size_t>(n) * (sizeof(jaworski::Object<R>) + sizeof(jaworski::Light<R>) +
                                                             sizeof(jaworski::SurfaceNode<R>) + sizeof(jaworski::Part<R>)) +
                              jaworski::Tracer<M>::arena_bytes(n, n) + 4096;
    if (!s->storage.allocate(bytes, in.shown, error)) return nullptr;
    Arena arena(s->storage.bytes.get(), s->storage.size);
    if (!s->scene.allocate(arena, n)) {
      error = in.shown + ": error: scene does not fit in memory";
      return nullptr;
    }
    MemorySource mem{reinterpret_cast<const uint8_t*>(in.text.data()), in.text.size()};
    jaworski::Reader<M> reader(mem.source(), s->scene);
    Diagnostic d;
    if (!reader.read(d)) {
      if (d.out_of_memory && growth < kMaxArenaGrowths) continue;
      error = in.shown + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": error: " + d.message;
      return nullptr;
    }
    s->tracer = std::make_unique<jaworski::Tracer<M>>(s->scene, arena);
    if (!s->tracer->ready()) {
      error = in.shown + ": error: scene does not fit in memory";
      return nullptr;
    }
    s->width = s->scene.width;
    s->height = s->scene.height;
    s->output_name = in.path == "-" ? "-" : jaworski_output_name(in.path);
    s->path = "operation for operation (render/jaworski)";
    s->rows_final = true;
    return s;
  }
}

}  // namespace

std::string jaworski_output_name(const std::string& scene_path) { return with_extension(scene_path, ".bmp"); }

std::unique_ptr<PreparedScene> prepare_jaworski(const SceneInput& in, const DriverOptions& options,
                                                const WarningSink&, std::string& error) {
  std::unique_ptr<PreparedScene> scene;
  with_math_policy(options.variant, [&]<class M>() { scene = prepare_with<M>(in, error); });
  return scene;
}

}  // namespace minrt::host
