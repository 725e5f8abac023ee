// The firmware: reads a scene from the UART, renders it with the portable
// float math and streams the image back, row by row. The scene's format is
// recognised from its first word by the registry's rule
// (formats/registry.hpp), the same as minrt's; an SLD scene gets the
// original's PPM, the others the image board_formats.hpp sends (PNG, or
// BMP for Jaworski's). On a bad scene
// or bad arguments it sends one MINRT_ERROR_MARKER line instead and returns
// a non-zero status, which crt0 hands to the test finisher.
//
// --protocol=course and --protocol=framed run the board side of host-send's
// other two protocols (docs/host-send.md) with the code the stand-in board
// in test/host_send runs too: protocol/protocol_{course,framed}_board.hpp.
// The course protocol's first stage is a boot loader: an uploaded program
// is loaded and started instead of this renderer.
#include <minrt/boot_args.h>
#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "core/base/diagnostic.hpp"
#include "core/base/peek_source.hpp"
#include "board_formats.hpp"
#include "board_session.hpp"
#include "firmware_args.hpp"
#include "firmware_layout.h"
#include "footprint.hpp"
#include "board_math.hpp"
#include "uart.hpp"
#include "program_loader.hpp"
#include "protocol/protocol_course_board.hpp"
#include "protocol/protocol_framed_board.hpp"
#include "protocol/raw_check.hpp"
#include "protocol/scene_check.hpp"
#include "render/sld/render.hpp"
#include "serial_stream.hpp"

namespace {

using Math = minrt::fw::Math;  // board_math.hpp

// The scene and the tracer's tables: static, so their size shows in .bss.
minrt::RenderState<Math> g_state;

// The raw protocol's error line (the course protocol's too).
void send_error(minrt::fw::Uart uart, const minrt::Diagnostic& error) {
  minrt::fw::SerialOutput link(uart, false);
  minrt::send::course::write_error_line(link.sink(), error);
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

// The text formats' boards' result (scene_result.hpp) as the render status.
minrt::RenderStatus status_of(minrt::fw::SceneResult r) {
  if (r == minrt::fw::SceneResult::kOk) return minrt::RenderStatus::kOk;
  return r == minrt::fw::SceneResult::kOutOfMemory ? minrt::RenderStatus::kOutOfMemory
                                                   : minrt::RenderStatus::kSceneError;
}

// What a text-format scene may use on this board.
minrt::fw::BoardScene board_scene(minrt::Arena& arena, const minrt::fw::FirmwareOptions& options,
                                  minrt::Diagnostic& error) {
  minrt::fw::BoardScene s;
  s.arena = &arena;
  s.width = options.render.width;
  s.height = options.render.height;
  s.all_features = options.all_features;
  s.error = &error;
  return s;
}

// Course protocol, a text-format scene after its marker word: the bytes
// into the arena (or in place in a checked upload), the format's image
// (PNG, BMP) back as in raw.
minrt::RenderStatus serve_course_text(minrt::send::scene_check::CourseScene& upload, minrt::ByteSink out,
                                      const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
                                      minrt::Diagnostic& error) {
  minrt::send::text::TextScene scene;
  bool too_large = false;
  if (!upload.text_scene(arena, scene, too_large, error))
    return too_large ? minrt::RenderStatus::kOutOfMemory : minrt::RenderStatus::kSceneError;
  return status_of(minrt::fw::stream_uploaded_image(scene, board_scene(arena, options, error), out));
}

// Course protocol (protocol/protocol_course_board.hpp). Stage 1, the boot
// stage: 0x99, then the program. Length 0 means "no program": this image
// renders. Otherwise the program is loaded at MINRT_PROGRAM_LOAD_ADDR and
// started there (program_loader.hpp); a program started that way (this
// renderer linked for the region, say) finds the handoff and skips stage 1.
// Stage 2: 0xaa, then the scene words, rendered as in the raw protocol.
int serve_course(minrt::fw::Uart uart, int argc, char** argv, const minrt::fw::FirmwareOptions& options,
                 minrt::Arena& arena, minrt::Diagnostic& error) {
  using namespace minrt::send::course;
  const uint32_t handoff = minrt::fw::program_handoff();
  const bool loaded = (handoff & MINRT_PROGRAM_LOADED) != 0;
  const bool big = loaded ? (handoff & MINRT_PROGRAM_BIG_ENDIAN) != 0 : options.big_endian;
  const Endian endian = big ? Endian::kBig : Endian::kLittle;
  minrt::fw::SerialInput input(uart, options.idle_polls, /*binary=*/true);
  const minrt::ByteSource in = input.source();
  minrt::fw::SerialOutput link(uart, false);
  const minrt::ByteSink out = link.sink();
  if (!loaded) {
    const minrt::fw::ProgramRegion region = minrt::fw::program_region();
    uint32_t length = 0;
    if (receive_program(in, out, endian, region.base, region.capacity, length, error) != ProgramResult::kReceived)
      return MINRT_STATUS_BAD_PROGRAM;
    if (length > 0) minrt::fw::start_program(argc, argv, big);
  }
  minrt::fw::SerialOutput image(uart, options.footprint);
  minrt::send::raw_check::CheckedSink reply(image.sink(), false);
  minrt::RenderStatus status = minrt::RenderStatus::kOk;
  const bool ok = serve_scene(
      in, out,
      [&](minrt::ByteSource words) {
        // A checked upload is held and checked first; then the first word
        // tells a text-format upload from SLD words (scene_check.hpp).
        minrt::send::scene_check::CourseScene scene;
        if (!scene.begin(words, endian, arena, reply, error)) {
          status = scene.too_large() ? minrt::RenderStatus::kOutOfMemory : minrt::RenderStatus::kSceneError;
          return false;
        }
        if (scene.is_text()) {
          status = serve_course_text(scene, reply.sink(), options, arena, error);
          return status == minrt::RenderStatus::kOk;
        }
        status = minrt::render_sld_values<Math>(CourseWordValues<Math::real>(scene.words(), endian), reply.sink(),
                                                options.render, g_state, arena, error);
        return status == minrt::RenderStatus::kOk;
      },
      error);
  if (ok) reply.end();
  if (!ok) return status_of(status);
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), image.bytes());
  return MINRT_STATUS_OK;
}

