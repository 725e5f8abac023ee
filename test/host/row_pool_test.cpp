// host/row_pool.cpp and host/row_file_writer.cpp: every row rendered once
// and in its place, in memory and in a BMP or PPM file written as the rows
// are done, for any thread count (more threads than rows, too), rows wider
// than a hand-out and renders that follow one another in one process; a
// helper started on another core than its creator's is free of that limit
// by the time it renders.
#include <catch2/catch.hpp>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "host/row_file_writer.hpp"
#include "host/row_pool.hpp"

namespace {

using minrt::host::ImageFile;

uint8_t channel(int x, int y, int c) { return static_cast<uint8_t>(x * 7 + y * 13 + c * 101); }

// Pixels from their place; counts how often each row is asked for.
class Pattern final : public minrt::host::PreparedScene {
 public:
  Pattern(int w, int h) : asked(static_cast<std::size_t>(h)) {
    width = w;
    height = h;
  }
  void render_row(int y, uint8_t* rgba) const override {
    asked[static_cast<std::size_t>(y)].fetch_add(1);
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) rgba[4 * x + c] = c == 3 ? 255 : channel(x, y, c);
  }
  bool each_row_once() const {
    for (const auto& a : asked)
      if (a.load() != 1) return false;
    return true;
  }
  mutable std::vector<std::atomic<int>> asked;
};

std::string file_bytes(std::FILE* f) {
  std::string bytes;
  std::rewind(f);
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) bytes.append(buf, n);
  return bytes;
}

// The pixels part of the file as it should be.
std::string expected_pixels(ImageFile kind, int w, int h) {
  std::string out;
  for (int i = 0; i < h; ++i) {
    const int y = kind == ImageFile::kBmp ? h - 1 - i : i;  // a BMP's bottom row first
    for (int x = 0; x < w; ++x) {
      if (kind == ImageFile::kBmp) {
        for (int c : {2, 1, 0}) out += static_cast<char>(channel(x, y, c));
        out += static_cast<char>(255);
      } else {
        for (int c : {0, 1, 2}) out += static_cast<char>(channel(x, y, c));
      }
    }
  }
  return out;
}

}  // namespace

TEST_CASE("row pool: every row once and in its place, kept or written, on any thread count", "[host][rows]") {
  minrt::host::start_row_threads(3);  // more than some renders below take
  const int sizes[][2] = {{1, 1}, {7, 5}, {640, 48}, {33, 200}, {20000, 9}};
  for (const auto& size : sizes) {
    const int w = size[0], h = size[1];
    for (int threads : {1, 2, 3, 8}) {
      CAPTURE(w, h, threads);
      {
        Pattern scene(w, h);
        minrt::host::RgbaImage image;
        const int used = minrt::host::render_rows(scene, threads, image, nullptr);
        CHECK(used == std::min(threads, h));
        CHECK(scene.each_row_once());
        REQUIRE(image.rgba.size() == std::size_t{4} * w * h);
        bool same = true;
        for (int y = 0; y < h; ++y)
          for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) same = same && image.rgba[4 * (static_cast<std::size_t>(y) * w + x) + c] == channel(x, y, c);
        CHECK(same);
      }
      for (ImageFile kind : {ImageFile::kBmp, ImageFile::kPpm}) {
        std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::tmpfile(), &std::fclose);
        REQUIRE(f);
        minrt::host::RowFileWriter writer;
        REQUIRE(writer.start(f.get(), kind, w, h));
        Pattern scene(w, h);
        minrt::host::RgbaImage image;
        minrt::host::render_rows(scene, threads, image, nullptr, nullptr, &writer);
        std::string why;
        REQUIRE(writer.finish(why));
        CHECK(scene.each_row_once());
        const std::string bytes = file_bytes(f.get());
        const std::string pixels = expected_pixels(kind, w, h);
        REQUIRE(bytes.size() >= pixels.size());
        CHECK(bytes.compare(bytes.size() - pixels.size(), pixels.size(), pixels) == 0);
      }
    }
  }
}

namespace {

// Rows that note the cores their thread may run on.
class AffinityProbe final : public minrt::host::PreparedScene {
 public:
  explicit AffinityProbe(int h) : cores(static_cast<std::size_t>(h)) {
    width = 1;
    height = h;
  }
  void render_row(int y, uint8_t* rgba) const override {
    cpu_set_t set;
    CPU_ZERO(&set);
    cores[static_cast<std::size_t>(y)] =
        pthread_getaffinity_np(pthread_self(), sizeof set, &set) == 0 ? CPU_COUNT(&set) : -1;
    for (int c = 0; c < 4; ++c) rgba[c] = 255;
  }
  mutable std::vector<int> cores;
};

}  // namespace

TEST_CASE("row pool: a helper started on another core may run on every core for its rows", "[host][rows]") {
  cpu_set_t allowed;
  REQUIRE(sched_getaffinity(0, sizeof allowed, &allowed) == 0);
  const int count = CPU_COUNT(&allowed);
  // Helpers started now and in render_rows itself, on as many threads as
  // the process may use cores and more.
  minrt::host::start_row_threads(2);
  for (int threads : {2, 3, count + 1}) {
    CAPTURE(threads, count);
    AffinityProbe scene(400);
    minrt::host::RgbaImage image;
    minrt::host::render_rows(scene, threads, image, nullptr);
    for (int cores : scene.cores) CHECK(cores == count);
  }
}

// A process held to one core (as by `taskset`): its helpers start there and
// render all the same. Hidden: ctest runs it in a process of its own
// (test/host/CMakeLists.txt), which is held before any helper exists;
// helpers left by another case would still be free to use every core.
TEST_CASE("row pool: a process held to one core renders every row there", "[.one-core]") {
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(sched_getcpu(), &one);
  REQUIRE(sched_setaffinity(0, sizeof one, &one) == 0);
  AffinityProbe scene(50);
  minrt::host::RgbaImage image;
  minrt::host::render_rows(scene, 4, image, nullptr);
  for (int cores : scene.cores) CHECK(cores == 1);
}
