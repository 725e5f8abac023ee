#include "image_window.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

#if MINRT_HAVE_SDL2
#include <SDL.h>
#endif

namespace minrt::host {

#if MINRT_HAVE_SDL2

namespace {

// What the window shows: the image composited over black, as RGB.
std::vector<uint8_t> over_black(const RgbaImage& image) {
  std::vector<uint8_t> rgb(static_cast<size_t>(image.width) * image.height * 3);
  for (size_t i = 0, n = static_cast<size_t>(image.width) * image.height; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      rgb[3 * i + c] = static_cast<uint8_t>((image.rgba[4 * i + c] * image.rgba[4 * i + 3] + 127) / 255);
  return rgb;
}

bool save_snapshot(SDL_Renderer* renderer, int w, int h, const char* path) {
  std::vector<uint8_t> rgb(static_cast<size_t>(w) * h * 3);
  SDL_Rect all{0, 0, w, h};
  if (SDL_RenderReadPixels(renderer, &all, SDL_PIXELFORMAT_RGB24, rgb.data(), w * 3) != 0) return false;
  std::FILE* f = std::fopen(path, "wb");
  if (f == nullptr) return false;
  std::fprintf(f, "P6\n%d %d\n255\n", w, h);
  const bool ok = std::fwrite(rgb.data(), 1, rgb.size(), f) == rgb.size();
  return std::fclose(f) == 0 && ok;
}

}  // namespace

bool show_image(const RgbaImage& image, const std::string& title, std::string& why) {
  if (std::getenv("DISPLAY") == nullptr && std::getenv("WAYLAND_DISPLAY") == nullptr &&
      std::getenv("SDL_VIDEODRIVER") == nullptr) {
    why = "no display (DISPLAY is not set)";
    return false;
  }
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    why = std::string("no display (") + SDL_GetError() + ")";
    return false;
  }
  // SDL falls back to drivers that show nothing (offscreen, dummy): a
  // window there would wait for a key nobody can press.
  const char* driver = SDL_GetCurrentVideoDriver();
  const std::string name = driver != nullptr ? driver : "";
  if (name != "x11" && name != "wayland" && name != "kmsdrm" && name != "cocoa" && name != "windows") {
    why = "no display (SDL video driver '" + name + "'; set DISPLAY or run under a desktop)";
    SDL_Quit();
    return false;
  }
  SDL_Window* window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, image.width,
                                        image.height, SDL_WINDOW_RESIZABLE);
  SDL_Renderer* renderer = window != nullptr ? SDL_CreateRenderer(window, -1, SDL_RENDERER_SOFTWARE) : nullptr;
  SDL_Texture* texture = renderer != nullptr ? SDL_CreateTexture(renderer, SDL_PIXELFORMAT_RGB24,
                                                                 SDL_TEXTUREACCESS_STATIC, image.width, image.height)
                                             : nullptr;
  if (texture == nullptr) {
    why = std::string("cannot open a window (") + SDL_GetError() + ")";
    if (renderer != nullptr) SDL_DestroyRenderer(renderer);
    if (window != nullptr) SDL_DestroyWindow(window);
    SDL_Quit();
    return false;
  }
  const std::vector<uint8_t> rgb = over_black(image);
  SDL_UpdateTexture(texture, nullptr, rgb.data(), image.width * 3);
  SDL_RenderSetLogicalSize(renderer, image.width, image.height);  // keeps the aspect when resized
  auto draw = [&] {
    SDL_SetRenderDrawColor(renderer, 0, 0, 0, 255);
    SDL_RenderClear(renderer);
    SDL_RenderCopy(renderer, texture, nullptr, nullptr);
  };
  const char* snapshot = std::getenv("MINRT_SHOW_SNAPSHOT");
  bool running = true;
  bool ok = true;
  draw();
  if (snapshot != nullptr) {
    ok = save_snapshot(renderer, image.width, image.height, snapshot);
    if (!ok) why = std::string("cannot save the snapshot ") + snapshot;
    running = false;
  }
  SDL_RenderPresent(renderer);
  while (running) {
    SDL_Event e;
    if (SDL_WaitEvent(&e) == 0) break;
    if (e.type == SDL_QUIT) running = false;
    else if (e.type == SDL_KEYDOWN && (e.key.keysym.sym == SDLK_ESCAPE || e.key.keysym.sym == SDLK_q)) running = false;
    else if (e.type == SDL_WINDOWEVENT) {
      draw();  // exposed, resized, restored: the image again
      SDL_RenderPresent(renderer);
    }
  }
  SDL_DestroyTexture(texture);
  SDL_DestroyRenderer(renderer);
  SDL_DestroyWindow(window);
  SDL_Quit();
  return ok;
}

#else

bool show_image(const RgbaImage&, const std::string&, std::string& why) {
  why = "minrt was built without SDL2 (install libsdl2-dev and rebuild)";
  return false;
}

#endif

}  // namespace minrt::host
