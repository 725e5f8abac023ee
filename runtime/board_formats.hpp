// What the board does with each format in the registry (formats/registry.hpp),
// in its order: the only place the firmware names its formats' code. Every
// format but SLD (whose PPM main.cpp streams on each protocol) renders RGBA
// rows; the image that goes back (PNG, BMP) is the registry's reply kind.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/image/row_sink.hpp"
#include "formats/registry.hpp"
#include "protocol/text_scene_upload.hpp"
#include "protocol/texture_blobs.hpp"
#include "scene_result.hpp"

namespace minrt::fw {

// One scene's text as the board has it, and what rendering it may use.
struct BoardScene {
  ByteSource text;                                 // the text, after any texture preamble
  const uint8_t* bytes = nullptr;                  // the same text when it lies whole in memory
  size_t size = 0;
  Arena* arena = nullptr;
  int width = 0, height = 0;                       // the board's --size (formats without their own)
  bool all_features = false;
  const send::textures::Table* textures = nullptr; // decoded by host-send, sent ahead of the scene
  Diagnostic* error = nullptr;
};

struct BoardFormat {
  formats::FormatId id;
  SceneResult (*rows)(const BoardScene& scene, RgbaRowSink rows);  // null: SLD
};

// The rows of a text-format scene (the raw protocol's, or one that arrived
// whole over course or framed), into `rows`.
SceneResult render_board_rows(const formats::Format& format, const BoardScene& scene, RgbaRowSink rows);

// The same, streamed on `out` as the registry's reply image (a stored-deflate
// PNG, or a 32-bit BMP).
SceneResult stream_board_image(const formats::Format& format, const BoardScene& scene, ByteSink out);

// A scene that arrived whole over course or framed (protocol/text_scene_upload.hpp):
// its format from the upload's tag, the texture preamble read in place.
SceneResult render_uploaded_rows(const send::text::TextScene& upload, BoardScene scene, RgbaRowSink rows);
SceneResult stream_uploaded_image(const send::text::TextScene& upload, BoardScene scene, ByteSink out);

}  // namespace minrt::fw
