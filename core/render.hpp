// The core's one entry point: SLD bytes in, PPM bytes out, everything taken
// from one arena the platform provides. Nothing is written unless the whole
// scene was read and checked, so a bad input never leaves half an image.
#pragma once

#include <cstddef>
#include <new>

#include <minrt/limits.hpp>

#include "arena.hpp"
#include "byte_io.hpp"
#include "diagnostic.hpp"
#include "math_policy.hpp"
#include "ppm_writer.hpp"
#include "scene.hpp"
#include "sld_reader.hpp"
#include "tracer.hpp"

namespace minrt {

struct RenderOptions {
  int width = limits::kDefaultImageWidth;
  int height = limits::kDefaultImageHeight;
  PpmFormat format = PpmFormat::kP3;
};

enum class RenderStatus { kOk, kBadOptions, kSceneError, kOutOfMemory };

// Arena bytes that suffice for any valid scene at this image width.
template <MathPolicy M>
constexpr std::size_t arena_bytes_for_width(int width) {
  using R = typename M::real;
  constexpr std::size_t kDirvecs = Tracer<M>::kDirvecGroups * Tracer<M>::kDirvecsPerGroup + 1 +
                                   Tracer<M>::kMaxReflections;
  return Arena::footprint<Scene<R>>(1) + Arena::footprint<Tracer<M>>(1) +
         Arena::footprint<R>(kDirvecs * limits::kMaxObjects * 6) +
         Tracer<M>::pixel_line_bytes(width);
}

inline bool valid_size(int width, int height) {
  return width >= 1 && height >= 1 && width <= limits::kMaxImageWidth &&
         height <= limits::kMaxImageHeight;
}

template <MathPolicy M>
RenderStatus render_sld(ByteSource in, ByteSink out, const RenderOptions& options, Arena& arena,
                        Diagnostic& error, const WarningSink& warnings = {}) {
  using R = typename M::real;
  if (!valid_size(options.width, options.height)) {
    error.text("image size must be between 1x1 and ")
        .number(limits::kMaxImageWidth)
        .text("x")
        .number(limits::kMaxImageHeight);
    return RenderStatus::kBadOptions;
  }
  Scene<R>* scene = arena.alloc_zeroed<Scene<R>>(1);
  Tracer<M>* tracer = arena.alloc_zeroed<Tracer<M>>(1);
  if (scene == nullptr || tracer == nullptr) {
    error.text("out of memory for the scene tables");
    return RenderStatus::kOutOfMemory;
  }
  new (scene) Scene<R>();
  SldReader<R> reader(in, warnings);
  if (!reader.read(*scene, error)) return RenderStatus::kSceneError;
  new (tracer) Tracer<M>();
  const std::size_t before = arena.used();
  if (!tracer->init(*scene, options.width, options.height, arena)) {
    error.text("out of memory: this scene needs ")
        .number(static_cast<std::int64_t>(before + Tracer<M>::arena_bytes(*scene, options.width)))
        .text(" bytes of arena, ")
        .number(static_cast<std::int64_t>(arena.capacity()))
        .text(" available");
    return RenderStatus::kOutOfMemory;
  }
  PpmWriter writer(out, options.format);
  tracer->render(writer);
  return RenderStatus::kOk;
}

}  // namespace minrt
