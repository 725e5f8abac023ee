// Byte source and sink over C stdio streams, for the host front ends.
#pragma once

#include <cstdio>

#include "core/base/byte_io.hpp"

namespace minrt::host {

struct FileSource {
  std::FILE* file;

  static int read_fn(void* ctx) {
    const int c = getc_unlocked(static_cast<FileSource*>(ctx)->file);
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
