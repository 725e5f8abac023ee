// The precision and shim combinations the host build carries, chosen at run
// time. Each one is a separate instantiation of the same core template.
#pragma once

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "render/sld/render.hpp"

namespace minrt::host {

enum class Precision { kDouble, kFloat };
enum class ShimSet { kLibm, kPortable, kPortableFast, kPortableMin };

struct Variant {
  Precision precision = Precision::kDouble;
  ShimSet shims = ShimSet::kLibm;
};

// Name of the math policy behind a variant, or nullptr if not built.
const char* variant_name(Variant v);

// Allocates the arena once (sized from the limits and the width) and renders
// on `threads` threads (0: every core; the bytes are the same for any count).
// `finished`, when given, also gets each row as soon as it is rendered, in
// any order and from any thread (--show; only row() is called).
RenderStatus render_variant(Variant v, ByteSource in, ByteSink out, const RenderOptions& options,
                            Diagnostic& error, const WarningSink& warnings, int threads = 1,
                            const RowSink* finished = nullptr);

// The same into a row sink.
RenderStatus render_variant_rows(Variant v, ByteSource in, const RowSink& out, const RenderOptions& options,
                                 Diagnostic& error, const WarningSink& warnings, int threads = 1,
                                 const RowSink* finished = nullptr);

// The same from the course protocol's scene words (what the board does).
RenderStatus render_variant_course_words(Variant v, ByteSource words, bool big_endian, ByteSink out,
                                         const RenderOptions& options, Diagnostic& error,
                                         const WarningSink& warnings);

}  // namespace minrt::host
