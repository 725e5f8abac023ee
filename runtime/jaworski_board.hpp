// The board's path for Jaworski's scenes: the text from the line, the image
// back as a 32-bit BMP streamed row by row (bottom row first, as rendered),
// in float with the portable shims like the host's `--precision float
// --shims portable`.
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "scene_result.hpp"

namespace minrt::fw {

// Into RGBA rows, bottom row first (the BMP writer, or the framed
// protocol's row sender).
SceneResult render_jaworski_rows(ByteSource in, RgbaRowSink rows, Arena& arena, Diagnostic& error);

}  // namespace minrt::fw
