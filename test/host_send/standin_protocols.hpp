// The stand-in board's course and framed protocols: the board side the
// firmware runs too (protocol/protocol_{course,framed}_board.hpp) over the
// stand-in's pty.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "render/sld/render.hpp"

namespace standin {

struct Link {
  void* ctx;
  bool (*read_exact)(void* ctx, uint8_t* p, size_t n);
  void (*write)(void* ctx, const uint8_t* p, size_t n);
  int fd;
};

// Renders the SLD text from `in` to `out`; false with the reason in `error`.
using RenderFn = std::function<bool(minrt::ByteSource in, minrt::ByteSink out, minrt::Diagnostic& error)>;

// Renders the course protocol's scene words from `words` to `out`.
using CourseRenderFn = std::function<bool(minrt::ByteSource words, minrt::ByteSink out, minrt::Diagnostic& error)>;

bool serve_course(Link& link, const CourseRenderFn& render, bool big_endian);
// Renders the SLD text from `in` into the row sink `rows`.
using RowRenderFn = std::function<bool(minrt::ByteSource in, const minrt::RowSink& rows, minrt::Diagnostic& error)>;

bool serve_framed(Link& link, const minrt::RenderOptions& options, const RowRenderFn& render);

}  // namespace standin
