// The board's path for miniRT scenes (.rt): the text from the line, the
// image back as a streamed stored-deflate PNG, rendered in float with the
// portable shims like the host's `--precision float --shims portable`. The
// file has no image size: the board renders at its --size (host-send passes
// its own). Textures arrive decoded ahead of the scene (texture preamble).
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "scene_result.hpp"
#include "protocol/texture_blobs.hpp"

namespace minrt::fw {

// Into RGBA rows (the PNG writer, or the framed protocol's RowFramer).
SceneResult render_minirt_rows(ByteSource in, RgbaRowSink rows, Arena& arena, int width, int height,
                               bool all_features, const send::textures::Table* textures, Diagnostic& error);

}  // namespace minrt::fw
