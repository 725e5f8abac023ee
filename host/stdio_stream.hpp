// Byte source and sink over C stdio streams, for the host front ends.
#pragma once

#include <cerrno>
#include <cstdio>

#include "core/base/byte_io.hpp"

namespace minrt::host {

struct FileSource {
  std::FILE* file;
  int read_errno = 0;  // the system's reason when reading failed (not at end of file)

  static int read_fn(void* ctx) {
    auto* self = static_cast<FileSource*>(ctx);
    const int c = getc_unlocked(self->file);
    if (c == EOF && std::ferror(self->file) && self->read_errno == 0) self->read_errno = errno != 0 ? errno : EIO;
    return c == EOF ? -1 : c;
  }
  ByteSource source() { return ByteSource{&read_fn, this}; }
};

struct FileSink {
  std::FILE* file;
  bool failed = false;

  static void write_fn(void* ctx, const uint8_t* data, size_t size);
  ByteSink sink() { return ByteSink{&write_fn, this}; }
};

}  // namespace minrt::host
