// host-send's command line: its options (one table, which the help is
// printed from: posix/command_line.hpp), their checks, the exit statuses.
#pragma once

#include <cstdint>
#include <string>

#include "checked_reply.hpp"
#include "port.hpp"
#include "ppm_receiver.hpp"

namespace minrt::send {

enum class Protocol { kRaw, kCourse, kFramed };

struct Options {
  std::string port;          // --port DEV or usb:VID:PID[:SERIAL]
  bool sim = false;          // --sim: firmware-sim on a pty (one of --port and --sim is required)
  std::string sim_elf;       // --sim ELF
  bool rtl = false;          // --rtl: the RTL harness (minrt-rtl) in firmware-sim's place
  std::string sim_board;     // --board FILE: the simulated board's description (with -p: the board expected)
  std::string sim_binary;    // --sim-binary
  std::uint64_t sim_ram_bytes = 0;  // --sim-ram-size (0: the board's 4 MiB)
  bool baud_given = false;
  PortSettings port_settings;
  Protocol protocol = Protocol::kRaw;
  ImageSpec spec{512, 512, PpmKind::kP3};
  bool size_given = false;   // miniRT's default size differs (800x600, as minrt)
  std::string scene;
  std::string output;        // -o; default SCENE's stem + ".ppm" (CS418: the png line's name)
  bool output_given = false;
  bool allow_any_output = false;  // --allow-any-output: the scene's own output name may go anywhere
  bool write_through = false;  // --write-through: into a FIFO, device or link given to -o
  bool as_received = false;    // --as-received: a PNG as the board streamed it (stored deflate)
  double first_byte_timeout = 120;
  double idle_timeout = 30;
  double reply_timeout = 0;       // --reply-timeout; 0: from the image and the line speed
  double sim_start_timeout = 10;  // --sim-start-timeout
  std::string verify_ref;
  std::string expect_sha256;
  RawCheck check = RawCheck::kAuto;  // raw: --check / --no-check (the CRC-32 trailer)
  std::string program;       // course: --program FILE
  bool big_endian = false;   // course: --endian
  bool full_textures = false;  // --full-textures: every texel (default: those the render reads, CS418)
  bool list = false;
  bool probe = false;        // --probe: print the board's identity and exit
  bool handshake = true;     // --no-handshake: a board (-p) without the session
  bool quiet = false;
  bool progress_forced = false;  // --progress: draw even without a terminal
  bool show = false;             // --show: the received image in a window
};

enum class ParseResult { kRun, kHelp, kVersion, kError };

// Fills `options` from argv; kError with the one-line message in `error`.
ParseResult parse_command_line(int argc, char** argv, Options& options, std::string& error);
void print_help();

// SCENE's name without its folder and extension, with `extension` (".ppm").
std::string default_output(const std::string& scene, const char* extension);

// Exit statuses (a signal ends host-send with its own: 130 for Ctrl-C).
constexpr int kExitOk = 0;
constexpr int kExitLink = 1;
constexpr int kExitUsage = 2;
constexpr int kExitFirmware = 3;

}  // namespace minrt::send
