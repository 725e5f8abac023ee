// An image file whose rows each have a fixed place in it (BMP: 32-bit,
// bottom row first; binary PPM), written a few rows at a time from any
// thread as the rows are rendered: the header first, then each run of
// rows with pwrite at its own offset. Writing the file thus overlaps the render and shares its
// threads, instead of following the last row on one thread, and no row
// waits for the rows before it.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "image_file_output.hpp"

namespace minrt::host {

class RowFileWriter {
 public:
  // Begins `f` as a `kind` image of width x height. False, with `f`
  // untouched, when the kind's rows have no fixed place (PNG, TIFF) or `f`
  // is not an empty regular file at its start (a pipe, a terminal); false
  // with write_error() set when the header cannot be written.
  bool start(std::FILE* f, ImageFile kind, int width, int height);
  bool started() const { return fd_ >= 0; }

  // Rows y .. y + count - 1 (0 = top) as RGBA, width x 4 bytes each, one
  // after the other in `rgba`, which is converted in place into the
  // file's bytes and written with one call. Any thread, any order, each
  // row once; the first failing write is kept for finish().
  void rows(int y, int count, uint8_t* rgba);

  // After the last row: leaves the file's offset at its end, as a
  // sequential writer would. False with the reason when a write failed.
  bool finish(std::string& why);
  int write_error() const { return error_.load(std::memory_order_relaxed); }

 private:
  bool put(const uint8_t* bytes, std::size_t count, std::size_t offset);

  int fd_ = -1;
  ImageFile kind_ = ImageFile::kBmp;
  int width_ = 0, height_ = 0;
  std::size_t header_bytes_ = 0, row_bytes_ = 0;
  std::atomic<int> error_{0};  // errno of the first failed write
};

}  // namespace minrt::host
