#include "row_file_writer.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/image/bmp_writer.hpp"

namespace minrt::host {

namespace {

// Pixels converted and written at a time: one buffer on the stack.
constexpr int kChunkPixels = 1024;

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

void RowFileWriter::row(int y, const uint8_t* rgba) {
  if (error_.load(std::memory_order_relaxed) != 0) return;
  const bool bmp = kind_ == ImageFile::kBmp;
  const int file_row = bmp ? height_ - 1 - y : y;  // a BMP stores the bottom row first
  std::size_t offset = header_bytes_ + static_cast<std::size_t>(file_row) * row_bytes_;
  uint8_t chunk[4 * kChunkPixels];
  for (int x = 0; x < width_; x += kChunkPixels) {
    const int n = width_ - x < kChunkPixels ? width_ - x : kChunkPixels;
    const uint8_t* src = rgba + 4 * static_cast<std::size_t>(x);
    std::size_t bytes;
    if (bmp) {
      BmpWriter::to_bgra(src, chunk, n);
      bytes = 4 * static_cast<std::size_t>(n);
    } else {
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) chunk[3 * i + c] = src[4 * i + c];
      bytes = 3 * static_cast<std::size_t>(n);
    }
    if (!put(chunk, bytes, offset)) return;
    offset += bytes;
  }
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