// Framed protocol (protocol/protocol_framed_board.hpp): the frame buffer
// comes from the arena; the upload is collected in all the rest of it (its
// top end) and moved to the very top once complete, so the scene text, and
// a CS418 scene's textures read in place, take no more than their size. An
// SLD scene renders as P6 into the RowFramer over a 3*W*H-byte row store; a
// text-format upload (text_scene_upload.hpp) sends RGBA rows over a
// 4*W*H store taken once the scene gives the size. Without room for the
// store the rows are sent once, but Q cannot be answered.
constexpr size_t kFramedPayload = 4096;

// An RGBA row sink that gives the framer its row store when the size is known.
struct StoreOnBegin {
  minrt::send::framed::RowFramer& framer;
  minrt::Arena& arena;
  void begin(int width, int height) {
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height) * 4;
    framer.attach_store(arena.alloc_zeroed<uint8_t>(n), n);
    framer.begin(width, height);
  }
  void row(int y, const uint8_t* rgba) { framer.row(y, rgba); }
  void end() { framer.end(); }
};

int serve_framed(minrt::fw::Uart uart, const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
                 minrt::Diagnostic& error) {
  using namespace minrt::send::framed;
  const uint32_t idle = options.idle_polls > UINT32_MAX / MINRT_FRAMED_IDLE_FACTOR
                            ? UINT32_MAX
                            : options.idle_polls * MINRT_FRAMED_IDLE_FACTOR;
  minrt::fw::SerialInput input(uart, idle, /*binary=*/true);
  minrt::fw::SerialOutput link(uart, false);
  const minrt::ByteSink out = link.sink();
  uint8_t* payload = arena.alloc_zeroed<uint8_t>(kFramedPayload);
  const size_t top = arena.top_mark();
  const size_t room = top > arena.used() ? top - arena.used() : 0;
  uint8_t* scene = payload == nullptr || room == 0 ? nullptr : arena.alloc_top<uint8_t>(room);
  if (scene == nullptr) {
    error.text("framed: no room for the frame and scene buffers");
    write_error_frame(out, error);
    return MINRT_STATUS_OUT_OF_MEMORY;
  }
  FrameParser parser(payload, kFramedPayload);
  SceneCollector collector(scene, room);
  RowFramer framer(out, nullptr, 0);
  minrt::RenderStatus status = minrt::RenderStatus::kOk;
  const BoardResult result = serve_board(
      input.source(), out, parser, collector, framer,
      [&](minrt::ByteSource, RowFramer& rows) {
        const size_t n = collector.size();
        uint8_t* data = scene + (room - n);
        for (size_t i = n; i-- > 0;) data[i] = scene[i];  // upwards: from the end
        arena.release_top(top - n);
        minrt::send::text::TextScene text;
        bool header_ok = false;
        if (minrt::send::text::view_framed(data, n, text, header_ok, error)) {
          if (!header_ok) {
            status = minrt::RenderStatus::kSceneError;
            return false;
          }
          rows.set_pixel_bytes(4);
          StoreOnBegin sink{rows, arena};
          status = status_of(minrt::fw::render_uploaded_rows(text, board_scene(arena, options, error),
                                                             minrt::rgba_row_sink_of(sink)));
          return status == minrt::RenderStatus::kOk;
        }
        const minrt::RenderOptions& render = options.render;
        const size_t store_size = static_cast<size_t>(render.width) * static_cast<size_t>(render.height) * 3;
        rows.attach_store(arena.alloc_zeroed<uint8_t>(store_size), store_size);
        minrt::MemorySource sld{data, n};
        status = minrt::render_sld_rows<Math>(minrt::SldTextValues<Math::real>(sld.source()), minrt::row_sink_of(rows),
                                              render, g_state, arena, error);
        return status == minrt::RenderStatus::kOk;
      },
      error);
  switch (result) {
    case BoardResult::kDone: return MINRT_STATUS_OK;
    case BoardResult::kRenderFailed: return status_of(status);
    default: return MINRT_STATUS_SCENE_ERROR;
  }
}

