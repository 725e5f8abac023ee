#include "tiff_io.hpp"

#include <tiffio.h>
#include <unistd.h>

#include <algorithm>

#include "shared_library.hpp"

namespace minrt::host {

namespace {

// libtiff loaded at the first TIFF written (dlopen), not linked: with the
// seven compression libraries it pulls in, loading it cost every minrt run
// about 0.8 ms of CPU, a few percent of a small render that never writes a
// TIFF. The headers still come from the build's libtiff-dev.
struct TiffLibrary {
#define MINRT_TIFF_FUNCTIONS(X) X(TIFFFdOpen) X(TIFFSetField) X(TIFFWriteScanline) X(TIFFClose)
#define MINRT_TIFF_POINTER(name) decltype(&::name) name = nullptr;
  MINRT_TIFF_FUNCTIONS(MINRT_TIFF_POINTER)
#undef MINRT_TIFF_POINTER
};

// The library's functions, loaded once; null with the reason if it is not
// installed.
const TiffLibrary* load_tiff(std::string& why) {
  return load_library_once<TiffLibrary>(
      MINRT_TIFF_SONAME, "libtiff",
      [](TiffLibrary& library, SymbolBinder& bind) {
#define MINRT_TIFF_LOAD(name) bind(library.name, #name);
        MINRT_TIFF_FUNCTIONS(MINRT_TIFF_LOAD)
#undef MINRT_TIFF_LOAD
      },
      why);
}

// The reading side, loaded on its own at the first TIFF read.
struct TiffReadLibrary {
#define MINRT_TIFF_READ_FUNCTIONS(X) \
  X(TIFFOpen) X(TIFFGetField) X(TIFFReadRGBAImageOriented) X(TIFFClose) X(TIFFSetErrorHandler) X(TIFFSetWarningHandler)
#define MINRT_TIFF_POINTER(name) decltype(&::name) name = nullptr;
  MINRT_TIFF_READ_FUNCTIONS(MINRT_TIFF_POINTER)
#undef MINRT_TIFF_POINTER
};

const TiffReadLibrary* load_tiff_reader(std::string& why) {
  return load_library_once<TiffReadLibrary>(
      MINRT_TIFF_SONAME, "libtiff",
      [](TiffReadLibrary& library, SymbolBinder& bind) {
#define MINRT_TIFF_LOAD(name) bind(library.name, #name);
        MINRT_TIFF_READ_FUNCTIONS(MINRT_TIFF_LOAD)
#undef MINRT_TIFF_LOAD
      },
      why);
}

// A map larger than this (per side) is refused before its pixels are read.
constexpr uint32_t kMaxTiffSide = 16384;

}  // namespace

bool read_tiff_rgb(const std::string& path, int& width, int& height, std::vector<uint8_t>& rgb, std::string& error) {
  const TiffReadLibrary* lib = load_tiff_reader(error);
  if (lib == nullptr) return false;
  // libtiff's own messages would go to stderr; the reason is ours.
  lib->TIFFSetErrorHandler(nullptr);
  lib->TIFFSetWarningHandler(nullptr);
  TIFF* t = lib->TIFFOpen(path.c_str(), "r");
  if (t == nullptr) {
    error = "cannot open it as a TIFF file";
    return false;
  }
  uint32_t w = 0, h = 0;
  lib->TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &w);
  lib->TIFFGetField(t, TIFFTAG_IMAGELENGTH, &h);
  if (w == 0 || h == 0 || w > kMaxTiffSide || h > kMaxTiffSide) {
    lib->TIFFClose(t);
    error = "TIFF image size " + std::to_string(w) + "x" + std::to_string(h) + " is not 1 to " +
            std::to_string(kMaxTiffSide) + " a side";
    return false;
  }
  std::vector<uint32_t> rgba(static_cast<std::size_t>(w) * h);
  if (lib->TIFFReadRGBAImageOriented(t, w, h, rgba.data(), ORIENTATION_TOPLEFT, 0) == 0) {
    lib->TIFFClose(t);
    error = "libtiff cannot decode the TIFF image";
    return false;
  }
  lib->TIFFClose(t);
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  rgb.resize(rgba.size() * 3);
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    rgb[3 * i] = static_cast<uint8_t>(TIFFGetR(rgba[i]));
    rgb[3 * i + 1] = static_cast<uint8_t>(TIFFGetG(rgba[i]));
    rgb[3 * i + 2] = static_cast<uint8_t>(TIFFGetB(rgba[i]));
  }
  return true;
}

bool write_tiff_rgb(std::FILE* f, int width, int height, const std::vector<uint8_t>& rgb,
                    std::string& error) {
  const TiffLibrary* lib = load_tiff(error);
  if (lib == nullptr) return false;
  std::fflush(f);
  const int fd = ::dup(fileno(f));  // TIFFClose closes its descriptor; the caller keeps f
  TIFF* t = fd < 0 ? nullptr : lib->TIFFFdOpen(fd, "output", "w");
  if (t == nullptr) {
    if (fd >= 0) ::close(fd);
    error = "libtiff cannot open the file";
    return false;
  }
  lib->TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(width));
  lib->TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(height));
  lib->TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 3);
  lib->TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8);
  lib->TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
  lib->TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  lib->TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
  lib->TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  lib->TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 1);
  std::vector<uint8_t> row(static_cast<std::size_t>(width) * 3);
  for (int y = 0; y < height; ++y) {
    std::copy_n(rgb.data() + static_cast<std::size_t>(y) * width * 3, row.size(), row.data());
    if (lib->TIFFWriteScanline(t, row.data(), static_cast<uint32_t>(y), 0) < 0) {
      lib->TIFFClose(t);
      error = "libtiff write error";
      return false;
    }
  }
  lib->TIFFClose(t);
  return true;
}

}  // namespace minrt::host
