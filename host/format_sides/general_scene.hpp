// A scene of the general tracer (CS418, miniRT, EASTRAY) set up for the
// driver: its arena, the model the reader filled, and the renderer over it.
#pragma once

#include <chrono>
#include <memory>

#include "formats/model/scene.hpp"
#include "formats/model/scene_builder.hpp"
#include "prepared_scene.hpp"
#include "render/general/render.hpp"
#include "scene_memory.hpp"
#include "texture_files.hpp"

namespace minrt::host {

const char* general_path_name(uint32_t path);

template <class M>
class GeneralScene : public PreparedScene {
 public:
  using R = typename M::real;
  using Clock = std::chrono::steady_clock;

  void render_row(int y, uint8_t* rgba) const override {
    renderer_.render_row(y, rgba);
    if (opaque)
      for (int x = 0; x < width; ++x) rgba[4 * x + 3] = 255;
  }

  ArenaStorage storage;
  model::Scene<R> model;
  std::unique_ptr<TextureFiles> textures;  // the pixels model.textures points into

  // Builds the BVH over `model` in `arena`; false when it does not fit.
  bool set_up(Arena& arena, const DriverOptions& options, Clock::time_point t_parse) {
    parse_seconds = std::chrono::duration<double>(Clock::now() - t_parse).count();
    const Clock::time_point t_build = Clock::now();
    if (!renderer_.setup(model, arena, options.seed, options.force_full, options.full_tree)) return false;
    build_seconds = std::chrono::duration<double>(Clock::now() - t_build).count();
    features = renderer_.features();
    path = general_path_name(renderer_.path());
    width = model.width;
    height = model.height;
    return true;
  }

  // The renderer set up, for the tests that compare its walks.
  general::Renderer<M>& renderer() { return renderer_; }

 private:
  general::Renderer<M> renderer_;
};

// Arena bytes for `lines` lines of scene text: the parse log and the final
// arrays take at most two records a line, the BVH a bounded amount per object.
template <class R>
std::size_t general_arena_bytes(std::size_t lines) {
  const std::size_t record = model::SceneBuilder<R>::record_bytes();
  return lines * (2 * record + 64) + general::bvh_footprint<R>(static_cast<uint32_t>(lines)) + (1u << 16);
}

// How one try at reading a scene into an arena went.
enum class Pass { kDone, kFull, kFailed };

// Runs `attempt(scene, arena, first, error)` on a fresh GeneralScene with an
// arena for `lines` lines (content_lines), doubling them while it reports
// kFull. `first` is true on the first try (warnings once). On kFull the
// attempt sets `error` to its "does not fit" line, which stands when the
// growths run out.
template <class M, class Attempt>
std::unique_ptr<PreparedScene> prepare_growing(std::size_t lines, const std::string& shown, std::string& error,
                                               Attempt attempt) {
  using R = typename M::real;
  for (int growth = 0;; ++growth, lines *= 2) {
    auto scene = std::make_unique<GeneralScene<M>>();
    if (!scene->storage.allocate(general_arena_bytes<R>(lines), shown, error)) return nullptr;
    Arena arena(scene->storage.bytes.get(), scene->storage.size);
    const Pass pass = attempt(*scene, arena, growth == 0, error);
    if (pass == Pass::kDone) return scene;
    if (pass == Pass::kFailed || growth == kMaxArenaGrowths) return nullptr;
  }
}

// The message line for a reader's located diagnostic.
inline std::string located_error(const std::string& name, const Diagnostic& d) {
  if (!d.has_pos) return name + ": error: " + d.message;
  return name + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": error: " + d.message;
}

}  // namespace minrt::host
