#include "image_window.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <future>

#include "sdl_library.hpp"

namespace minrt::host {

namespace {

constexpr int kEmpty = 0, kWriting = 1, kReady = 2;

}  // namespace

LiveWindow::~LiveWindow() { abandon(); }

void LiveWindow::begin(int width, int height) {
  if (!is_open() || width <= 0 || height <= 0) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (began_) return;
    height_ = height;
    pixels_.assign(static_cast<size_t>(width) * height * 3, 0);
    rows_.reset(new std::atomic<uint8_t>[static_cast<size_t>(height)]);
    for (int y = 0; y < height; ++y) rows_[y].store(kEmpty, std::memory_order_relaxed);
    began_ = true;
    width_.store(width, std::memory_order_release);  // rows may come from now on
  }
  changed_.notify_all();
}

// The row's pixels if this caller is the first to give row y, else null.
uint8_t* LiveWindow::claim(int y) {
  const int w = width_.load(std::memory_order_acquire);
  if (w == 0 || y < 0 || y >= height_) return nullptr;
  uint8_t expected = kEmpty;
  if (!rows_[y].compare_exchange_strong(expected, kWriting, std::memory_order_acquire)) return nullptr;
  return pixels_.data() + static_cast<size_t>(y) * w * 3;
}

void LiveWindow::publish(int y) {
  rows_[y].store(kReady, std::memory_order_release);
  throttle();
}

void LiveWindow::throttle() const {
  if (delay_ms_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms_));
}

void LiveWindow::row_rgba(int y, const uint8_t* rgba) {
  uint8_t* out = claim(y);
  if (out == nullptr) return;
  for (int x = 0, w = width(); x < w; ++x)
    for (int c = 0; c < 3; ++c)
      out[3 * x + c] = static_cast<uint8_t>((rgba[4 * x + c] * rgba[4 * x + 3] + 127) / 255);
  publish(y);
}

void LiveWindow::row_rgb(int y, const uint8_t* rgb) {
  uint8_t* out = claim(y);
  if (out == nullptr) return;
  for (int i = 0, n = 3 * width(); i < n; ++i) out[i] = rgb[i];
  publish(y);
}

void LiveWindow::fill(const RgbaImage& image) {
  if (image.width != width() || image.height != height_) return;
  const int saved = delay_ms_;
  delay_ms_ = 0;
  for (int y = 0; y < image.height; ++y) row_rgba(y, image.rgba.data() + static_cast<size_t>(y) * image.width * 4);
  delay_ms_ = saved;
}

