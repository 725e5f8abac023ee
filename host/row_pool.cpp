#include "row_pool.hpp"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <system_error>

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

// Threads that render rows beside the calling thread, each for one
// render. start_row_threads starts them before the scene is parsed, so that
// they are running when its rows are ready: a helper then starts on them
// at once, without the cost of a thread's start (more than a small
// scene's serial part) or of a sleeping thread's wake-up. A helper ends
// as soon as no rows are left, while the caller finishes the file, and
// so is not in the way of the process's exit.
class Helpers {
 public:
  using Job = void (*)(void* context);

  // Makes sure that `count` helpers are waiting for the next render.
  void start(int count) {
    std::lock_guard<std::mutex> lock(start_mutex_);
    for (; waiting_ < count; ++waiting_) {
      // A bare thread: std::thread's state is freed by the thread at its
      // end, and that first free set up a heap of the helper's own (four
      // memory-map calls after its last row, the unmaps interrupting the
      // core that commits the file).
      const unsigned seen = generation_.load(std::memory_order_relaxed);
      pthread_attr_t attr;
      pthread_attr_init(&attr);
      pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
      if (first_place_elsewhere(attr)) placed_ = true;  // stays set: allowed_ is known
      pthread_t id;
      void* arg = reinterpret_cast<void*>(static_cast<uintptr_t>(seen));
      const int err = pthread_create(&id, &attr, &Helpers::entry, arg);
      pthread_attr_destroy(&attr);
      if (err != 0) throw std::system_error(err, std::generic_category(), "cannot start a row thread");
    }
  }

  // Where a new helper first runs: on a core other than the calling
  // thread's. Left to itself, the kernel starts a new thread on its
  // creator's core whenever the other cores look no less busy (on a busy
  // machine, in about half the runs), and there it waits for the
  // creator, which renders rows, to give way: its first rows came 6 ms
  // after the creator's instead of 1.4 ms (2 threads, Jaworski's speed
  // scene, ordinary priority, machine load 5). The helper lifts the limit
  // as soon as it runs (`allowed_`), so that the kernel moves it as it
  // likes from then on. False, with `attr` untouched, where the calling
  // thread may run on one core only.
  bool first_place_elsewhere(pthread_attr_t& attr) {
    cpu_set_t allowed, others;
    const int here = sched_getcpu();
    if (here < 0 || pthread_getaffinity_np(pthread_self(), sizeof allowed, &allowed) != 0 ||
        !CPU_ISSET(here, &allowed) || CPU_COUNT(&allowed) < 2)
      return false;
    others = allowed;
    CPU_CLR(here, &others);
    if (pthread_attr_setaffinity_np(&attr, sizeof others, &others) != 0) return false;
    allowed_ = allowed;
    return true;
  }

  // Runs job(context) on the calling thread and on `count` helpers at the
  // same time; returns when every one has returned.
  void run(int count, Job job, void* context) {
    std::lock_guard<std::mutex> lock(run_mutex_);
    if (count > 0) {
      start(count);
      {
        std::lock_guard<std::mutex> started(start_mutex_);
        waiting_ -= count;  // the first `count` to claim a place take them
      }
      job_ = job;
      context_ = context;
      pending_.store(count, std::memory_order_relaxed);
      const unsigned generation = generation_.load(std::memory_order_relaxed) + 1;
      places_.store(uint64_t{generation} << 32 | static_cast<uint32_t>(count), std::memory_order_release);
      generation_.store(generation, std::memory_order_release);
      generation_.notify_all();
    }
    job(context);
    for (int left = pending_.load(std::memory_order_acquire); left != 0;) left = wait_for_change(pending_, left);
  }

