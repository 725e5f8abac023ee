// SDL2 loaded when a window is first asked for (dlopen), not linked: the
// library pulls in some fifty others (X11, Wayland, sound), whose loading
// took about 5 ms of every minrt run, most of a small render.
#pragma once

#if MINRT_HAVE_SDL2
#include <SDL.h>

#include <string>

namespace minrt::host {

struct SdlLibrary {
#define MINRT_SDL_FUNCTIONS(X)                                                                              \
  X(SetHint) X(Init) X(GetError) X(GetCurrentVideoDriver) X(Quit) X(CreateWindow) X(DestroyWindow)         \
  X(GetWindowSurface) X(UpdateWindowSurface) X(CreateRGBSurfaceWithFormat) X(FreeSurface) X(UpperBlitScaled) \
  X(FillRect) X(LockSurface) X(UnlockSurface) X(ConvertPixels) X(PollEvent) X(SetWindowTitle)
#define MINRT_SDL_POINTER(name) decltype(&::SDL_##name) name = nullptr;
  MINRT_SDL_FUNCTIONS(MINRT_SDL_POINTER)
#undef MINRT_SDL_POINTER
};

// The library's functions, loaded once; null with the reason if it is not
// installed.
const SdlLibrary* load_sdl(std::string& why);

}  // namespace minrt::host
#endif
