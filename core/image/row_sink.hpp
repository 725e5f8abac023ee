// Where a tracer's finished rows go: the image size first, then each row as
// soon as it is finished, then the end. Rows are 8-bit RGB, 3 bytes a pixel,
// top row first. The PPM writer, the framed protocol's row sender on the
// board and the host's other outputs are sinks. A pair of function pointers
// and a context, like ByteSink: no virtual calls, nothing the bare-metal
// build lacks, one indirect call per row.
#pragma once

#include <stdint.h>

namespace minrt {

struct RowSink {
  void* ctx;
  void (*begin_fn)(void* ctx, int width, int height);
  void (*row_fn)(void* ctx, int y, const uint8_t* rgb);
  void (*end_fn)(void* ctx);

  void begin(int width, int height) const { begin_fn(ctx, width, height); }
  void row(int y, const uint8_t* rgb) const { row_fn(ctx, y, rgb); }
  void end() const { end_fn(ctx); }
};

// A RowSink over any object with begin(w, h), row(y, rgb) and end().
template <class T>
RowSink row_sink_of(T& target) {
  return RowSink{
      &target,
      [](void* c, int w, int h) { static_cast<T*>(c)->begin(w, h); },
      [](void* c, int y, const uint8_t* rgb) { static_cast<T*>(c)->row(y, rgb); },
      [](void* c) { static_cast<T*>(c)->end(); },
  };
}

// The same for the general tracer's rows: 8-bit RGBA, 4 bytes a pixel (CS418
// needs alpha; writers without it drop the fourth byte).
struct RgbaRowSink {
  void* ctx;
  void (*begin_fn)(void* ctx, int width, int height);
  void (*row_fn)(void* ctx, int y, const uint8_t* rgba);
  void (*end_fn)(void* ctx);

  void begin(int width, int height) const { begin_fn(ctx, width, height); }
  void row(int y, const uint8_t* rgba) const { row_fn(ctx, y, rgba); }
  void end() const { end_fn(ctx); }
};

template <class T>
RgbaRowSink rgba_row_sink_of(T& target) {
  return RgbaRowSink{
      &target,
      [](void* c, int w, int h) { static_cast<T*>(c)->begin(w, h); },
      [](void* c, int y, const uint8_t* rgba) { static_cast<T*>(c)->row(y, rgba); },
      [](void* c) { static_cast<T*>(c)->end(); },
  };
}

}  // namespace minrt
