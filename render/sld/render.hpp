// The min-rt renderer's entry points: SLD values in (text, or course words),
// finished rows out to a RowSink (or PPM bytes), everything taken from a
// fixed RenderState and one arena the platform provides. Nothing is
// written unless the whole scene was read and checked, so a bad input never
// leaves half an image.
#pragma once

#include <stddef.h>

#include <minrt/limits.hpp>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_policy.hpp"
#include "core/image/ppm_writer.hpp"
#include "formats/sld/scene.hpp"
#include "formats/sld/sld_reader.hpp"
#include "render/sld/tracer.hpp"

namespace minrt {

struct RenderOptions {
  int width = limits::kDefaultImageWidth;
  int height = limits::kDefaultImageHeight;
  PpmFormat format = PpmFormat::kP3;
};

enum class RenderStatus { kOk, kBadOptions, kSceneError, kOutOfMemory };

// The fixed-size state of one render: the scene as read and the tracer's
// tables. Platforms give it static storage (firmware) or allocate it once.
template <MathPolicy M>
struct RenderState {
  Scene<typename M::real> scene;
  Tracer<M> tracer;
};

// Arena bytes that suffice for any valid scene at this image width.
template <MathPolicy M>
constexpr size_t arena_bytes_for_width(int width) {
  return Tracer<M>::max_arena_bytes(width);
}

inline bool valid_size(int width, int height) {
  return width >= 1 && height >= 1 && width <= limits::kMaxImageWidth &&
         height <= limits::kMaxImageHeight;
}

// Reads the scene whose numbers `values` gives (sld_values.hpp: SLD text,
// or the course protocol's words on the board) and initialises the tracer
// in `state` for it; nothing is rendered yet.
template <MathPolicy M, class Values>
RenderStatus prepare_sld(const Values& values, const RenderOptions& options, RenderState<M>& state,
                         Arena& arena, Diagnostic& error, const WarningSink& warnings = {}) {
  using R = typename M::real;
  if (!valid_size(options.width, options.height)) {
    error.text("image size must be between 1x1 and ")
        .number(limits::kMaxImageWidth)
        .text("x")
        .number(limits::kMaxImageHeight);
    return RenderStatus::kBadOptions;
  }
  Scene<R>& scene = state.scene;
  SldReader<R, Values> reader(values, warnings);
  if (!reader.read(scene, error)) return RenderStatus::kSceneError;
  Tracer<M>& tracer = state.tracer;
  const size_t before = arena.used();
  if (!tracer.init(scene, options.width, options.height, arena)) {
    error.text("out of memory: this scene needs ")
        .number(static_cast<int64_t>(before + Tracer<M>::arena_bytes(scene, options.width)))
        .text(" bytes of arena, ")
        .number(static_cast<int64_t>(arena.capacity()))
        .text(" available");
    return RenderStatus::kOutOfMemory;
  }
  return RenderStatus::kOk;
}

// The same, then renders into a row sink.
template <MathPolicy M, class Values>
RenderStatus render_sld_rows(const Values& values, const RowSink& out, const RenderOptions& options,
                               RenderState<M>& state, Arena& arena, Diagnostic& error,
                               const WarningSink& warnings = {}) {
  const RenderStatus st = prepare_sld<M>(values, options, state, arena, error, warnings);
  if (st == RenderStatus::kOk) state.tracer.render(out);
  return st;
}

// The same as a PPM image (options.format) on a byte sink.
template <MathPolicy M, class Values>
RenderStatus render_sld_values(const Values& values, ByteSink out, const RenderOptions& options,
                               RenderState<M>& state, Arena& arena, Diagnostic& error,
                               const WarningSink& warnings = {}) {
  PpmWriter writer(out, options.format);
  return render_sld_rows<M>(values, writer.sink(), options, state, arena, error, warnings);
}

// SLD text in, PPM out: the original program.
template <MathPolicy M>
RenderStatus render_sld(ByteSource in, ByteSink out, const RenderOptions& options,
                        RenderState<M>& state, Arena& arena, Diagnostic& error,
                        const WarningSink& warnings = {}) {
  return render_sld_values<M>(SldTextValues<typename M::real>(in), out, options, state, arena, error, warnings);
}

}  // namespace minrt
