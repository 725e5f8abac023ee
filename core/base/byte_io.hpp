// Byte source and sink the core reads SLD from and writes PPM to. Plain
// function pointers (no virtuals, no RTTI) so the same core links into the
// host tool, the firmware's UART loop and the tests.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace minrt {

struct ByteSource {
  // Returns the next byte (0..255) or -1 at end of input.
  int (*read)(void* ctx);
  void* ctx;

  int get() { return read(ctx); }
};

struct ByteSink {
  void (*write)(void* ctx, const uint8_t* data, size_t size);
  void* ctx;

  void put(const uint8_t* data, size_t size) { write(ctx, data, size); }
};

// Reads from an in-memory buffer; handy for tests and the course protocol.
struct MemorySource {
  const uint8_t* data;
  size_t size;
  size_t pos = 0;

  static int read_fn(void* ctx) {
    auto* self = static_cast<MemorySource*>(ctx);
    return self->pos < self->size ? self->data[self->pos++] : -1;
  }
  ByteSource source() { return ByteSource{&read_fn, this}; }
};

}  // namespace minrt
