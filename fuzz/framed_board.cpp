// The board side of the framed protocol on arbitrary bytes from the line:
// the frame parser and the scene collector must never crash, overrun their
// buffers or deliver a scene larger than their buffer.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "protocol/protocol_framed_board.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace minrt::send::framed;
  static uint8_t payload[4096];
  static uint8_t scene[2048];
  FrameParser parser(payload, sizeof payload);
  SceneCollector collector(scene, sizeof scene);
  for (size_t i = 0; i < size; ++i) {
    if (parser.feed(data[i]) != FrameParser::kFrame) continue;
    if (parser.length() > sizeof payload) std::abort();
    if (collector.frame(parser) == SceneCollector::kComplete && collector.size() > sizeof scene) std::abort();
  }
  return 0;
}
