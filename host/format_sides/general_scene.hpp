// A scene of the general tracer (CS418, miniRT, EASTRAY) set up for the
// driver: its arena, the model the reader filled, and the renderer over it.
#pragma once

#include <chrono>
#include <memory>

#include "formats/model/scene.hpp"
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

 private:
  general::Renderer<M> renderer_;
};

// The message line for a reader's located diagnostic.
inline std::string located_error(const std::string& name, const Diagnostic& d) {
  if (!d.has_pos) return name + ": error: " + d.message;
  return name + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": error: " + d.message;
}

}  // namespace minrt::host
