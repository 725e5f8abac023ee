#include "row_pool.hpp"

#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "image_window.hpp"
#include "row_file_writer.hpp"
#include "thread_count.hpp"

namespace minrt::host {

namespace {

using Clock = std::chrono::steady_clock;

// How long a new helper polls for its first rows before it sleeps: longer
// than a small scene takes to read and prepare, so that its rows start at
// once instead of after a wake-up (on a virtual machine an idle core can
// take tens of microseconds to wake), and short enough that a large scene's
// preparation does not keep a core busy. Also how long the calling thread
// polls for the helpers' last rows before it sleeps.
constexpr auto kPollTime = std::chrono::milliseconds(2);

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Polls `value` until it differs from `old` for at most kPollTime, then
// sleeps on it until it does.
template <class T>
T wait_for_change(const std::atomic<T>& value, T old) {
  T now = value.load(std::memory_order_acquire);
  const auto deadline = Clock::now() + kPollTime;
  for (int i = 1; now == old; ++i) {
    cpu_relax();
    now = value.load(std::memory_order_acquire);
    if (now == old && i % 256 == 0 && Clock::now() > deadline) {
      value.wait(old, std::memory_order_acquire);
      now = value.load(std::memory_order_acquire);
    }
  }
  return now;
}

// Threads that render rows beside the calling thread. They are started
// once (start_row_threads, or the first render) and live as long as the
// process, sleeping between renders: starting a thread costs more than a
// small scene's serial part, and a helper that is already running when the
// rows are ready starts on them at once. The pool is never destroyed, so a
// sleeping helper at exit holds nothing that the exit takes away.
class Helpers {
 public:
  using Job = void (*)(void* context, int thread);

  void start(int count) {
    std::lock_guard<std::mutex> lock(start_mutex_);
    for (; started_ < count; ++started_) std::thread(&Helpers::loop, this, started_ + 1).detach();
  }

  // Runs job(context, t) on the calling thread (t = 0) and on helpers
  // 1..count at the same time; returns when every one has returned.
  void run(int count, Job job, void* context) {
    std::lock_guard<std::mutex> lock(run_mutex_);
    start(count);
    if (count > 0) {
      job_ = job;
      context_ = context;
      count_ = count;
      pending_.store(count, std::memory_order_relaxed);
      generation_.fetch_add(1, std::memory_order_release);
      generation_.notify_all();
    }
    job(context, 0);
    for (int left = pending_.load(std::memory_order_acquire); left != 0;) left = wait_for_change(pending_, left);
  }

 private:
  void loop(int index) {
    unsigned seen = 0;
    for (;;) {
      seen = wait_for_change(generation_, seen);
      if (index > count_) continue;
      job_(context_, index);
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
    }
  }

  std::mutex start_mutex_, run_mutex_;
  int started_ = 0;
  // The current job, written before generation_ moves on.
  Job job_ = nullptr;
  void* context_ = nullptr;
  int count_ = 0;
  std::atomic<unsigned> generation_{0};
  std::atomic<int> pending_{0};  // helpers still on the current job
};

Helpers& helpers() {
  static Helpers* pool = new Helpers;  // never destroyed, see above
  return *pool;
}

struct RowJob {
  const PreparedScene& scene;
  RgbaImage& image;
  LiveWindow* window;
  const std::atomic<bool>* stop;
  RowFileWriter* file;
  WorkProgress* progress;
  bool keep, live;
  std::size_t row_bytes;
  uint8_t* own_rows;  // a row per thread when the image is not kept
  std::atomic<int> next{0};

  static void run(void* context, int thread) noexcept { static_cast<RowJob*>(context)->rows(thread); }

  void rows(int thread) {
    uint8_t* own = keep ? nullptr : own_rows + static_cast<std::size_t>(thread) * row_bytes;
    for (int y; (y = next.fetch_add(1, std::memory_order_relaxed)) < scene.height;) {
      if (stop != nullptr && stop->load(std::memory_order_acquire)) return;
      uint8_t* row = keep ? image.rgba.data() + static_cast<std::size_t>(y) * row_bytes : own;
      scene.render_row(y, row);
      if (live) window->row_rgba(y, row);
      if (file != nullptr) file->row(y, row);
      if (progress != nullptr) progress->add();
    }
  }
};

}  // namespace

void start_row_threads(int threads) { helpers().start(minrt_thread_count(threads, INT32_MAX) - 1); }

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
  // Every thread's own row taken here: a helper's first allocation would
  // set up a heap of its own first.
  std::vector<uint8_t> own_rows(keep ? 0 : row_bytes * static_cast<std::size_t>(n));
  RowJob job{scene, image, window, stop, file, progress, keep, live, row_bytes, own_rows.data()};
  helpers().run(n - 1, &RowJob::run, &job);
  return n;
}

}  // namespace minrt::host
