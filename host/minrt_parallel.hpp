// The min-rt tracer's rows on several threads. Each worker takes bands of
// rows in order from a shared counter and renders them with a tracer of its
// own, initialised from the scene (the tracer's tables point into its own
// object array, which the ray loops write), and its own pixel lines (Tracer::render_rows
// replays the rows above a band, so every band comes out as the one-thread
// render makes it). The rows are kept and handed to the sink in order at the
// end.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

#include "core/base/arena.hpp"
#include "core/image/row_sink.hpp"
#include "render/minrt/tracer.hpp"
#include "thread_count.hpp"

namespace minrt::host {

// Rows a worker takes at a time: every worker replays the geometry of the
// rows above its band, and a band's two boundary rows are traced twice when
// the neighbouring worker has not handed them over yet, so bands are not
// tiny, yet short enough that the last one leaves no core idle for long.
inline int minrt_band_rows(int height, int threads) {
  return std::clamp(height / (threads * 16), 4, 16);
}

// Rows the workers hand over (SharedRows): one slot per row, filled once by
// the worker whose band starts there and emptied by the one whose band
// ends there.
class RowExchange {
 public:
  explicit RowExchange(int height) : slots_(static_cast<size_t>(height)) {}
  ~RowExchange() {
    for (auto& s : slots_) delete[] s.exchange(nullptr);
  }
  SharedRows shared() {
    SharedRows r;
    r.ctx = this;
    r.give = [](void* c, int row, const void* pixels, size_t bytes) {
      auto* copy = new (std::nothrow) unsigned char[bytes];
      if (copy == nullptr) return;  // the taker traces the row itself
      std::memcpy(copy, pixels, bytes);
      delete[] static_cast<RowExchange*>(c)->slots_[static_cast<size_t>(row)].exchange(copy, std::memory_order_acq_rel);
    };
    r.take = [](void* c, int row, void* pixels, size_t bytes) {
      unsigned char* copy = static_cast<RowExchange*>(c)->slots_[static_cast<size_t>(row)].exchange(nullptr, std::memory_order_acq_rel);
      if (copy == nullptr) return false;
      std::memcpy(pixels, copy, bytes);
      delete[] copy;
      return true;
    };
    return r;
  }

 private:
  std::vector<std::atomic<unsigned char*>> slots_;
};

// Renders with `threads` workers (>= 2) into `out`. Returns false when memory
// for the copies runs out (nothing is written then).
template <MathPolicy M>
bool render_minrt_parallel(const Scene<typename M::real>& scene, int width, int height, int threads,
                           const RowSink& out, const RowSink* finished = nullptr) {
  const size_t row_bytes = static_cast<size_t>(width) * 3;
  std::vector<uint8_t> image;
  struct Worker {
    std::unique_ptr<Tracer<M>> tracer;
    std::unique_ptr<unsigned char[]> memory;
  };
  std::vector<Worker> workers(static_cast<size_t>(threads));
  const size_t bytes = Tracer<M>::arena_bytes(scene, width);
  try {
    image.resize(row_bytes * static_cast<size_t>(height));
  } catch (const std::bad_alloc&) {
    return false;
  }
  for (Worker& w : workers) {
    w.tracer.reset(new (std::nothrow) Tracer<M>());
    w.memory.reset(new (std::nothrow) unsigned char[bytes]);
    if (w.tracer == nullptr || w.memory == nullptr) return false;
    Arena arena(w.memory.get(), bytes);
    if (!w.tracer->init(scene, width, height, arena)) return false;
  }

  struct Rows {
    uint8_t* image;
    size_t row_bytes;
    const RowSink* finished;
    void begin(int, int) {}
    void row(int y, const uint8_t* rgb) {
      std::memcpy(image + static_cast<size_t>(y) * row_bytes, rgb, row_bytes);
      if (finished != nullptr) finished->row(y, rgb);  // --show: as soon as it is done
    }
    void end() {}
  } rows{image.data(), row_bytes, finished};
  const RowSink into_image = row_sink_of(rows);
  const int band = minrt_band_rows(height, threads);
  RowExchange exchange(height);
  const SharedRows shared = exchange.shared();
  std::atomic<int> next{0};
  auto work = [&](Tracer<M>& t) {
    // fetch_add hands each worker increasing bands, as render_rows needs.
    for (int y0; (y0 = next.fetch_add(band)) < height;)
      t.render_rows(y0, std::min(y0 + band, height), into_image, shared);
  };
  std::vector<std::thread> pool;
  try {
    for (int i = 1; i < threads; ++i) pool.emplace_back(work, std::ref(*workers[static_cast<size_t>(i)].tracer));
  } catch (const std::system_error&) {
    // Fewer threads than asked: the bands go to those that started.
  }
  work(*workers[0].tracer);
  for (std::thread& t : pool) t.join();

  out.begin(width, height);
  for (int y = 0; y < height; ++y) out.row(y, image.data() + static_cast<size_t>(y) * row_bytes);
  out.end();
  return true;
}

}  // namespace minrt::host
