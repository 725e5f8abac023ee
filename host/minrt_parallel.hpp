// The min-rt tracer's rows on several threads. The workers take bands of
// rows in order from a shared counter (minrt_band_rows: smaller towards the
// end, so that they finish together) and render them with a tracer of their
// own (its tables point into its own object array, which the ray loops
// write) through Tracer::render_rows, which gives every band the bytes of
// the one-thread render (render/sld/band_rows.hpp). The calling thread's
// worker uses the tracer prepare_sld set up; the others set theirs up in
// their own threads. The rows where two bands meet are traced once and
// handed over when they are ready (RowExchange), and finished rows go to the sink in order as
// soon as the rows above them are done (RowsInOrder).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <memory>
#include <mutex>
#include <new>
#include <system_error>
#include <thread>
#include <vector>

#include "core/base/arena.hpp"
#include "core/image/row_sink.hpp"
#include "render/sld/tracer.hpp"
#include "thread_count.hpp"

namespace minrt::host {

// Rows in the band that starts at row y0: half of each worker's share of
// what is left, so that the bands shrink towards the end and the workers
// finish together, at most 24 and at least 8: where two bands meet, the
// later one traces the shared rows first thing and the earlier one needs
// them last, and with shorter bands it would often find them still being
// traced and trace them too.
inline int minrt_band_rows(int height, int threads, int y0) {
  return std::clamp((height - y0) / (2 * threads), 8, 24);
}

// Rows traced in full that two workers need (SharedRows): one slot per row.
// The first worker to ask traces the row and gives a copy of its state; the
// second copies it out, or traces the row too if it is still being traced:
// no worker ever waits for another, which may have lost its core.
class RowExchange {
 public:
  explicit RowExchange(int height) : states_(static_cast<size_t>(height)), copies_(static_cast<size_t>(height)) {}
  ~RowExchange() {
    for (unsigned char* c : copies_) delete[] c;
    for (unsigned char* c : spare_) delete[] c;
  }
  RowExchange(const RowExchange&) = delete;
  RowExchange& operator=(const RowExchange&) = delete;

  SharedRows shared() {
    SharedRows r;
    r.ctx = this;
    r.take = [](void* c, int row, void* pixels, size_t pixel_bytes, void* slots, size_t slot_bytes) {
      return static_cast<RowExchange*>(c)->take(static_cast<size_t>(row), pixels, pixel_bytes, slots, slot_bytes);
    };
    r.give = [](void* c, int row, const void* pixels, size_t pixel_bytes, const void* slots, size_t slot_bytes) {
      static_cast<RowExchange*>(c)->give(static_cast<size_t>(row), pixels, pixel_bytes, slots, slot_bytes);
    };
    return r;
  }

 private:
  // kFree -> kTracing (the first taker) -> kReady (given) -> kTaken; or
  // kTracing -> kTaken when the second taker traces it too, or no memory was
  // left for the copy.
  enum : int { kFree, kTracing, kReady, kTaken };

  bool take(size_t row, void* pixels, size_t pixel_bytes, void* slots, size_t slot_bytes) {
    std::atomic<int>& state = states_[row];
    int s = kFree;
    if (state.compare_exchange_strong(s, kTracing, std::memory_order_acq_rel)) return false;
    if (s == kTracing && state.compare_exchange_strong(s, kTaken, std::memory_order_acq_rel)) return false;
    // A third taker (a one-row band) or no copy: trace it again.
    if (s != kReady || !state.compare_exchange_strong(s, kTaken, std::memory_order_acq_rel)) return false;
    unsigned char* copy = copies_[row];
    copies_[row] = nullptr;
    std::memcpy(pixels, copy, pixel_bytes);
    std::memcpy(slots, copy + pixel_bytes, slot_bytes);
    std::lock_guard<std::mutex> lock(spare_mutex_);
    spare_.push_back(copy);  // no allocation: reserved in give
    return true;
  }

  void give(size_t row, const void* pixels, size_t pixel_bytes, const void* slots, size_t slot_bytes) {
    std::atomic<int>& state = states_[row];
    if (state.load(std::memory_order_acquire) != kTracing) return;  // the other traces it too
    unsigned char* copy = nullptr;
    {
      std::lock_guard<std::mutex> lock(spare_mutex_);
      if (!spare_.empty()) {
        copy = spare_.back();
        spare_.pop_back();
      } else {
        try {
          spare_.reserve(++buffers_);  // take() can always put it back
          copy = new unsigned char[pixel_bytes + slot_bytes];
        } catch (const std::bad_alloc&) {
          copy = nullptr;
        }
      }
    }
    if (copy == nullptr) {
      state.store(kTaken, std::memory_order_release);
      return;
    }
    std::memcpy(copy, pixels, pixel_bytes);
    std::memcpy(copy + pixel_bytes, slots, slot_bytes);
    copies_[row] = copy;
    int s = kTracing;
    if (state.compare_exchange_strong(s, kReady, std::memory_order_acq_rel)) return;
    copies_[row] = nullptr;  // the other took to tracing it meanwhile
    std::lock_guard<std::mutex> lock(spare_mutex_);
    spare_.push_back(copy);
  }

