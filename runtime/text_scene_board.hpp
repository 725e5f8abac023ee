// The board's side of a CS418, Jaworski, miniRT or EASTRAY scene that
// arrived whole in memory over the course or framed protocol
// (protocol/text_scene_upload.hpp): the texture preamble is read in place,
// then the scene text goes to the format's board path (cs418_board.hpp,
// jaworski_board.hpp, minirt_board.hpp, eastray_board.hpp), in float with
// the portable shims like the raw protocol. `width` and `height` are the
// board's --size, which only miniRT uses (its files have no image size).
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "scene_result.hpp"
#include "protocol/text_scene_upload.hpp"

namespace minrt::fw {

// Into an RGBA row sink (framed: the RowFramer, 4 bytes a pixel).
SceneResult render_text_scene_rows(const send::text::TextScene& scene, RgbaRowSink rows, Arena& arena,
                                   int width, int height, bool all_features, Diagnostic& error);

// The format's own image streamed on `out`, as in the raw protocol (course):
// a stored-deflate PNG for CS418, miniRT and EASTRAY, a 32-bit BMP for
// Jaworski.
SceneResult stream_text_scene(const send::text::TextScene& scene, ByteSink out, Arena& arena, int width,
                              int height, bool all_features, Diagnostic& error);

}  // namespace minrt::fw
