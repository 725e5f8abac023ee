#include "row_pool.hpp"

#include <thread>
#include <vector>

#include "image_window.hpp"
#include "row_file_writer.hpp"
#include "thread_count.hpp"

namespace minrt::host {

int render_rows(const PreparedScene& scene, int threads, RgbaImage& image, LiveWindow* window,
                const std::atomic<bool>* stop, RowFileWriter* file, WorkProgress* progress) {
  image.width = scene.width;
  image.height = scene.height;
  const int n = minrt_thread_count(threads, scene.height);
  const bool live = window != nullptr && window->is_open();
  // Zeroing the image before the threads start costs a serial page fault
  // for every 4 KiB, which a file written as it goes does not need.
  const bool keep = file == nullptr || live;
  const std::size_t row_bytes = static_cast<std::size_t>(scene.width) * 4;
  if (keep) image.rgba.assign(row_bytes * scene.height, 0);
  else image.rgba.clear();
  if (live) window->begin(scene.width, scene.height);
  std::atomic<int> next{0};
  auto work = [&] {
    std::vector<uint8_t> own(keep ? 0 : row_bytes);
    for (int y; (y = next.fetch_add(1, std::memory_order_relaxed)) < scene.height;) {
      if (stop != nullptr && stop->load(std::memory_order_acquire)) return;
      uint8_t* row = keep ? image.rgba.data() + static_cast<std::size_t>(y) * row_bytes : own.data();
      scene.render_row(y, row);
      if (live) window->row_rgba(y, row);
      if (file != nullptr) file->row(y, row);
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
