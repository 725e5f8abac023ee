// The firmware: reads an SLD scene from the UART, renders it with the
// portable float math and streams the PPM back, row by row. On a bad scene
// or bad arguments it sends one MINRT_ERROR_MARKER line instead and returns
// a non-zero status, which crt0 hands to the test finisher.
//
// --protocol=course and --protocol=framed run the board side of host-send's
// other two protocols (docs/host-send.md) with the shared code in
// host/send/protocol_{course,framed}.hpp, as the stand-in board in
// test/host_send/standin_protocols.cpp does on the host.
#include <minrt/serial_protocol.h>

#include "diagnostic.hpp"
#include "firmware_args.hpp"
#include "footprint.hpp"
#include "math_portable.hpp"
#include "protocol_course.hpp"
#include "protocol_framed.hpp"
#include "math_rv32f.hpp"
#include "ns16550.hpp"
#include "render.hpp"
#include "serial_stream.hpp"

namespace {

// PortableFloat as the host's `--shims portable`; with MINRT_FW_HW_SQRT the
// square root is fsqrt.s (same bits, see core/math_rv32f.hpp) where the ISA
// has it.
#if MINRT_FW_HW_SQRT
using Math = minrt::PortableFloatHwSqrt;
#else
using Math = minrt::PortableFloat;
#endif

// The scene and the tracer's tables: static, so their size shows in .bss.
minrt::RenderState<Math> g_state;

void send_error(minrt::fw::Ns16550 uart, const minrt::Diagnostic& error) {
  minrt::Diagnostic where;
  if (error.has_pos)
    where.number(error.pos.line).text(":").number(error.pos.col).text(": ");
  uart.write(MINRT_ERROR_MARKER);
  uart.write(where.message);
  uart.write(error.message);
  uart.write("\n");
}

// The error as "line:col: message" (what send_error puts after the marker).
minrt::Diagnostic error_text(const minrt::Diagnostic& error) {
  minrt::Diagnostic text;
  if (error.has_pos) text.number(error.pos.line).text(":").number(error.pos.col).text(": ");
  text.text(error.message);
  return text;
}

int status_of(minrt::RenderStatus status) {
  switch (status) {
    case minrt::RenderStatus::kOk: return MINRT_STATUS_OK;
    case minrt::RenderStatus::kBadOptions: return MINRT_STATUS_USAGE;
    case minrt::RenderStatus::kSceneError: return MINRT_STATUS_SCENE_ERROR;
    case minrt::RenderStatus::kOutOfMemory: return MINRT_STATUS_OUT_OF_MEMORY;
  }
  return MINRT_STATUS_SCENE_ERROR;
}

// Course protocol: 0x99, program size and bytes (read and discarded: this
// firmware is already the program), 0xaa, then the scene as 4-byte words
// that SceneTextSource turns back into SLD text for the usual reader. The
// image and errors go out as in the raw protocol.
int serve_course(minrt::fw::Ns16550 uart, const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
                 minrt::Diagnostic& error) {
  using namespace minrt::send::course;
  const Endian endian = options.big_endian ? Endian::kBig : Endian::kLittle;
  minrt::fw::SerialInput input(uart, options.idle_polls, /*binary=*/true);
  minrt::ByteSource in = input.source();
  uart.tx(kProgramRequest);
  uint8_t len[4];
  for (uint8_t& b : len) {
    const int c = in.get();
    if (c < 0) {
      error.text("course: no program size from the host");
      send_error(uart, error);
      return MINRT_STATUS_SCENE_ERROR;
    }
    b = static_cast<uint8_t>(c);
  }
  for (uint32_t left = get_u32(len, endian); left > 0; --left) {
    if (in.get() < 0) {
      error.text("course: program ended early, ").number(static_cast<int64_t>(left)).text(" bytes missing");
      send_error(uart, error);
      return MINRT_STATUS_SCENE_ERROR;
    }
  }
  uart.tx(kSceneRequest);
  SceneTextSource text(in, endian);
  minrt::fw::SerialOutput output(uart, options.footprint);
  const minrt::RenderStatus status =
      minrt::render_sld<Math>(text.source(), output.sink(), options.render, g_state, arena, error);
  if (status != minrt::RenderStatus::kOk) {
    send_error(uart, error);
    return status_of(status);
  }
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), output.bytes());
  return MINRT_STATUS_OK;
}

// Framed protocol: collects the SLD text from S/E frames (answering K, N or
// X), renders P6 into a RowFramer that sends H and one D frame per row and
// keeps the rows in a store from the arena, sends Z, then answers Q
// requests until F (or until the line stays idle).
constexpr size_t kFramedPayload = 4096;
constexpr size_t kFramedScene = 64 * 1024;

