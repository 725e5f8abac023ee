#include "image_window.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
  const int n = ready_rows_.fetch_add(1, std::memory_order_acq_rel) + 1;
  if (hold_at_half_ && n >= (height_ + 1) / 2 && n < height_) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return partial_done_ || abandoned_; });
  }
  throttle();
}

void LiveWindow::release_producers() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (partial_done_) return;
    partial_done_ = true;
  }
  changed_.notify_all();
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

// Writes w x h pixels of `surface` (any format) as a P6 file.
bool save_snapshot(const SdlLibrary& sdl, SDL_Surface* surface, int w, int h, const char* path) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  if (sdl.LockSurface(surface) != 0) return false;
  const int converted = sdl.ConvertPixels(w, h, surface->format->format, surface->pixels, surface->pitch,
                                          SDL_PIXELFORMAT_RGB24, rgb.data(), w * 3);
  sdl.UnlockSurface(surface);
  if (converted != 0) return false;
  std::FILE* f = std::fopen(path, "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", w, h);
  const bool ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  return std::fclose(f) == 0 && ok;
}

// The largest rectangle of the image's aspect centred in a window of ww x wh.
SDL_Rect letterbox(int w, int h, int ww, int wh) {
  SDL_Rect r{0, 0, ww, wh};
  if (static_cast<long long>(ww) * h > static_cast<long long>(wh) * w) {
    r.w = static_cast<int>(static_cast<long long>(wh) * w / h);
    r.x = (ww - r.w) / 2;
  } else {
    r.h = static_cast<int>(static_cast<long long>(ww) * h / w);
    r.y = (wh - r.h) / 2;
  }
  return r;
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
  hold_at_half_ = std::getenv("MINRT_SHOW_PARTIAL_SNAPSHOT") != nullptr;
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
  // However the window ends, producers held for the partial snapshot go on.
  struct Release {
    LiveWindow* w;
    ~Release() { w->release_producers(); }
  } release{this};
  std::string unused;
  const SdlLibrary& sdl = *load_sdl(unused);  // loaded by open()
  // The render's Ctrl-C must stay the render's (SDL would turn it into a
  // quit event for a window nobody may be looking at).
  sdl.SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  // The image is blitted onto the window's own surface: without these SDL
  // backs that surface with an OpenGL texture, and loading Mesa (and its
  // LLVM) delayed the window by over a second.
  sdl.SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  sdl.SetHint(SDL_HINT_RENDER_DRIVER, "software");
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
  // The rows shown so far, black until they come.
  SDL_Surface* image = window != nullptr ? sdl.CreateRGBSurfaceWithFormat(0, w, h, 24, SDL_PIXELFORMAT_RGB24) : nullptr;
  if (image == nullptr) {
    const std::string program = title.substr(0, title.find(':'));
    std::fprintf(stderr, "%s: warning: not showing the image: cannot open a window (%s)\n", program.c_str(),
                 sdl.GetError());
    if (window != nullptr) sdl.DestroyWindow(window);
    sdl.Quit();
    return;
  }
  sdl.FillRect(image, nullptr, 0);
  // Draws the image onto the window's surface, scaled to fit with its aspect
  // kept; the surface is asked for each time, as a resize replaces it.
  auto draw = [&]() -> SDL_Surface* {
    SDL_Surface* screen = sdl.GetWindowSurface(window);
    if (screen == nullptr) return nullptr;
    sdl.FillRect(screen, nullptr, 0);
    SDL_Rect to = letterbox(w, h, screen->w, screen->h);
    sdl.UpperBlitScaled(image, nullptr, screen, &to);
    return screen;
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
  for (bool first = true;; first = false) {
    // Events are polled, never waited for: SDL's wait on X11 wakes itself
    // with an event sent over a second connection to the server, which may
    // handle it after this thread's connection has destroyed the window;
    // the BadWindow then goes to Xlib's default handler, which ends the
    // process with status 1.
    if (!first) std::this_thread::sleep_for(std::chrono::milliseconds(kPollMs));
    SDL_Event e;
    bool quit = false;
    while (sdl.PollEvent(&e) != 0) {
      if (e.type == SDL_QUIT) quit = true;
      else if (e.type == SDL_KEYDOWN && (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q)) quit = true;
      else if (e.type == SDL_WINDOWEVENT) redraw = true;  // exposed, resized, restored: the image again
    }
    if (quit) {
      // The renderer stops at its next row when the window was its only
      // output (closed()); the window goes at once either way.
      closed_.store(true, std::memory_order_release);
      break;
    }
    bool finished, abandoned;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      finished = finished_;
      abandoned = abandoned_;
    }
    if (abandoned) break;
    const auto now = Clock::now();
    // The partial snapshot is due once half the rows are in (publish holds
    // the producers there).
    const bool partial_due = partial != nullptr && ready_rows_.load(std::memory_order_acquire) >= (h + 1) / 2;
    if ((now - last >= period || finished || partial_due) && shown_rows < h) {
      last = now;
      // Copy the rows that became ready.
      for (int y = 0; y < h; ++y) {
        if (shown[y] != 0 || rows_[y].load(std::memory_order_acquire) != kReady) continue;
        shown[y] = 1;
        std::memcpy(static_cast<uint8_t*>(image->pixels) + static_cast<size_t>(y) * image->pitch,
                    pixels_.data() + static_cast<size_t>(y) * w * 3, static_cast<size_t>(w) * 3);
        ++shown_rows;
        redraw = true;
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
    if (partial != nullptr && complete) partial = nullptr;  // every row came at once: no mid-render frame
    if (partial == nullptr) release_producers();
    if (!redraw && !snap && !partial_due) continue;
    redraw = false;
    SDL_Surface* screen = draw();
    // Snapshots read the window's surface back when it has the image's
    // size (it does until someone resizes it), else the image itself.
    SDL_Surface* shot = screen != nullptr && screen->w == w && screen->h == h ? screen : image;
    if (partial_due && !complete) {
      if (!save_snapshot(sdl, shot, w, h, partial)) {
        snapshot_ok_ = false;
        snapshot_error_ = std::string("cannot save the snapshot ") + partial;
      }
      partial = nullptr;
    }
    if (partial == nullptr) release_producers();
    if (snap) {
      if (!save_snapshot(sdl, shot, w, h, snapshot)) {
        snapshot_ok_ = false;
        snapshot_error_ = std::string("cannot save the snapshot ") + snapshot;
      }
      break;
    }
    if (screen != nullptr) sdl.UpdateWindowSurface(window);
  }
  sdl.FreeSurface(image);
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