// Raw protocol: the scene as text (a checked upload or a CRC-32 request
// first, textures ahead of the text), the format's image back.
int serve_raw(minrt::fw::Uart uart, const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
              minrt::Diagnostic& error) {
  minrt::fw::SerialInput input(uart, options.idle_polls);
  minrt::fw::SerialOutput uart_out(uart, options.footprint);
  // The host's request for the CRC-32 trailer comes first (protocol/raw_check.hpp).
  minrt::PeekSource request(input.source());
  const int lead = request.first_nonblank();
  // A checked upload is held whole and checked before anything reads it
  // (protocol/scene_check.hpp); its textures are read in place.
  minrt::send::scene_check::CheckedUpload upload;
  minrt::send::textures::Table* textures = nullptr;
  if (lead == MINRT_SCENE_CHECK_REQUEST) {
    minrt::fw::SerialInput binary(uart, options.idle_polls, /*binary=*/true);
    const auto r = upload.receive_raw(binary.source(), arena, error);
    // The table only for an upload that starts with textures.
    const bool has_textures = r == minrt::send::scene_check::Result::kOk && upload.has_textures();
    if (has_textures) {
      textures = arena.alloc_zeroed<minrt::send::textures::Table>(1);
      if (textures == nullptr) error.text("no room for the texture table");
    }
    if (r != minrt::send::scene_check::Result::kOk ||
        (has_textures && (textures == nullptr || !upload.view_textures(arena, *textures, error)))) {
      send_error(uart, error);
      return r == minrt::send::scene_check::Result::kTooLarge || textures == nullptr ? MINRT_STATUS_OUT_OF_MEMORY
                                                                                  : MINRT_STATUS_SCENE_ERROR;
    }
  }
  const bool checked = lead == MINRT_CHECK_REQUEST || upload.received();
  minrt::send::raw_check::CheckedSink output(uart_out.sink(), checked);
  minrt::PeekSource scene(upload.received() ? upload.text() : checked ? input.source() : request.source());
  const int first = scene.first_nonblank();
  // A scene's textures, decoded by host-send (and deflated), come first.
  minrt::PeekSource after_textures(input.source());
  if (minrt::send::textures::is_marker(first)) {
    minrt::fw::SerialInput binary(uart, options.idle_polls, /*binary=*/true);
    textures = arena.alloc_zeroed<minrt::send::textures::Table>(1);
    if (textures == nullptr) error.text("no room for the texture table");
    const bool packed = first != MINRT_TEXTURES_MARKER;
    if (textures == nullptr ||
        !(packed ? minrt::send::textures::receive_compressed(binary.source(), arena, *textures, error, first)
                 : minrt::send::textures::receive(binary.source(), arena, *textures, error))) {
      send_error(uart, error);
      return MINRT_STATUS_OUT_OF_MEMORY;
    }
  }
  // The format by the registry's rule, from the first word (SLD: a number).
  minrt::PeekSource& text = textures != nullptr && !upload.received() ? after_textures : scene;
  text.first_nonblank();
  minrt::formats::TextStart start;
  while (!(start = minrt::formats::text_start(text.kept(), static_cast<size_t>(text.kept_count()))).complete &&
         text.extend()) {
  }
  const minrt::formats::Format& format = minrt::formats::format_of_text(start);
  minrt::RenderStatus status;
  if (format.reply == minrt::formats::ImageKind::kPpm) {
    status = minrt::render_sld<Math>(text.source(), output.sink(), options.render, g_state, arena, error);
  } else {
    minrt::fw::BoardScene s = board_scene(arena, options, error);
    s.text = text.source();
    s.textures = textures;
    status = status_of(minrt::fw::stream_board_image(format, s, output.sink()));
  }
  if (status != minrt::RenderStatus::kOk) {
    send_error(uart, error);
    return status_of(status);
  }
  output.end();
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), uart_out.bytes());
  return MINRT_STATUS_OK;
}

