#include "standin_protocols.hpp"

#include <minrt/serial_protocol.h>

#include <vector>

#include "protocol_course.hpp"
#include "protocol_framed.hpp"

namespace standin {

namespace {

struct LinkSource {
  Link* link;
  static int read_fn(void* ctx) {
    uint8_t c;
    return static_cast<LinkSource*>(ctx)->link->read_exact(static_cast<LinkSource*>(ctx)->link->ctx, &c, 1) ? c : -1;
  }
};

void sink_fn(void* ctx, const uint8_t* p, size_t n) {
  auto* link = static_cast<Link*>(ctx);
  link->write(link->ctx, p, n);
}

void send_error_line(Link& link, const std::string& message) {
  const std::string line = MINRT_ERROR_MARKER + message + "\n";
  link.write(link.ctx, reinterpret_cast<const uint8_t*>(line.data()), line.size());
}

}  // namespace

bool serve_course(Link& link, const RenderFn& render, bool big_endian) {
  using namespace minrt::send::course;
  const Endian endian = big_endian ? Endian::kBig : Endian::kLittle;
  uint8_t b = kProgramRequest;
  link.write(link.ctx, &b, 1);
  uint8_t len[4];
  if (!link.read_exact(link.ctx, len, 4)) return false;
  std::vector<uint8_t> program(get_u32(len, endian));
  if (!program.empty() && !link.read_exact(link.ctx, program.data(), program.size())) return false;
  b = kSceneRequest;
  link.write(link.ctx, &b, 1);
  LinkSource words{&link};
  SceneTextSource text(minrt::ByteSource{&LinkSource::read_fn, &words}, endian);
  std::string message;
  if (!render(text.source(), minrt::ByteSink{&sink_fn, &link}, message)) {
    send_error_line(link, message);
    return false;
  }
  return true;
}

bool serve_framed(Link& link, const minrt::RenderOptions& options, const RenderFn& render) {
  using namespace minrt::send::framed;
  const minrt::ByteSink out{&sink_fn, &link};
  std::vector<uint8_t> payload(4096);
  FrameParser parser(payload.data(), payload.size());
  std::vector<uint8_t> scene(64 * 1024);
  SceneCollector collector(scene.data(), scene.size());
  uint8_t c;
  for (bool complete = false; !complete;) {
    if (!link.read_exact(link.ctx, &c, 1)) return false;
    if (parser.feed(c) != FrameParser::kFrame) continue;
    switch (collector.frame(parser)) {
      case SceneCollector::kComplete:
        write_frame(out, kAck, 0, nullptr, 0);
        complete = true;
        break;
      case SceneCollector::kDamaged:
        write_frame(out, kNak, 0, nullptr, 0);
        break;
      case SceneCollector::kTooLarge: {
        const char msg[] = "scene larger than the board's 65536-byte buffer";
        write_frame(out, kError, 0, reinterpret_cast<const uint8_t*>(msg), sizeof msg - 1);
        return false;
      }
      case SceneCollector::kMore:
        break;
    }
  }
  std::vector<uint8_t> store(static_cast<size_t>(options.width) * options.height * 3);
  RowFramer framer(out, store.data(), store.size());
  minrt::MemorySource src{collector.data(), collector.size()};
  std::string message;
  if (!render(src.source(), framer.sink(), message)) {
    write_frame(out, kError, 0, reinterpret_cast<const uint8_t*>(message.data()), static_cast<uint16_t>(message.size()));
    return false;
  }
  framer.send_end();
  // Answer requests until the host says it has everything.
  for (;;) {
    if (!link.read_exact(link.ctx, &c, 1)) return true;
    if (parser.feed(c) != FrameParser::kFrame) continue;
    if (parser.type() == kRequest) framer.answer_request(parser);
    else if (parser.type() == kFinished) return true;
    else if (parser.type() == kSceneEnd) write_frame(out, kAck, 0, nullptr, 0);
  }
}

}  // namespace standin
