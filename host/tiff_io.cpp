#include "tiff_io.hpp"

#include <tiffio.h>
#include <unistd.h>

#include <algorithm>

namespace minrt::host {

bool write_tiff_rgb(std::FILE* f, int width, int height, const std::vector<uint8_t>& rgb,
                    std::string& error) {
  std::fflush(f);
  const int fd = ::dup(fileno(f));  // TIFFClose closes its descriptor; the caller keeps f
  TIFF* t = fd < 0 ? nullptr : TIFFFdOpen(fd, "output", "w");
  if (t == nullptr) {
    if (fd >= 0) ::close(fd);
    error = "libtiff cannot open the file";
    return false;
  }
  TIFFSetField(t, TIFFTAG_IMAGEWIDTH, static_cast<uint32_t>(width));
  TIFFSetField(t, TIFFTAG_IMAGELENGTH, static_cast<uint32_t>(height));
  TIFFSetField(t, TIFFTAG_SAMPLESPERPIXEL, 3);
  TIFFSetField(t, TIFFTAG_BITSPERSAMPLE, 8);
  TIFFSetField(t, TIFFTAG_ORIENTATION, ORIENTATION_TOPLEFT);
  TIFFSetField(t, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
  TIFFSetField(t, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_RGB);
  TIFFSetField(t, TIFFTAG_COMPRESSION, COMPRESSION_NONE);
  TIFFSetField(t, TIFFTAG_ROWSPERSTRIP, 1);
  std::vector<uint8_t> row(static_cast<std::size_t>(width) * 3);
  for (int y = 0; y < height; ++y) {
    std::copy_n(rgb.data() + static_cast<std::size_t>(y) * width * 3, row.size(), row.data());
    if (TIFFWriteScanline(t, row.data(), static_cast<uint32_t>(y), 0) < 0) {
      TIFFClose(t);
      error = "libtiff write error";
      return false;
    }
  }
  TIFFClose(t);
  return true;
}

}  // namespace minrt::host
