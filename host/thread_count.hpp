// How many threads render a scene's rows, shared by every format's driver.
#pragma once

#include <algorithm>
#include <thread>

namespace minrt::host {

// `requested` 0: every core. Never more threads than rows, never fewer than one.
inline int minrt_thread_count(int requested, int height) {
  int n = requested > 0 ? requested : static_cast<int>(std::thread::hardware_concurrency());
  return std::clamp(n, 1, std::max(height, 1));
}

}  // namespace minrt::host