  std::vector<std::atomic<int>> states_;
  std::vector<unsigned char*> copies_;  // written before kReady, read after
  std::mutex spare_mutex_;
  std::vector<unsigned char*> spare_;  // copies taken, to be reused
  size_t buffers_ = 0;
};

// Finished rows kept in one image buffer and handed to the sink in order:
// whichever worker finds the next rows done writes them, unless another is
// writing already; flush after the workers stop writes whatever is left.
class RowsInOrder {
 public:
  RowsInOrder(const RowSink& out, size_t row_bytes, int height, const RowSink* finished)
      : out_(out), row_bytes_(row_bytes), height_(height), finished_(finished) {}

  // Allocates the buffer; false when there is no memory for it.
  bool reserve() {
    try {
      image_.resize(row_bytes_ * static_cast<size_t>(height_));
      done_ = std::vector<std::atomic<bool>>(static_cast<size_t>(height_));
    } catch (const std::bad_alloc&) {
      return false;
    }
    return true;
  }

  void begin(int, int) {}  // the sink's begin and end are the renderer's
  void end() {}
  void row(int y, const uint8_t* rgb) {
    std::memcpy(image_.data() + static_cast<size_t>(y) * row_bytes_, rgb, row_bytes_);
    if (finished_ != nullptr) finished_->row(y, rgb);  // --show: as soon as it is done
    done_[static_cast<size_t>(y)].store(true, std::memory_order_release);
    flush();
  }

  void flush() {
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    for (; next_ < height_ && done_[static_cast<size_t>(next_)].load(std::memory_order_acquire); ++next_)
      out_.row(next_, image_.data() + static_cast<size_t>(next_) * row_bytes_);
  }

 private:
  const RowSink& out_;
  size_t row_bytes_;
  int height_;
  const RowSink* finished_;
  std::vector<uint8_t> image_;
  std::vector<std::atomic<bool>> done_;
  std::mutex mutex_;
  int next_ = 0;  // the first row not written yet
};

// Renders with `threads` workers (>= 2) into `out`; `first` is initialised
// for `scene` and prepared for bands (Tracer::prepare_bands) and renders on
// the calling thread. Returns false when memory for the image runs out
// (nothing is written then). A worker that cannot get memory for its tracer
// or a thread leaves its bands to the others.
template <MathPolicy M>
bool render_minrt_parallel(Tracer<M>& first, const Scene<typename M::real>& scene, int width, int height,
                           int threads, const RowSink& out, const RowSink* finished = nullptr) {
  RowsInOrder rows(out, static_cast<size_t>(width) * 3, height, finished);
  if (!rows.reserve()) return false;
  const RowSink into_rows = row_sink_of(rows);
  RowExchange exchange(height);
  const SharedRows shared = exchange.shared();
  std::atomic<int> next{0};
  auto work = [&](Tracer<M>& t) {
    // Each worker's bands go down the image, as render_rows needs.
    for (int y0 = next.load(std::memory_order_relaxed);;) {
      if (y0 >= height) return;
      const int y1 = std::min(height, y0 + minrt_band_rows(height, threads, y0));
      if (next.compare_exchange_weak(y0, y1, std::memory_order_relaxed)) {
        t.render_rows(y0, y1, into_rows, shared);
        y0 = next.load(std::memory_order_relaxed);
      }
    }
  };
  const size_t bytes = Tracer<M>::arena_bytes(scene, width) + Tracer<M>::band_bytes(width);
  auto helper = [&] {
    std::unique_ptr<Tracer<M>> tracer(new (std::nothrow) Tracer<M>());
    std::unique_ptr<unsigned char[]> memory(new (std::nothrow) unsigned char[bytes]);
    if (tracer == nullptr || memory == nullptr) return;
    Arena arena(memory.get(), bytes);
    if (tracer->init(scene, width, height, arena) && tracer->prepare_bands(arena)) work(*tracer);
  };

  out.begin(width, height);
  std::vector<std::thread> pool;
  try {
    for (int i = 1; i < threads; ++i) pool.emplace_back(helper);
  } catch (const std::exception&) {
    // Fewer threads than asked (system_error, or no memory for the list).
  }
  work(first);
  for (std::thread& t : pool) t.join();
  rows.flush();
  out.end();
  return true;
}

}  // namespace minrt::host
