// The board's CS418 path: the scene text from the line, the image back as a
// streamed stored-deflate PNG (core/image/png_writer.hpp), rendered in float
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

// `all_features`: render on the path with every feature compiled in (to
// measure what the specialised paths save).
// `textures`: what the preamble brought, or nullptr when there was none.
SceneResult render_cs418(ByteSource in, ByteSink out, Arena& arena, bool all_features,
                         const send::textures::Table* textures, Diagnostic& error);

// The same into any RGBA row sink (the framed protocol's row sender).
SceneResult render_cs418_rows(ByteSource in, RgbaRowSink rows, Arena& arena, bool all_features,
                              const send::textures::Table* textures, Diagnostic& error);

}  // namespace minrt::fw
