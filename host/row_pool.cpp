#include "row_pool.hpp"

#include <thread>
#include <vector>

#include "image_window.hpp"
#include "thread_count.hpp"

namespace minrt::host {

int render_rows(const PreparedScene& scene, int threads, RgbaImage& image, LiveWindow* window,
                const std::atomic<bool>* stop, WorkProgress* progress) {
  image.width = scene.width;
  image.height = scene.height;
  image.rgba.assign(static_cast<std::size_t>(scene.width) * scene.height * 4, 0);
  const int n = minrt_thread_count(threads, scene.height);
  const bool live = window != nullptr && window->is_open();
  if (live) window->begin(scene.width, scene.height);
  std::atomic<int> next{0};
  auto work = [&] {
    for (int y; (y = next.fetch_add(1, std::memory_order_relaxed)) < scene.height;) {
      if (stop != nullptr && stop->load(std::memory_order_acquire)) return;
      uint8_t* row = image.rgba.data() + static_cast<std::size_t>(y) * scene.width * 4;
      scene.render_row(y, row);
      if (live) window->row_rgba(y, row);
      if (progress != nullptr) progress->add();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < n; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return n;
}

}  // namespace minrt::host
