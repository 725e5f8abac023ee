// CS418 scene text for the tests that drive the renderer directly: the
// text read into a Scene in an arena, and a fan of triangles to add to a
// scene (crossing the spheres the tests scatter in front of the eye).
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <memory>
#include <ostream>
#include <string>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/model/scene_builder.hpp"

namespace minrt::test {

template <class M>
model::Scene<typename M::real> read_scene(const std::string& text, Arena& arena) {
  model::SceneBuilder<typename M::real> builder(arena);
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  cs418::Reader<M> reader(mem.source(), builder, cs418::TextureResolver{}, WarningSink{});
  cs418::Header header;
  model::Scene<typename M::real> scene;
  Diagnostic d;
  REQUIRE(reader.read(header, scene, d) == cs418::ReadStatus::kOk);
  REQUIRE(builder.finish(scene));
  return scene;
}

// The scene with the arena it lives in (64 MB: the tests' scenes and
// their trees fit with room to spare).
template <class M>
struct SceneInArena {
  std::unique_ptr<unsigned char[]> storage;
  Arena arena;
  model::Scene<typename M::real> scene;
  explicit SceneInArena(const std::string& text, size_t bytes = size_t{64} << 20)
      : storage(new unsigned char[bytes]), arena(storage.get(), bytes), scene(read_scene<M>(text, arena)) {}
};

// `count` triangles, the i-th moved `spread * i * step` along x.
inline void append_triangle_fan(std::ostream& s, int count, double step, double spread) {
  for (int i = 0; i < count; ++i) {
    const double a = i * step;
    s << "xyz " << spread * a - 1.5 << " -1.2 " << -2.0 - 0.3 * (i % 3) << '\n';
    s << "xyz " << spread * a - 1.2 << " 0.4 " << -2.5 - 0.2 * (i % 4) << '\n';
    s << "xyz " << spread * a - 1.0 << " -0.5 " << -3.0 << '\n';
    s << "tri -3 -2 -1\n";
  }
}

}  // namespace minrt::test
