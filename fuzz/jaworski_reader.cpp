// Jaworski's reader and tracer on arbitrary bytes: the reader accepts or
// refuses with a located message, never crashes; an accepted small scene
// renders (shallow ray depth) without reading out of bounds.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "formats/jaworski/jaworski_reader.hpp"
#include "reader_fuzzing.hpp"
#include "render/jaworski/tracer.hpp"

namespace {

template <class M>
void read_one(const uint8_t* data, size_t size) {
  using R = typename M::real;
  minrt::Arena arena = fuzzing::arena_once<M>();
  minrt::jaworski::Scene<R> scene;
  if (!scene.allocate(arena, 2048)) std::abort();
  minrt::MemorySource mem{data, size};
  minrt::jaworski::Reader<M> reader(mem.source(), scene);
  minrt::Diagnostic d;
  if (!reader.read(d)) {
    fuzzing::require_message(d, true);
    return;
  }
  if (static_cast<int64_t>(scene.width) * scene.height > 256 || scene.ray_depth > 8) return;
  std::vector<uint8_t> row(static_cast<size_t>(scene.width) * 4);
  const minrt::jaworski::Tracer<M> tracer(scene, arena);
  if (!tracer.ready()) std::abort();  // 4 MB holds the tables of 2048 items and the hierarchy
  for (int y = 0; y < scene.height; ++y) {
    tracer.render_row(y, row.data());
    for (int x = 0; x < scene.width; ++x)
      if (row[4 * x + 3] != 255) std::abort();
  }
}

}  // namespace

MINRT_FUZZ_BOTH_POLICIES(read_one)
