// The stand-in board's course and framed protocol loops, built on the
// shared protocol code in host/send/protocol_{course,framed}.hpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "byte_io.hpp"
#include "render.hpp"

namespace standin {

struct Link {
  void* ctx;
  bool (*read_exact)(void* ctx, uint8_t* p, size_t n);
  void (*write)(void* ctx, const uint8_t* p, size_t n);
  int fd;
};

// Renders the SLD text from `in` to `out`; false with the message on error.
using RenderFn = std::function<bool(minrt::ByteSource in, minrt::ByteSink out, std::string& message)>;

bool serve_course(Link& link, const RenderFn& render, bool big_endian);
bool serve_framed(Link& link, const minrt::RenderOptions& options, const RenderFn& render);

}  // namespace standin