// One exchange in the protocol `options` names (a byte the wait took off
// the line is put back for it).
int serve(minrt::fw::Uart uart, int argc, char** argv, const minrt::fw::FirmwareOptions& options,
          minrt::Arena& arena, minrt::Diagnostic& error) {
  if (options.protocol == minrt::fw::Protocol::kCourse) return serve_course(uart, argc, argv, options, arena, error);
  if (options.protocol == minrt::fw::Protocol::kFramed) return serve_framed(uart, options, arena, error);
  return serve_raw(uart, options, arena, error);
}

}  // namespace

// Called by crt0; extern "C" because freestanding C++ does not treat main
// specially (it would be mangled).
//
// With boot arguments (firmware-sim's runs: argv[0] is the ELF) the
// firmware serves one exchange and halts with its status. Without any (a
// real board, QEMU, firmware-sim --real-board) it is a board: it waits for
// a host for as long as it takes (board key wait_polls may set a limit),
// answers the session's greeting and options (protocol/session.hpp),
// serves the exchange, and waits again, unless the board file says
// after_image = halt. With --protocol=course the board speaks first
// (0x99), as the course's server expects.
extern "C" int main(int argc, char** argv) {
  minrt::fw::Uart uart = minrt::fw::console_uart();
  uart.init();

  minrt::fw::FirmwareOptions options;
  minrt::Diagnostic error;
  if (!minrt::fw::parse_arguments(argc, argv, options, error)) {
    minrt::Diagnostic usage;
    usage.text("usage: ").text(error.message);
    send_error(uart, usage);
    return MINRT_STATUS_USAGE;
  }

  minrt::fw::ArenaRegion region = minrt::fw::arena_region();
  // A machine with more RAM than the board (firmware-sim --ram-size): the
  // RAM above the linked 4 MiB, when larger. The simulator's sp sits just
  // below the boot arguments at the top of that RAM, so the stack's share
  // stays out of the arena.
  const uint32_t ram = options.ram_mib << 20;
  if (ram > MINRT_RAM_DEFAULT_SIZE + MINRT_BOOT_ARGS_MAX + MINRT_FW_STACK_SIZE) {
    const size_t above = ram - MINRT_RAM_DEFAULT_SIZE - MINRT_BOOT_ARGS_MAX - MINRT_FW_STACK_SIZE;
    if (above > region.size)
      region = {reinterpret_cast<void*>(static_cast<uintptr_t>(MINRT_RAM_BASE + MINRT_RAM_DEFAULT_SIZE)), above};
  }
  if ((minrt::fw::program_handoff() & MINRT_PROGRAM_LOADED) != 0) {
    minrt::Arena arena(region.base, region.size);
    return serve_course(uart, argc, argv, options, arena, error);
  }
  const minrt::fw::BoardFacts facts{ram > MINRT_RAM_DEFAULT_SIZE ? ram : MINRT_RAM_DEFAULT_SIZE,
                                    static_cast<uint32_t>(region.size)};
  const bool board = argc == 0;
  for (;;) {
    minrt::Arena arena(region.base, region.size);
    minrt::fw::FirmwareOptions run = options;
    minrt::Diagnostic failure;
    // The course protocol's board speaks first (0x99): no wait.
    if (run.protocol != minrt::fw::Protocol::kCourse) {
      const uint32_t wait = board ? MINRT_BOARD_WAIT_POLLS : options.idle_polls;
      const minrt::fw::HostEvent e = minrt::fw::wait_for_host(uart, wait, board, facts, run);
      // A board that waited out its limit stops as a run without input
      // does: the raw reader finds the input ended.
      if (e == minrt::fw::HostEvent::kWaitedOut && board) return MINRT_STATUS_SCENE_ERROR;
      // A run that got nothing: the protocol finds the input ended at once
      // (not after a second idle count).
      if (e == minrt::fw::HostEvent::kWaitedOut) minrt::fw::SerialInput::put_back(MINRT_END_OF_INPUT);
    }
    const int status = serve(uart, argc, argv, run, arena, failure);
    if (!board || MINRT_FW_AFTER_IMAGE == MINRT_AFTER_IMAGE_HALT) return status;
    minrt::fw::console_uart().drain();
  }
}
