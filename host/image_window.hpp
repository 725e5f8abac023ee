// The --show window (SDL2), live: rows appear as they are rendered or as
// they arrive from the board, in any order, so a user can watch the image
// being drawn; once it is complete it stays until closed. ESC, q and the
// close button close it at once (the render goes on and the file is still
// written, unless the window was the only output: closed());
// resizing, covering or minimising keep the image. The image is blitted
// onto the window's own surface (no OpenGL: the window appears in a few
// tens of milliseconds). Without a display,
// open() says why in one line and the caller goes on without a window.
//
// Threads: SDL lives on a thread of its own, which looks for events every
// kPollMs and redraws at most kRefreshHz times a second. Producers hand
// rows over through a shared buffer with a per-row ready flag (each row is
// written once, then published with a release store), so a render never
// waits on the window.
//
// For tests: MINRT_SHOW_SNAPSHOT=FILE.ppm saves what the window shows once
// the image is complete and closes it; MINRT_SHOW_PARTIAL_SNAPSHOT=FILE.ppm
// saves the frame drawn once half the rows have been handed over, holding
// the producers there until it is saved (so it never depends on how fast
// the window opens or the rows come); and
// MINRT_SHOW_ROW_DELAY_MS=N makes every row hand-over sleep N ms, so that
// a test can catch the image half drawn.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "png_io.hpp"

namespace minrt::host {

class LiveWindow {
 public:
  static constexpr int kRefreshHz = 30;
  // How often the window's thread looks for the user's events: ESC or the
  // close button is seen within this many milliseconds.
  static constexpr int kPollMs = 10;

  LiveWindow() = default;
  LiveWindow(const LiveWindow&) = delete;
  LiveWindow& operator=(const LiveWindow&) = delete;
  ~LiveWindow();  // closes the window without waiting for the user

  // Starts the window's thread and its display connection; the window
  // itself appears with begin(). False with the reason when there is no
  // display (or SDL2 is not built in).
  bool open(const std::string& title, std::string& why);
  bool is_open() const { return thread_.joinable(); }

  // The image's size; rows before it are ignored. Call once.
  void begin(int width, int height);
  // Row y (0 = top) as RGBA (shown over black) or RGB. Any thread, any
  // order; a row given twice keeps its first pixels.
  void row_rgba(int y, const uint8_t* rgba);
  void row_rgb(int y, const uint8_t* rgb);
  // Every row not given yet, from a whole top-first RGBA image (for images
  // that could not be followed live).
  void fill(const RgbaImage& image);
  int width() const { return width_.load(std::memory_order_acquire); }
  int height() const { return height_; }

  // The image is complete: wait() then returns when the user closes the
  // window. False when a requested snapshot could not be saved.
  bool finish_and_wait(std::string& why);
  // Something failed: close the window now.
  void abandon();
  // The user closed the window (ESC, q or the close button). A renderer
  // whose only output is the window checks this after each row and stops.
  bool closed() const { return closed_.load(std::memory_order_acquire); }
  const std::atomic<bool>* closed_flag() const { return &closed_; }

 private:
  void run(std::string title, std::shared_ptr<std::promise<std::string>> started);
  uint8_t* claim(int y);
  void publish(int y);
  void throttle() const;
  void release_producers();

  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool began_ = false, finished_ = false, abandoned_ = false;  // under mutex_
  std::atomic<int> width_{0};
  int height_ = 0;
  std::vector<uint8_t> pixels_;                   // RGB, top row first
  std::unique_ptr<std::atomic<uint8_t>[]> rows_;  // 0 empty, 1 being written, 2 ready
  int delay_ms_ = 0;
  std::atomic<bool> closed_{false};
  std::atomic<int> ready_rows_{0};  // rows handed over
  bool hold_at_half_ = false;       // MINRT_SHOW_PARTIAL_SNAPSHOT is set
  bool partial_done_ = false;       // under mutex_: the producers may go on
  bool snapshot_ok_ = true;
  std::string snapshot_error_;
};

// Shows a finished image until the user closes the window. False with the
// reason when there is no window to be had; the caller warns and goes on.
bool show_image(const RgbaImage& image, const std::string& title, std::string& why);

}  // namespace minrt::host
