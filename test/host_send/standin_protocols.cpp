#include "standin_protocols.hpp"

#include <minrt/memory_map.h>

#include <vector>

#include "protocol/protocol_course_board.hpp"
#include "protocol/protocol_framed_board.hpp"
#include "protocol/scene_check.hpp"

namespace standin {

namespace {

// Binary input: every byte counts, the input ends when the host hangs up.
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

}  // namespace

bool serve_course(Link& link, const CourseRenderFn& render, bool big_endian) {
  using namespace minrt::send::course;
  const Endian endian = big_endian ? Endian::kBig : Endian::kLittle;
  LinkSource words{&link};
  const minrt::ByteSource in{&LinkSource::read_fn, &words};
  const minrt::ByteSink out{&sink_fn, &link};
  minrt::Diagnostic error;
  // The stand-in cannot run RV32 code: it takes the program as the firmware
  // would (same size limit) and drops it, then renders with the host code.
  uint32_t length = 0;
  if (receive_program(in, out, endian, nullptr, MINRT_PROGRAM_MAX_SIZE, length, error) != ProgramResult::kReceived)
    return false;
  // A checked scene is held and checked first, and the reply gets the
  // trailer, as on the firmware (protocol/scene_check.hpp).
  std::vector<uint8_t> memory(16 * 1024 * 1024);
  minrt::Arena arena(memory.data(), memory.size());
  minrt::send::raw_check::CheckedSink reply(out, false);
  const bool ok = serve_scene(
      in, out,
      [&](minrt::ByteSource words) {
        minrt::send::scene_check::CourseScene scene;
        if (!scene.begin(words, endian, arena, reply, error)) return false;
        return render(scene.words(), reply.sink(), error);
      },
      error);
  if (ok) reply.end();
  return ok;
}

bool serve_framed(Link& link, const minrt::RenderOptions& options, const RowRenderFn& render) {
  using namespace minrt::send::framed;
  LinkSource bytes{&link};
  const minrt::ByteSource in{&LinkSource::read_fn, &bytes};
  const minrt::ByteSink out{&sink_fn, &link};
  std::vector<uint8_t> payload(4096);
  FrameParser parser(payload.data(), payload.size());
  std::vector<uint8_t> scene(64 * 1024);
  SceneCollector collector(scene.data(), scene.size());
  std::vector<uint8_t> store(static_cast<size_t>(options.width) * options.height * 3);
  RowFramer framer(out, store.data(), store.size());
  minrt::Diagnostic error;
  return serve_board(in, out, parser, collector, framer,
                     [&](minrt::ByteSource src, RowFramer& rows) { return render(src, minrt::row_sink_of(rows), error); },
                     error) == BoardResult::kDone;
}

}  // namespace standin
