#include "board_session.hpp"

#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "core/base/crc32.hpp"
#include "protocol/protocol_course_board.hpp"
#include "protocol/session.hpp"
#include "serial_stream.hpp"

#ifndef MINRT_FW_VERSION
#define MINRT_FW_VERSION "unknown"
#endif

extern "C" {
extern const uint8_t __text_start[];
extern const uint8_t __text_end[];
}

namespace minrt::fw {
namespace {

// Bytes that begin an exchange: scene text (printable ASCII and blanks),
// the raw protocol's markers, the framed sync byte, a UTF-8 byte order mark
// and the session's lead. Anything else between scenes is noise.
bool starts_exchange(uint8_t c) {
  if (c >= 0x20 && c < 0x7f) return true;
  if (c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f') return true;
  return c == MINRT_TEXTURES_MARKER || c == MINRT_CHECK_REQUEST || c == MINRT_SCENE_CHECK_REQUEST ||
         c == MINRT_TEXTURES_DEFLATE_MARKER || c == MINRT_TEXTURES_SPARSE_MARKER || c == 0xA5 || c == 0xEF ||
         c == MINRT_SESSION_LEAD;
}

const char* protocol_name(Protocol p) {
  return p == Protocol::kCourse ? "course" : p == Protocol::kFramed ? "framed" : "raw";
}

void send_line(Uart uart, const session::LineWriter& line) { uart.write(line.data(), line.size()); }

void send_error(Uart uart, const Diagnostic& error) {
  SerialOutput link(uart, false);
  send::course::write_error_line(link.sink(), error);
}

void send_identity(Uart uart, const BoardFacts& facts, const FirmwareOptions& defaults) {
  // Computed at the first greeting only (a slow rv32i takes a fraction of
  // a second over the code).
  static uint32_t build = 0;
  static bool build_known = false;
  if (!build_known) {
    build = crc32(__text_start, static_cast<size_t>(__text_end - __text_start));
    build_known = true;
  }
  session::LineWriter line(MINRT_SESSION_IDENTITY);
  char size[24];
  Diagnostic wxh;
  wxh.number(defaults.render.width).text("x").number(defaults.render.height);
  for (int i = 0; i <= wxh.length; ++i) size[i] = wxh.message[i];
  line.field("v", static_cast<uint32_t>(MINRT_SESSION_VERSION))
      .field("fw", MINRT_FW_VERSION)
      .hex_field("build", build)
      .field("board", MINRT_BOARD_NAME)
      .field("isa", MINRT_BOARD_ISA)
      .field("clock", static_cast<uint32_t>(MINRT_BOARD_CLOCK_HZ))
      .field("ram", facts.ram_bytes)
      .field("arena", facts.arena_bytes)
      .field("protocols", "raw,course,framed")
      .field("size", size)
      .field("format", defaults.render.format == PpmFormat::kP6 ? "p6" : "p3")
      .field("protocol", protocol_name(defaults.protocol))
      .field("endian", defaults.big_endian ? "big" : "little")
      .field("after", MINRT_FW_AFTER_IMAGE == MINRT_AFTER_IMAGE_HALT ? "halt" : "serve")
      .field("wait", static_cast<uint32_t>(MINRT_BOARD_WAIT_POLLS));
  line.finish();
  send_line(uart, line);
}

// One options line (after SYN o), applied to `options`; false with the
// reason in `error`.
bool apply_options(const char* text, size_t n, FirmwareOptions& options, Diagnostic& error) {
  session::LineReader line(text, n);
  if (!line.check()) {
    error.text("session: options line damaged (CRC-32 mismatch): check the baud rate");
    return false;
  }
  const char* word;
  size_t word_n;
  line.head(word, word_n);
  FirmwareOptions run = options;
  const char *key, *value;
  size_t key_n, value_n;
  char v[32];
  while (line.next(key, key_n, value, value_n)) {
    size_t k = 0;
    for (; k < value_n && k + 1 < sizeof v; ++k) v[k] = value[k];
    v[k] = 0;
    if (session::same(key, key_n, "size")) {
      if (!parse_size(v, run.render.width, run.render.height)) {
        error.text("session: bad size ").quoted(value, static_cast<int>(value_n));
        return false;
      }
    } else if (session::same(key, key_n, "format") && (session::same(value, value_n, "p3") || session::same(value, value_n, "p6"))) {
      run.render.format = value[1] == '6' ? PpmFormat::kP6 : PpmFormat::kP3;
    } else if (session::same(key, key_n, "protocol") && session::same(value, value_n, "raw")) {
      run.protocol = Protocol::kRaw;
    } else if (session::same(key, key_n, "protocol") && session::same(value, value_n, "course")) {
      run.protocol = Protocol::kCourse;
    } else if (session::same(key, key_n, "protocol") && session::same(value, value_n, "framed")) {
      run.protocol = Protocol::kFramed;
    } else if (session::same(key, key_n, "endian") &&
               (session::same(value, value_n, "little") || session::same(value, value_n, "big"))) {
      run.big_endian = value[0] == 'b';
    } else {
      error.text("session: option not supported by this board: ").quoted(key, static_cast<int>(key_n + 1 + value_n));
      return false;
    }
  }
  options = run;
  return true;
}

}  // namespace

HostEvent wait_for_host(Uart uart, uint32_t wait_polls, bool skip_noise, const BoardFacts& facts,
                        FirmwareOptions& options) {
  const FirmwareOptions defaults = options;
  for (;;) {
    int c;
    {
      SerialInput wait(uart, wait_polls, /*binary=*/true);
      c = wait.source().get();
    }
    if (c < 0) return HostEvent::kWaitedOut;
    const uint8_t b = static_cast<uint8_t>(c);
    if (b != MINRT_SESSION_LEAD) {
      if (skip_noise && !starts_exchange(b)) continue;
      SerialInput::put_back(b);
      return HostEvent::kScene;
    }
    // A session message: the rest comes at once, or it was noise.
    SerialInput in(uart, options.idle_polls == 0 ? MINRT_IDLE_POLLS_DEFAULT : options.idle_polls, true);
    ByteSource src = in.source();
    const int kind = src.get();
    if (kind == MINRT_SESSION_GREETING[1]) {
      bool whole = true;
      for (int i = 2; i < MINRT_SESSION_GREETING_SIZE && whole; ++i) whole = src.get() == MINRT_SESSION_GREETING[i];
      if (whole) send_identity(uart, facts, defaults);
      continue;
    }
    if (kind != MINRT_SESSION_OPTIONS[1]) continue;
    char text[session::kLineMax];
    size_t n = 0;
    text[n++] = static_cast<char>(kind);
    int d;
    while ((d = src.get()) >= 0 && d != '\n' && n < sizeof text) text[n++] = static_cast<char>(d);
    Diagnostic error;
    if (d != '\n') {
      error.text("session: options line cut short or too long");
      send_error(uart, error);
      continue;
    }
    FirmwareOptions run = defaults;
    if (!apply_options(text, n, run, error)) {
      send_error(uart, error);
      continue;
    }
    options = run;
    uart.write(MINRT_SESSION_ACCEPTED);
    return HostEvent::kOptions;
  }
}

}  // namespace minrt::fw
