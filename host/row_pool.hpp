// The one pool that renders a prepared scene's rows on several threads (0:
// every core), for every format but SLD, whose band renderer has its own
// (render_variants.cpp). Each thread takes the next rows (a run of them
// while many are left, one at a time toward the end); the image is the
// same for any thread count because rows do not depend on each other.
#pragma once

#include <atomic>

#include "posix/progress_line.hpp"

#include "png_io.hpp"
#include "prepared_scene.hpp"

namespace minrt::host {

class LiveWindow;
class RowFileWriter;

// Starts the threads that a later render_rows on `threads` (0: every core)
// renders with beside the calling thread, so that they are running when
// the rows are ready: call it before preparing the scene. render_rows
// starts any that are missing itself.
void start_row_threads(int threads);

// Renders every row of `scene` into `image` (resized), handing each to
// `window` as it is done when the window is open, to `file` (started) on
// the thread that rendered it, and counting it in `progress` when given.
// Returns the thread count used. `stop`, when set by another thread, ends
// the work early (the image is then incomplete). Rows that only `file`
// takes are not kept: `image` then has its size and no pixels, and each
// thread renders into a row of its own.
int render_rows(const PreparedScene& scene, int threads, RgbaImage& image, LiveWindow* window,
                const std::atomic<bool>* stop = nullptr, RowFileWriter* file = nullptr,
                WorkProgress* progress = nullptr);

}  // namespace minrt::host