void LiveWindow::abandon() {
  if (!is_open()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    abandoned_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

bool LiveWindow::finish_and_wait(std::string& why) {
  if (!is_open()) return true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    finished_ = true;
  }
  changed_.notify_all();
  thread_.join();
  if (!snapshot_ok_) why = snapshot_error_;
  return snapshot_ok_;
}

#if MINRT_HAVE_SDL2

namespace {

bool save_snapshot(const SdlLibrary& sdl, SDL_Renderer* renderer, int w, int h, const char* path) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  SDL_Rect all{0, 0, w, h};
  if (sdl.RenderReadPixels(renderer, &all, SDL_PIXELFORMAT_RGB24, rgb.data(), w * 3) != 0) return false;
  std::FILE* f = std::fopen(path, "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", w, h);
  const bool ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

bool LiveWindow::open(const std::string& title, std::string& why) {
  if (is_open()) return true;
  if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr &&
      std::getenv("SDL_VIDEODRIVER") == nullptr) {
    why = "no display (DISPLAY is not set)";
    return false;
  }
  if (load_sdl(why) == nullptr) return false;
  if (const char* d = std::getenv("MINRT_SHOW_ROW_DELAY_MS")) delay_ms_ = std::atoi(d);
  auto started = std::make_shared<std::promise<std::string>>();
  std::future<std::string> result = started->get_future();
  thread_ = std::thread(&LiveWindow::run, this, title, started);
  why = result.get();
  if (!why.empty()) {
    thread_.join();
    return false;
  }
  return true;
}

void LiveWindow::run(std::string title, std::shared_ptr<std::promise<std::string>> started) {
  std::string unused;
  const SdlLibrary& sdl = *load_sdl(unused);  // loaded by open()
  // The render's Ctrl-C must stay the render's (SDL would turn it into a
  // quit event for a window nobody may be looking at).
  sdl.SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  if (sdl.Init(SDL_INIT_VIDEO) != 0) {
    started->set_value(std::string("no display (") + sdl.GetError() + ")");
    return;
  }
  // SDL falls back to drivers that show nothing (offscreen, dummy): a
  // window there would wait for a key nobody can press.
  const char* driver = sdl.GetCurrentVideoDriver();
  const std::string name = driver != nullptr ? driver : "";
  if (name != "x11" && name != "wayland" && name != "kmsdrm" && name != "cocoa" && name != "windows") {
    sdl.Quit();
    started->set_value("no display (SDL video driver '" + name + "'; set DISPLAY or run under a desktop)");
    return;
  }
  started->set_value("");

  // The window appears when the size is known.
  int w = 0, h = 0;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return began_ || abandoned_ || finished_; });
    if (!began_) {
      lock.unlock();
      sdl.Quit();
      return;
    }
    w = width_.load(std::memory_order_relaxed);
    h = height_;
  }
  SDL_Window* window =
      sdl.CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, w, h, SDL_WINDOW_RESIZABLE);
  SDL_Renderer* renderer = window != nullptr ? sdl.CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
  SDL_Texture* texture =
      renderer != nullptr ? sdl.CreateTexture(renderer, SDL_PIXELFORMAT_RGB24, SDL_TEXTUREACCESS_STATIC, w, h) : nullptr;
  if (texture == nullptr) {
    const std::string program = title.substr(0, title.find(':'));
    std::fprintf(stderr, "%s: warning: not showing the image: cannot open a window (%s)\n", program.c_str(),
                 sdl.GetError());
    if (renderer != nullptr) sdl.DestroyRenderer(renderer);
    if (window != nullptr) sdl.DestroyWindow(window);
    sdl.Quit();
    return;
  }
  {
    const std::vector<uint8_t> black(static_cast<size_t>(w) * h * 3, 0);
    sdl.UpdateTexture(texture, nullptr, black.data(), w * 3);
  }
  sdl.RenderSetLogicalSize(renderer, w, h);  // keeps the aspect when resized
  auto draw = [&] {
    sdl.SetRenderDrawColor(renderer, 0, 0, 0, 255);
    sdl.RenderClear(renderer);
    sdl.RenderCopy(renderer, texture, nullptr, nullptr);
  };
  const char* snapshot = std::getenv("MINRT_SHOW_SNAPSHOT");
  const char* partial = std::getenv("MINRT_SHOW_PARTIAL_SNAPSHOT");
  std::vector<uint8_t> shown(static_cast<size_t>(h), 0);
  int shown_rows = 0, titled_rows = -1;
  bool complete_titled = false;
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::milliseconds(1000 / kRefreshHz);
  auto last = Clock::now() - period;
  bool redraw = true;
  for (;;) {
    SDL_Event e;
    bool quit = false;
    // Complete: nothing changes but what the user does.
    const bool idle = shown_rows == h && complete_titled;
    if ((idle ? sdl.WaitEvent(&e) : sdl.WaitEventTimeout(&e, static_cast<int>(period.count()))) != 0) {
      do {
        if (e.type == SDL_QUIT) quit = true;
        else if (e.type == SDL_KEYDOWN && (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q)) quit = true;
        else if (e.type == SDL_WINDOWEVENT) redraw = true;  // exposed, resized, restored: the image again
      } while (sdl.PollEvent(&e) != 0);
    }
    bool finished, abandoned;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished = finished_;
      abandoned = abandoned_;
    }
    if (quit || abandoned) break;
    const auto now = Clock::now();
    if ((now - last >= period || finished) && shown_rows < h) {
      last = now;
      // Upload the rows that became ready, in runs of neighbours.
      for (int y = 0; y < h;) {
        if (shown[y] != 0 || rows_[y].load(std::memory_order_acquire) != kReady) {
          ++y;
          continue;
        }
        int end = y;
        while (end < h && shown[end] == 0 && rows_[end].load(std::memory_order_acquire) == kReady) shown[end++] = 1;
        SDL_Rect rect{0, y, w, end - y};
        sdl.UpdateTexture(texture, &rect, pixels_.data() + static_cast<size_t>(y) * w * 3, w * 3);
        shown_rows += end - y;
        redraw = true;
        y = end;
      }
      if (shown_rows != titled_rows && shown_rows < h) {
        titled_rows = shown_rows;
        const std::string t = title + " (" + std::to_string(shown_rows) + " of " + std::to_string(h) + " rows)";
        sdl.SetWindowTitle(window, t.c_str());
      }
    }
    const bool complete = shown_rows == h;
    if (complete && finished && !complete_titled) {
      complete_titled = true;
      sdl.SetWindowTitle(window, title.c_str());
    }
    const bool snap = snapshot != nullptr && complete && finished;
    if (!redraw && !snap) continue;
    redraw = false;
    draw();
    if (partial != nullptr && shown_rows > 0 && !complete) {
      if (!save_snapshot(sdl, renderer, w, h, partial)) {
        snapshot_ok_ = false;
        snapshot_error_ = std::string("cannot save the snapshot ") + partial;
      }
      partial = nullptr;
    }
    if (snap) {
      if (!save_snapshot(sdl, renderer, w, h, snapshot)) {
        snapshot_ok_ = false;
        snapshot_error_ = std::string("cannot save the snapshot ") + snapshot;
      }
      break;
    }
    sdl.RenderPresent(renderer);
  }
  sdl.DestroyTexture(texture);
  sdl.DestroyRenderer(renderer);
  sdl.DestroyWindow(window);
  sdl.Quit();
}

#else

bool LiveWindow::open(const std::string&, std::string& why) {
  why = "built without SDL2 (install libsdl2-dev and rebuild)";
  return false;
}

void LiveWindow::run(std::string, std::shared_ptr<std::promise<std::string>>) {}

#endif

bool show_image(const RgbaImage& image, const std::string& title, std::string& why) {
  LiveWindow window;
  if (!window.open(title, why)) return false;
  window.begin(image.width, image.height);
  window.fill(image);
  return window.finish_and_wait(why);
}

}  // namespace minrt::host
