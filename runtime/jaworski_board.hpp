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

SceneResult render_jaworski(ByteSource in, ByteSink out, Arena& arena, Diagnostic& error);

// The same into any RGBA row sink, bottom row first (the framed protocol's
// row sender).
SceneResult render_jaworski_rows(ByteSource in, RgbaRowSink rows, Arena& arena, Diagnostic& error);

// True when a scene's first word (lower case, letters only) or its first
// byte ('#') says it is one of Jaworski's.
bool is_jaworski_start(int first_byte, const char* first_word);

}  // namespace minrt::fw
