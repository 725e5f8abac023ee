// The firmware: reads an SLD scene from the UART, renders it with the
// portable float math and streams the PPM back, row by row. A scene whose
// first word starts with a letter is a CS418 file (cs418_board.hpp): its
// image goes back as a streamed PNG; one that starts with `#` or a header
// field of Jaworski's format (jaworski_board.hpp) gets a streamed BMP; one
// that starts with a miniRT element (minirt_board.hpp) a streamed PNG; one
// that starts with host-send's `/*` marker is an expanded EASTRAY scene
// (eastray_board.hpp) and gets a streamed PNG too. On a bad scene
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
#include "cs418_board.hpp"
#include "jaworski_board.hpp"
#include "minirt_board.hpp"
#include "eastray_board.hpp"
#include "firmware_args.hpp"
#include "firmware_layout.h"
#include "footprint.hpp"
#include "board_math.hpp"
#include "ns16550.hpp"
#include "program_loader.hpp"
#include "protocol/protocol_course_board.hpp"
#include "protocol/protocol_framed_board.hpp"
#include "protocol/raw_check.hpp"
#include "render/sld/render.hpp"
#include "serial_stream.hpp"
#include "text_scene_board.hpp"

namespace {

using Math = minrt::fw::Math;  // board_math.hpp

// The scene and the tracer's tables: static, so their size shows in .bss.
minrt::RenderState<Math> g_state;

// The raw protocol's error line (the course protocol's too).
void send_error(minrt::fw::Ns16550 uart, const minrt::Diagnostic& error) {
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

// Course protocol, a CS418, Jaworski, miniRT or EASTRAY scene after its marker word: the
// bytes into the arena, the format's image (PNG, BMP) back as in raw.
minrt::RenderStatus serve_course_text(minrt::ByteSource in, minrt::send::course::Endian endian, minrt::ByteSink out,
                                      const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
                                      minrt::Diagnostic& error) {
  minrt::send::text::TextScene scene;
  bool too_large = false;
  if (!minrt::send::text::read_course(in, endian, arena, scene, too_large, error))
    return too_large ? minrt::RenderStatus::kOutOfMemory : minrt::RenderStatus::kSceneError;
  return status_of(minrt::fw::stream_text_scene(scene, out, arena, options.render.width, options.render.height,
                                                options.all_features, error));
}

// Course protocol (protocol/protocol_course_board.hpp). Stage 1, the boot
// stage: 0x99, then the program. Length 0 means "no program": this image
// renders. Otherwise the program is loaded at MINRT_PROGRAM_LOAD_ADDR and
// started there (program_loader.hpp); a program started that way (this
// renderer linked for the region, say) finds the handoff and skips stage 1.
// Stage 2: 0xaa, then the scene words, rendered as in the raw protocol.
int serve_course(minrt::fw::Ns16550 uart, int argc, char** argv, const minrt::fw::FirmwareOptions& options,
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
  minrt::RenderStatus status = minrt::RenderStatus::kOk;
  const bool ok = serve_scene(
      in, out,
      [&](minrt::ByteSource words) {
        // The first word tells a text-format upload (text_scene_upload.hpp)
        // from SLD words; for SLD it is handed back to the reader.
        uint8_t first[4];
        int got = 0;
        for (int c; got < 4 && (c = words.get()) >= 0;) first[got++] = static_cast<uint8_t>(c);
        if (got == 4 && minrt::send::text::is_marker(first, endian)) {
          status = serve_course_text(words, endian, image.sink(), options, arena, error);
          return status == minrt::RenderStatus::kOk;
        }
        minrt::send::text::PrefixSource replay(first, got, words);
        status = minrt::render_sld_values<Math>(CourseWordValues<Math::real>(replay.source(), endian), image.sink(),
                                                options.render, g_state, arena, error);
        return status == minrt::RenderStatus::kOk;
      },
      error);
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

int serve_framed(minrt::fw::Ns16550 uart, const minrt::fw::FirmwareOptions& options, minrt::Arena& arena,
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
          status = status_of(
              minrt::fw::render_text_scene_rows(text, minrt::rgba_row_sink_of(sink), arena, options.render.width,
                                                options.render.height, options.all_features, error));
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

// Raw protocol: a text-format scene as the first bytes tell it, after any
// texture preamble. Each format's board renderer (*_board.hpp) is an entry;
// the first that claims the scene renders it, and a scene none claims is SLD.
struct RawScene {
  minrt::ByteSource text;
  minrt::ByteSink out;
  minrt::Arena& arena;
  const minrt::fw::FirmwareOptions& options;
  const minrt::send::textures::Table* textures;
  minrt::Diagnostic& error;
};

struct RawFormat {
  bool (*claims)(int first_byte, const char* first_word);
  minrt::RenderStatus (*render)(const RawScene& scene);
};

// In the order they are tried: EASTRAY's `/*` marker, Jaworski's header
// fields or `#`, miniRT's element identifiers, then any other word that
// starts with a letter is CS418.
constexpr RawFormat kRawFormats[] = {
    {[](int first, const char*) { return minrt::fw::is_eastray_start(first); },
     [](const RawScene& s) { return status_of(minrt::fw::render_eastray(s.text, s.out, s.arena, s.textures, s.error)); }},
    {[](int first, const char* word) { return minrt::fw::is_jaworski_start(first, word); },
     [](const RawScene& s) { return status_of(minrt::fw::render_jaworski(s.text, s.out, s.arena, s.error)); }},
    {[](int, const char* word) { return minrt::fw::is_minirt_start(word); },
     [](const RawScene& s) {  // PNG at the board's --size
       return status_of(minrt::fw::render_minirt(s.text, s.out, s.arena, s.options.render.width,
                                                 s.options.render.height, s.options.all_features, s.textures,
                                                 s.error));
     }},
    {[](int first, const char*) { return (first >= 'a' && first <= 'z') || (first >= 'A' && first <= 'Z'); },
     [](const RawScene& s) {
       return status_of(minrt::fw::render_cs418(s.text, s.out, s.arena, s.options.all_features, s.textures, s.error));
     }},
};

const RawFormat* find_raw_format(int first_byte, const char* first_word) {
  // SLD's first value is a number: a digit, sign or point, which starts no
  // text format, so the common case skips the word lists.
  if ((first_byte >= '0' && first_byte <= '9') || first_byte == '-' || first_byte == '+' || first_byte == '.')
    return nullptr;
  for (const RawFormat& f : kRawFormats)
    if (f.claims(first_byte, first_word)) return &f;
  return nullptr;
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
  minrt::Arena arena(region.base, region.size);
  if (options.protocol == minrt::fw::Protocol::kCourse || (minrt::fw::program_handoff() & MINRT_PROGRAM_LOADED) != 0)
    return serve_course(uart, argc, argv, options, arena, error);
  if (options.protocol == minrt::fw::Protocol::kFramed) return serve_framed(uart, options, arena, error);
  minrt::fw::SerialInput input(uart, options.idle_polls);
  minrt::fw::SerialOutput uart_out(uart, options.footprint);
  // The host's request for the CRC-32 trailer comes first (protocol/raw_check.hpp).
  minrt::PeekSource request(input.source());
  const bool checked = request.first_nonblank() == MINRT_CHECK_REQUEST;
  minrt::send::raw_check::CheckedSink output(uart_out.sink(), checked);
  minrt::PeekSource scene(checked ? input.source() : request.source());
  int first = scene.first_nonblank();
  // A CS418 scene's textures, decoded by host-send, come first.
  minrt::send::textures::Table* textures = nullptr;
  minrt::PeekSource after_textures(input.source());
  if (first == MINRT_TEXTURES_MARKER) {
    minrt::fw::SerialInput binary(uart, options.idle_polls, /*binary=*/true);
    textures = arena.alloc_zeroed<minrt::send::textures::Table>(1);
    if (textures == nullptr) error.text("no room for the texture table");
    if (textures == nullptr || !minrt::send::textures::receive(binary.source(), arena, *textures, error)) {
      send_error(uart, error);
      return MINRT_STATUS_OUT_OF_MEMORY;
    }
    first = after_textures.first_nonblank();
  }
  minrt::PeekSource& text = textures != nullptr ? after_textures : scene;
  char word[16];
  text.first_word(word, sizeof word);
  const RawFormat* format = find_raw_format(first, word);
  const minrt::RenderStatus status =
      format != nullptr
          ? format->render(RawScene{text.source(), output.sink(), arena, options, textures, error})
          : minrt::render_sld<Math>(scene.source(), output.sink(), options.render, g_state, arena, error);
  if (status != minrt::RenderStatus::kOk) {
    send_error(uart, error);
    return status_of(status);
  }
  output.end();
  if (options.footprint) minrt::fw::print_footprint(uart, arena.used(), uart_out.bytes());
  return MINRT_STATUS_OK;
}