void send_frame_text(minrt::ByteSink out, uint8_t type, const minrt::Diagnostic& text) {
  minrt::send::framed::write_frame(out, type, 0, reinterpret_cast<const uint8_t*>(text.message),
                                   static_cast<uint16_t>(text.length));
}

int serve_framed(minrt::fw::Ns16550 uart, const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
                 minrt::Diagnostic& error) {
  using namespace minrt::send::framed;
  minrt::fw::SerialInput input(uart, options.idle_polls, /*binary=*/true);
  minrt::ByteSource in = input.source();
  minrt::fw::SerialOutput link(uart, false);
  const minrt::ByteSink out = link.sink();
  uint8_t* payload = arena.alloc_zeroed<uint8_t>(kFramedPayload);
  uint8_t* scene = arena.alloc_zeroed<uint8_t>(kFramedScene);
  if (payload == nullptr || scene == nullptr) {
    error.text("framed: no room for the frame and scene buffers");
    send_frame_text(out, kError, error);
    return MINRT_STATUS_OUT_OF_MEMORY;
  }
  FrameParser parser(payload, kFramedPayload);
  SceneCollector collector(scene, kFramedScene);
  for (bool complete = false; !complete;) {
    const int c = in.get();
    if (c < 0) {
      error.text("framed: the scene did not arrive");
      send_frame_text(out, kError, error);
      return MINRT_STATUS_SCENE_ERROR;
    }
    if (parser.feed(static_cast<uint8_t>(c)) != FrameParser::kFrame) continue;
    switch (collector.frame(parser)) {
      case SceneCollector::kComplete:
        write_frame(out, kAck, 0, nullptr, 0);
        complete = true;
        break;
      case SceneCollector::kDamaged:
        write_frame(out, kNak, 0, nullptr, 0);
        break;
      case SceneCollector::kTooLarge:
        error.text("scene larger than the board's ").number(static_cast<int64_t>(kFramedScene)).text("-byte buffer");
        send_frame_text(out, kError, error);
        return MINRT_STATUS_SCENE_ERROR;
      case SceneCollector::kMore:
        break;
    }
  }
  minrt::RenderOptions render = options.render;
  render.format = minrt::PpmFormat::kP6;  // rows travel as binary RGB
  const size_t store_size = static_cast<size_t>(render.width) * static_cast<size_t>(render.height) * 3;
  uint8_t* store = arena.alloc_zeroed<uint8_t>(store_size);
  // Static: its one-row spill buffer is too big for the stack. Without a
  // store the rows are still sent once, but Q cannot be answered.
  static RowFramer framer(out, store, store == nullptr ? 0 : store_size);
  minrt::MemorySource src{collector.data(), collector.size()};
  const minrt::RenderStatus status = minrt::render_sld<Math>(src.source(), framer.sink(), render, g_state, arena, error);
  if (status != minrt::RenderStatus::kOk) {
    send_frame_text(out, kError, error_text(error));
    return status_of(status);
  }
  framer.send_end();
  for (;;) {
    const int c = in.get();
    if (c < 0) return MINRT_STATUS_OK;
    if (parser.feed(static_cast<uint8_t>(c)) != FrameParser::kFrame) continue;
    if (parser.type() == kRequest) framer.answer_request(parser);
    else if (parser.type() == kFinished) return MINRT_STATUS_OK;
    else if (parser.type() == kSceneEnd) write_frame(out, kAck, 0, nullptr, 0);
  }
}

}  // namespace

// Called by crt0; extern "C" because freestanding C++ does not treat main
// specially (it would be mangled).
extern "C" int main(int argc, char** argv) {
  minrt::fw::Ns16550 uart = minrt::fw::console_uart();
  uart.init();

  minrt::fw::FirmwareOptions options;
  minrt::Diagnostic error;
  if (!minrt::fw::parse_arguments(argc, argv, options, error)) {
    minrt::Diagnostic usage;
    usage.text("usage: ").text(error.message);
    send_error(uart, usage);
    return MINRT_STATUS_USAGE;
  }

  const minrt::fw::ArenaRegion region = minrt::fw::arena_region();
  minrt::Arena arena(region.base, region.size);
  if (options.protocol == minrt::fw::Protocol::kCourse) return serve_course(uart, options, arena, error);
  if (options.protocol == minrt::fw::Protocol::kFramed) return serve_framed(uart, options, arena, error);
  minrt::fw::SerialInput input(uart, options.idle_polls);
  minrt::fw::SerialOutput output(uart, options.footprint);
  const minrt::RenderStatus status = minrt::render_sld<Math>(
      input.source(), output.sink(), options.render, g_state, arena, error);
  if (status != minrt::RenderStatus::kOk) {
    send_error(uart, error);
    return status_of(status);
  }
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), output.bytes());
  return MINRT_STATUS_OK;
}
