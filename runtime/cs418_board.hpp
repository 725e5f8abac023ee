// The board's CS418 path: the scene text from the line, the image back as a
// streamed stored-deflate PNG (core/image/png_writer.hpp), rendered in float
// with the portable shims like the host's `--precision float --shims
// portable`. Textures need the framed protocol (not yet): a scene naming one
// is refused with a located error.
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"

namespace minrt::fw {

enum class Cs418Result { kOk, kSceneError, kOutOfMemory };

// `all_features`: render on the path with every feature compiled in (to
// measure what the specialised paths save).
Cs418Result render_cs418(ByteSource in, ByteSink out, Arena& arena, bool all_features, Diagnostic& error);

}  // namespace minrt::fw