 private:
  static void* entry(void* seen);
  void loop(unsigned seen) {
    {
      std::lock_guard<std::mutex> lock(start_mutex_);
      if (placed_) pthread_setaffinity_np(pthread_self(), sizeof allowed_, &allowed_);
    }
    for (;;) {
      seen = wait_for_change(generation_, seen);
      // A place in render `seen`, if one is left (more helpers may be
      // waiting than it takes); a later render's places are taken after
      // its generation is seen.
      uint64_t places = places_.load(std::memory_order_acquire);
      while (places >> 32 == seen && static_cast<uint32_t>(places) != 0 &&
             !places_.compare_exchange_weak(places, places - 1, std::memory_order_acq_rel))
        ;
      if (places >> 32 != seen || static_cast<uint32_t>(places) == 0) continue;
      job_(context_);
      if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1) pending_.notify_one();
      return;
    }
  }

  std::mutex start_mutex_, run_mutex_;
  int waiting_ = 0;  // helpers started and not yet given a place
  // The cores the helpers may run on once they run, known once a helper
  // was started elsewhere (first_place_elsewhere); under start_mutex_.
  cpu_set_t allowed_{};
  bool placed_ = false;
  // The current render, written before generation_ moves on.
  Job job_ = nullptr;
  void* context_ = nullptr;
  std::atomic<unsigned> generation_{0};
  // The current render's generation (high half) and its places not yet
  // taken (low half), so that a place is taken in one step.
  std::atomic<uint64_t> places_{0};
  std::atomic<int> pending_{0};  // helpers still on the current render
};

Helpers& helpers() {
  // Never destroyed: a helper waiting at exit for a render that does not
  // come holds on to it.
  static Helpers* pool = new Helpers;
  return *pool;
}

void* Helpers::entry(void* seen) {
  helpers().loop(static_cast<unsigned>(reinterpret_cast<uintptr_t>(seen)));
  return nullptr;
}

// Rows handed out at a time at most: a run of rows goes to the file with
// one write, which costs a fifth of writing its rows one by one.
constexpr std::size_t kRunBytes = 64 * 1024;

struct RowJob {
  const PreparedScene& scene;
  RgbaImage& image;
  LiveWindow* window;
  const std::atomic<bool>* stop;
  RowFileWriter* file;
  WorkProgress* progress;
  int threads;
  bool keep, live;
  std::size_t row_bytes;
  int run_rows;  // rows per hand-out at most
  std::atomic<int> next{0};

  static void run(void* context) noexcept { static_cast<RowJob*>(context)->rows(); }

  // The next rows to render, `count` of them from the one returned (-1:
  // none left). Runs shrink to single rows as the image nears its end,
  // so that the threads finish within a row of each other.
  int take(int& count) {
    int y = next.load(std::memory_order_relaxed);
    for (;;) {
      const int left = scene.height - y;
      if (left <= 0) return -1;
      count = std::clamp(left / (4 * threads), 1, run_rows);
      if (next.compare_exchange_weak(y, y + count, std::memory_order_relaxed)) return y;
    }
  }

  void rows() {
    // The file's rows on the thread's own stack: nothing to allocate
    // (a helper's first allocation sets up a heap of its own) or to give
    // back (unmapping memory that two threads have used interrupts both)
    // but for rows wider than a run.
    alignas(64) uint8_t stack_rows[kRunBytes];
    std::unique_ptr<uint8_t[]> wide_rows;
    uint8_t* own = stack_rows;
    if (file != nullptr && row_bytes > kRunBytes) {
      wide_rows = std::make_unique_for_overwrite<uint8_t[]>(row_bytes);
      own = wide_rows.get();
    }
    for (int y0, count; (y0 = take(count)) >= 0;) {
      uint8_t* run = keep ? image.rgba.data() + static_cast<std::size_t>(y0) * row_bytes : own;
      for (int i = 0; i < count; ++i) {
        if (stop != nullptr && stop->load(std::memory_order_acquire)) return;
        uint8_t* row = run + static_cast<std::size_t>(i) * row_bytes;
        scene.render_row(y0 + i, row);
        if (live) window->row_rgba(y0 + i, row);
        if (progress != nullptr) progress->add();
      }
      if (file == nullptr) continue;
      // The file's conversion is done in place: a kept image is copied first.
      if (run != own) std::memcpy(own, run, static_cast<std::size_t>(count) * row_bytes);
      file->rows(y0, count, own);
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
  const int run_rows = static_cast<int>(std::max<std::size_t>(1, kRunBytes / std::max<std::size_t>(row_bytes, 1)));
  RowJob job{scene, image, window, stop, file, progress, n, keep, live, row_bytes, run_rows};
  helpers().run(n - 1, &RowJob::run, &job);
  return n;
}

}  // namespace minrt::host
