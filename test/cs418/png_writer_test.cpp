// The core's streaming PNG writer (stored deflate blocks, one IDAT per row)
// decodes, with libpng, to exactly the pixels it was given, including rows
// longer than one stored block.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "core/image/png_writer.hpp"
#include "core/image/row_sink.hpp"
#include "png_io.hpp"

namespace {

void append(void* ctx, const uint8_t* p, size_t n) {
  static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(p), n);
}

minrt::host::RgbaImage round_trip(int w, int h) {
  std::vector<uint8_t> rgba(static_cast<size_t>(w) * h * 4);
  uint32_t x = 12345;
  for (auto& b : rgba) {
    x = x * 1103515245u + 12345u;
    b = static_cast<uint8_t>(x >> 23);
  }
  std::string bytes;
  minrt::PngStoredWriter png(minrt::ByteSink{&append, &bytes});
  const minrt::RgbaRowSink sink = minrt::rgba_row_sink_of(png);
  sink.begin(w, h);
  for (int y = 0; y < h; ++y) sink.row(y, rgba.data() + static_cast<size_t>(y) * w * 4);
  sink.end();
  char path[] = "/tmp/minrt-png-XXXXXX";
  const int fd = mkstemp(path);
  REQUIRE(fd >= 0);
  std::FILE* f = fdopen(fd, "wb");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  minrt::host::RgbaImage img;
  std::string why;
  const bool ok = minrt::host::read_png(path, img, why);
  std::remove(path);
  INFO(why);
  REQUIRE(ok);
  REQUIRE(img.width == w);
  REQUIRE(img.height == h);
  CHECK(img.rgba == rgba);
  return img;
}

}  // namespace

TEST_CASE("PngStoredWriter: libpng decodes the pixels it was given", "[png]") {
  round_trip(1, 1);
  round_trip(3, 2);
  round_trip(100, 50);
  round_trip(16400, 2);  // a row of 65,601 bytes needs two stored blocks
}
