#include "sdl_library.hpp"

#if MINRT_HAVE_SDL2
#include <dlfcn.h>

#include <mutex>

namespace minrt::host {

const SdlLibrary* load_sdl(std::string& why) {
  static SdlLibrary library;
  static std::string error;
  static std::once_flag once;
  std::call_once(once, [] {
    void* handle = dlopen("libSDL2-2.0.so.0", RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* e = dlerror();
      error = std::string("cannot load SDL2 (") + (e != nullptr ? e : "libSDL2-2.0.so.0") + ")";
      return;
    }
#define MINRT_SDL_LOAD(name)                                                           \
  library.name = reinterpret_cast<decltype(library.name)>(dlsym(handle, "SDL_" #name)); \
  if (library.name == nullptr && error.empty()) error = "SDL2 has no SDL_" #name;
    MINRT_SDL_FUNCTIONS(MINRT_SDL_LOAD)
#undef MINRT_SDL_LOAD
  });
  if (!error.empty()) {
    why = error;
    return nullptr;
  }
  return &library;
}

}  // namespace minrt::host
#endif
