// What the host's drivers of the general tracer (CS418: general_render.cpp,
// miniRT: minirt_render.cpp) share around the parse: the one arena a scene's
// text needs, the renderer's set-up with its timings, and the rows rendered
// on several threads into the result's image, each also shown in the --show
// window as it is done.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "formats/model/scene_builder.hpp"
#include "general_render.hpp"
#include "image_window.hpp"
#include "thread_count.hpp"
#include "render/general/render.hpp"

namespace minrt::host {

// Arena bytes for scene text: the parse log and the final arrays take at
// most two records per line, the BVH a bounded amount per object.
template <class R>
std::size_t general_arena_bytes(const std::string& text) {
  std::size_t lines = 1;
  for (char c : text) lines += c == '\n';
  const std::size_t record = model::SceneBuilder<R>::record_bytes();
  return lines * (2 * record + 64) + general::bvh_footprint<R>(static_cast<uint32_t>(lines)) + (1u << 16);
}

// Renders every row of the set-up `renderer` into out.image (width x height
// RGBA) on options.threads threads (0: every core); sets out.threads and
// out.render_seconds too.
template <class M>
void render_general_rows(general::Renderer<M>& renderer, int width, int height, const GeneralOptions& options,
                         GeneralResult& out) {
  out.image.width = width;
  out.image.height = height;
  out.image.rgba.assign(static_cast<std::size_t>(width) * height * 4, 0);
  const int threads = minrt_thread_count(options.threads, height);
  const auto t0 = std::chrono::steady_clock::now();
  std::atomic<int> next{0};
  LiveWindow* window = options.window != nullptr && options.window->is_open() ? options.window : nullptr;
  if (window != nullptr) window->begin(width, height);
  auto work = [&] {
    for (int y; (y = next.fetch_add(1)) < height;) {
      if (options.cancel != nullptr && options.cancel->load(std::memory_order_acquire)) break;
      uint8_t* row = out.image.rgba.data() + static_cast<std::size_t>(y) * width * 4;
      renderer.render_row(y, row);
      if (window != nullptr) window->row_rgba(y, row);  // --show: as each row is done
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  out.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.threads = threads;
}

// After the parse (begun at `t_parse`): sets the renderer up over `scene`
// (its BVH in `arena`), records the times, features and path in `out`, and
// renders the rows. False when the BVH does not fit; the caller words that
// its format's way.
template <class M>
bool set_up_and_render(const model::Scene<typename M::real>& scene, Arena& arena, int width, int height,
                       const GeneralOptions& options, std::chrono::steady_clock::time_point t_parse,
                       GeneralResult& out) {
  using Clock = std::chrono::steady_clock;
  const auto seconds_since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  out.parse_seconds = seconds_since(t_parse);
  const Clock::time_point t_build = Clock::now();
  general::Renderer<M> renderer;
  if (!renderer.setup(scene, arena, options.seed, options.force_full, options.full_tree)) return false;
  out.build_seconds = seconds_since(t_build);
  out.features = renderer.features();
  out.path = general_path_name(renderer.path());
  render_general_rows(renderer, width, height, options, out);
  return true;
}

}  // namespace minrt::host
