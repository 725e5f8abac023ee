// The PNG texture loader (libpng behind host/png_io.cpp) on arbitrary bytes,
// read from memory: it decodes or refuses with a reason, never crashes, and
// never decodes more pixels than its bound, whatever the header claims (the
// bound is checked on the header, before any pixel is inflated).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "png_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 16;  // small: a bomb shows as a refusal
  if (size == 0) return 0;
  std::FILE* f = ::fmemopen(const_cast<uint8_t*>(data), size, "rb");
  if (f == nullptr) return 0;
  minrt::host::RgbaImage img;
  std::string error;
  if (!minrt::host::read_png(f, img, error, kMaxPixels)) {  // closes f
    if (error.empty()) std::abort();
    return 0;
  }
  const std::uint64_t pixels = static_cast<std::uint64_t>(img.width) * static_cast<std::uint64_t>(img.height);
  if (img.width < 1 || img.height < 1 || pixels > kMaxPixels || img.rgba.size() != pixels * 4) std::abort();
  return 0;
}
