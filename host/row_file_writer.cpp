#include "row_file_writer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "core/image/bmp_writer.hpp"

namespace minrt::host {

namespace {

// Pixels converted at a time (BmpWriter::to_bgra takes an int count).
constexpr std::size_t kChunkPixels = 1 << 20;

}  // namespace

bool RowFileWriter::start(std::FILE* f, ImageFile kind, int width, int height) {
  if (kind != ImageFile::kBmp && kind != ImageFile::kPpm) return false;
  const int fd = fileno(f);
  struct stat st {};
  if (fd < 0 || std::fflush(f) != 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size != 0 ||
      ::lseek(fd, 0, SEEK_CUR) != 0)
    return false;
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || (flags & O_APPEND) != 0) return false;  // pwrite would append

  uint8_t header[64];
  std::size_t header_bytes;
  if (kind == ImageFile::kBmp) {
    BmpWriter::header(header, width, height);
    header_bytes = BmpWriter::kHeaderBytes;
    row_bytes_ = static_cast<std::size_t>(width) * 4;
  } else {
    // write_ppm's header, byte for byte.
    const int n = std::snprintf(reinterpret_cast<char*>(header), sizeof header, "P6\n%d %d\n255\n", width, height);
    header_bytes = static_cast<std::size_t>(n);
    row_bytes_ = static_cast<std::size_t>(width) * 3;
  }
  fd_ = fd;
  kind_ = kind;
  width_ = width;
  height_ = height;
  header_bytes_ = header_bytes;
  // The file's blocks reserved now: a file still waiting for its blocks
  // (ext4's delayed allocation) gets them, and its pages sent to the disk,
  // when it is renamed over an existing one, which is after the last row.
  // Where the system cannot (EOPNOTSUPP), the rows are written all the same.
  const auto total = static_cast<off_t>(header_bytes + static_cast<std::size_t>(height) * row_bytes_);
  if (total > 0) (void)::fallocate(fd, 0, 0, total);
  return put(header, header_bytes, 0);
}

void RowFileWriter::rows(int y, int count, uint8_t* rgba) {
  if (count <= 0 || error_.load(std::memory_order_relaxed) != 0) return;
  const std::size_t in_bytes = static_cast<std::size_t>(width_) * 4;
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(count);
  int first_file_row;
  if (kind_ == ImageFile::kBmp) {
    // A BMP stores the bottom row first: the run goes in reversed.
    for (int i = 0, j = count - 1; i < j; ++i, --j)
      std::swap_ranges(rgba + i * in_bytes, rgba + (i + 1) * in_bytes, rgba + j * in_bytes);
    for (std::size_t p = 0; p < pixels; p += kChunkPixels) {
      const std::size_t n = pixels - p < kChunkPixels ? pixels - p : kChunkPixels;
      BmpWriter::to_bgra(rgba + 4 * p, rgba + 4 * p, static_cast<int>(n));
    }
    first_file_row = height_ - y - count;
  } else {
    // RGB from RGBA: each pixel moves down, never over one not yet read.
    for (std::size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) rgba[3 * p + c] = rgba[4 * p + c];
    first_file_row = y;
  }
  (void)put(rgba, static_cast<std::size_t>(count) * row_bytes_,
            header_bytes_ + static_cast<std::size_t>(first_file_row) * row_bytes_);
}

bool RowFileWriter::put(const uint8_t* bytes, std::size_t count, std::size_t offset) {
  while (count > 0) {
    const ssize_t n = ::pwrite(fd_, bytes, count, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      int expected = 0;
      error_.compare_exchange_strong(expected, n < 0 ? errno : EIO, std::memory_order_relaxed);
      return false;
    }
    bytes += n;
    count -= static_cast<std::size_t>(n);
    offset += static_cast<std::size_t>(n);
  }
  return true;
}

bool RowFileWriter::finish(std::string& why) {
  if (const int err = write_error(); err != 0) {
    why = std::strerror(err);
    return false;
  }
  const auto end = static_cast<off_t>(header_bytes_ + static_cast<std::size_t>(height_) * row_bytes_);
  if (::lseek(fd_, end, SEEK_SET) != end) {
    why = std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace minrt::host
