#include "sdl_library.hpp"

#if MINRT_HAVE_SDL2
#include "shared_library.hpp"

namespace minrt::host {

const SdlLibrary* load_sdl(std::string& why) {
  return load_library_once<SdlLibrary>(
      "libSDL2-2.0.so.0", "SDL2",
      [](SdlLibrary& library, SymbolBinder& bind) {
#define MINRT_SDL_LOAD(name) bind(library.name, "SDL_" #name);
        MINRT_SDL_FUNCTIONS(MINRT_SDL_LOAD)
#undef MINRT_SDL_LOAD
      },
      why);
}

}  // namespace minrt::host
#endif
