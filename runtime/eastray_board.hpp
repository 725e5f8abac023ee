// The board's path for EASTRAY scenes: host-send preprocesses the scene
// (#include needs files) and sends the expanded text behind a `/* EASTRAY */`
// marker; the board reads it whole into the arena (over course and framed it
// is already there: render_eastray_rows), renders it in float with
// the portable shims like the host's `--precision float --shims portable`,
// and sends the image back as a stored-deflate PNG (board_formats.hpp).
#pragma once

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "protocol/texture_blobs.hpp"
#include "scene_result.hpp"

namespace minrt::fw {

// `textures`: the map_data images host-send sent ahead of the scene (null: none).
// From the line (raw): the text is read whole into the arena first.
SceneResult render_eastray_source_rows(ByteSource in, RgbaRowSink rows, Arena& arena,
                                       const send::textures::Table* textures, Diagnostic& error);

// From text already in memory (course and framed uploads).
SceneResult render_eastray_rows(const char* text, size_t size, RgbaRowSink rows, Arena& arena,
                                const send::textures::Table* textures, Diagnostic& error);

}  // namespace minrt::fw
