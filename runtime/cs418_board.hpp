// The board's CS418 path: the scene text from the line, the image back as a
// stored-deflate PNG (board_formats.hpp), rendered in float
// with the portable shims like the host's `--precision float --shims
// portable`. Textures arrive decoded ahead of the scene (the texture
// preamble of include/minrt/serial_protocol.h, protocol/texture_blobs.hpp).
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "scene_result.hpp"
#include "protocol/texture_blobs.hpp"

namespace minrt::fw {

// Into RGBA rows (the PNG writer, or the framed protocol's row sender).
// `all_features`: render on the path with every feature compiled in (to
// measure what the specialised paths save).
// `textures`: what the preamble brought, or nullptr when there was none.
SceneResult render_cs418_rows(ByteSource in, RgbaRowSink rows, Arena& arena, bool all_features,
                              const send::textures::Table* textures, Diagnostic& error);

}  // namespace minrt::fw
