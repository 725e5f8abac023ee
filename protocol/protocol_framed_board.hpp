// Framed protocol, board side: the whole conversation as the firmware
// (runtime/) and the stand-in board (test/host_send) both run it, over
// buffers the caller owns. Freestanding like protocol_framed.hpp: no heap,
// no exceptions, <stdint.h>/<stddef.h> only.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "protocol/protocol_framed.hpp"

namespace minrt::send::framed {

// An X frame with "LINE:COL: message" (or just the message).
inline void write_error_frame(ByteSink out, const Diagnostic& error) {
  Diagnostic text;
  if (error.has_pos) text.number(error.pos.line).text(":").number(error.pos.col).text(": ");
  text.text(error.message);
  write_frame(out, kError, 0, reinterpret_cast<const uint8_t*>(text.message), static_cast<uint16_t>(text.length));
}

enum class BoardResult { kDone, kNoScene, kTooLarge, kRenderFailed };

// Step 1: feeds `in` to the parser until the collector has the whole
// scene (K), asking for it again after damage (N). An X frame goes out
// when the scene does not fit or the input ends first.
inline BoardResult receive_scene(ByteSource in, ByteSink out, FrameParser& parser, SceneCollector& collector,
                                 Diagnostic& error) {
  for (;;) {
    const int c = in.get();
    if (c < 0) {
      error.text("framed: the scene did not arrive");
      write_error_frame(out, error);
      return BoardResult::kNoScene;
    }
    if (parser.feed(static_cast<uint8_t>(c)) != FrameParser::kFrame) continue;
    switch (collector.frame(parser)) {
      case SceneCollector::kComplete:
        write_frame(out, kAck, 0, nullptr, 0);
        return BoardResult::kDone;
      case SceneCollector::kDamaged:
        write_frame(out, kNak, 0, nullptr, 0);
        break;
      case SceneCollector::kTooLarge:
        error.text("scene larger than the board's ").number(static_cast<int64_t>(collector.capacity())).text("-byte buffer");
        write_error_frame(out, error);
        return BoardResult::kTooLarge;
      case SceneCollector::kMore:
        break;
    }
  }
}

// Step 3: after the image, Z, then re-sends what Q frames ask for until
// F or the end of the input. A repeated E (the host missed K) gets K.
inline void answer_requests(ByteSource in, ByteSink out, FrameParser& parser, RowFramer& framer) {
  framer.send_end();
  for (;;) {
    const int c = in.get();
    if (c < 0) return;
    if (parser.feed(static_cast<uint8_t>(c)) != FrameParser::kFrame) continue;
    if (parser.type() == kRequest) framer.answer_request(parser);
    else if (parser.type() == kFinished) return;
    else if (parser.type() == kSceneEnd) write_frame(out, kAck, 0, nullptr, 0);
  }
}

// The conversation: receive the scene, render it into `framer` (H, one D
// frame per row), answer requests. `render(ByteSource scene, RowFramer&
// rows)` renders with the framer as its row sink and returns false with the
// reason in `error`, which goes out as X.
template <class Render>
BoardResult serve_board(ByteSource in, ByteSink out, FrameParser& parser, SceneCollector& collector,
                        RowFramer& framer, Render&& render, Diagnostic& error) {
  const BoardResult got = receive_scene(in, out, parser, collector, error);
  if (got != BoardResult::kDone) return got;
  MemorySource scene{collector.data(), collector.size()};
  if (!render(scene.source(), framer)) {
    write_error_frame(out, error);
    return BoardResult::kRenderFailed;
  }
  answer_requests(in, out, parser, framer);
  return BoardResult::kDone;
}

}  // namespace minrt::send::framed
