#include "cli.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <unistd.h>

#include "core/base/text_numbers.hpp"
#include "posix/command_line.hpp"
#include "posix/input_file.hpp"
#include "verify.hpp"

namespace minrt::send {

namespace {

using minrt::cli::Option;

bool ends_with(const std::string& s, const char* tail) {
  const std::string t = tail;
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

bool is_elf(const char* path) {
  // Opened by the one input rule: a FIFO named here must not block.
  std::string why;
  const int fd = minrt::host::open_regular_file(path, why);
  if (fd < 0) return false;
  unsigned char m[4] = {};
  const bool ok = ::read(fd, m, 4) == 4 && m[0] == 0x7f && m[1] == 'E' && m[2] == 'L' && m[3] == 'F';
  ::close(fd);
  return ok;
}

// `--sim [ELF]`: the next argument is the firmware when it is an ELF file
// or is named like one; otherwise it is the scene or another option.
bool names_firmware(const char* next) { return next[0] != '-' && (is_elf(next) || ends_with(next, ".elf")); }

struct Group {
  const char* title;
  std::vector<Option> options;
};

const std::vector<Group>& option_groups() {
  static const std::vector<Group> groups = {
      {"link",
       {
           {"port", 'p', "DEV", "serial device, or usb:VID:PID[:SERIAL] (see --list)"},
           {"sim", 0, "ELF",
            "run the firmware in firmware-sim (ELF defaults to\n"
            "$MINRT_FIRMWARE_ELF, else the installed firmware\n"
            "(PREFIX/share/minrt/firmware), else the build's)",
            names_firmware},
           {"rtl", 0, "ELF",
            "run the firmware on a CPU's RTL in the Verilator\n"
            "harness minrt-rtl (docs/rtl.md; ELF defaults to the\n"
            "build's minrt-rtl-reference.elf, the harness to\n"
            "$MINRT_RTL_HARNESS, else the build's)",
            names_firmware},
           {"sim-ram-size", 0, "NM",
            "RAM of the simulated board (default 4M, the\n"
            "board's); for CS418 scenes whose textures do not fit\n"
            "(implies --sim)"},
           {"board", 0, "FILE",
            "the simulated board's description (boards/*.board:\n"
            "memory map, UART, halt, ISA; implies --sim; default\n"
            "the reference); with -p the board expected there"},
           {"sim-binary", 0, "PATH",
            "simulator to run (default: $MINRT_FIRMWARE_SIM, else\n"
            "the firmware-sim next to host-send, else the build's)"},
           {"baud", 'b', "N",
            "line rate, any value (default 115200; with --sim it\n"
            "paces the simulated UART)"},
           {"flow", 0, "none|rtscts|xonxoff",
            "flow control (default none; xonxoff is unsafe for\n"
            "binary P6 and the framed protocol)"},
           {"list", 0, nullptr, "list serial ports with their USB identities"},
           {"probe", 0, nullptr,
            "greet the board on -p and print its identity\n"
            "(firmware, board, ISA, memory, defaults); no scene"},
           {"no-handshake", 0, nullptr,
            "-p: send at once, without greeting the board and\n"
            "sending the run's options (a firmware without the\n"
            "session: it renders at its build-time defaults)"},
       }},
      {"protocol and image",
       {
           {"protocol", 0, "raw|course|framed", "the serial protocol (default raw)"},
           {"size", 0, "WxH", "image size the board renders (default 512x512)"},
           {"format", 0, "p3|p6", "PPM flavour the board sends (default p3)"},
           {"program", 0, "FILE", "course protocol: program sent after 0x99"},
           {"endian", 0, "little|big", "course protocol: byte order of the scene words"},
           {"full-textures", 0, nullptr,
            "send every texel of a CS418 scene's textures; by\n"
            "default only the tiles host-send's own render of the\n"
            "scene reads go (the board reports any other read,\n"
            "and with --sim the textures then go whole)"},
       }},
      {"output and checks",
       {
           {"output", 'o', "FILE",
            "image file (default SCENE's name with .ppm; - is\n"
            "stdout); written only when complete and valid; a\n"
            "FIFO, device or symbolic link is refused"},
           {"write-through", 0, nullptr, "write into a FIFO, device or link given to -o"},
           {"allow-any-output", 0, nullptr,
            "let a scene's own output name (CS418 png line,\n"
            "EASTRAY output) leave the scene's and the working\n"
            "folder"},
           {"as-received", 0, nullptr,
            "write a PNG as the board sent it (stored deflate); by\n"
            "default it is compressed, with the same pixels"},
           {"verify", 0, "REF.ppm",
            "compare with a P3 or P6 reference: differing pixels,\n"
            "maximum channel error, PSNR"},
           {"expect-sha256", 0, "HEX", "refuse the image unless its bytes have this SHA-256"},
           {"check", 0, nullptr,
            "raw, course: require the board's CRC-32 trailer (by\n"
            "default it is asked for and checked when announced)"},
           {"no-check", 0, nullptr,
            "raw, course: send the scene without its CRC-32 and do\n"
            "not ask for the reply's (the plain protocol bytes)"},
           {"first-byte-timeout", 0, "S", "wait for the reply at most S seconds (default 120)"},
           {"idle-timeout", 0, "S", "longest silence within the reply (default 30)"},
           {"reply-timeout", 0, "S",
            "raw, course: the whole reply within S seconds of the\n"
            "upload (default: the first-byte timeout + 8 times the\n"
            "image's time on the line, at least 20 s more)"},
           {"sim-start-timeout", 0, "S", "--sim: wait at most S seconds for the simulator's pty\n(default 10)"},
           {"progress", 0, nullptr,
            "draw the progress line even when stderr is no\n"
            "terminal (on a terminal it is drawn unless -q)"},
           {"show", 's', nullptr,
            "show the image in a window (SDL2) as its rows arrive;\n"
            "it stays until closed (ESC, q, close button); without\n"
            "a display a one-line warning"},
           {"quiet", 'q', nullptr, "no progress line and no summary"},
           {"help", 'h', nullptr, "this text"},
           {"version", 0, nullptr, "version"},
       }},
  };
  return groups;
}

const std::vector<Option>& options_table() {
  static const std::vector<Option> table = [] {
    std::vector<Option> all;
    for (const Group& g : option_groups()) all.insert(all.end(), g.options.begin(), g.options.end());
    return all;
  }();
  return table;
}

bool parse_seconds(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == 0 && v > 0 && v < 1e6;
}

// One option's value into `o`; "" or the error message.
std::string take_option(const std::string& name, const std::string& v, Options& o, bool& help, bool& version) {
  if (name == "help") help = true;
  else if (name == "version") version = true;
  else if (name == "port") o.port = v;
  else if (name == "sim") {
    o.sim = true;
    o.sim_elf = v;
  } else if (name == "rtl") {
    o.sim = o.rtl = true;  // the harness takes firmware-sim's command line
    o.sim_elf = v;
  } else if (name == "board") {
    o.sim_board = v;  // with -p the board expected; else the simulated one (parse_command_line)
  } else if (name == "sim-binary") {
    o.sim_binary = v;
    o.sim = true;  // naming a simulator asks for one
  } else if (name == "sim-ram-size") {
    uint32_t mib = 0;
    const char* p = v.c_str();
    if (!minrt::parse_decimal(p, 'M', 1024, mib) || *p != 'M' || p[1] != 0 || mib < 4)
      return "bad --sim-ram-size '" + v + "': expected NM, 4M..1024M";
    o.sim_ram_bytes = static_cast<std::uint64_t>(mib) << 20;
    o.sim = true;
  } else if (name == "baud") {
    char* end = nullptr;
    const unsigned long b = std::strtoul(v.c_str(), &end, 10);
    if (end == v.c_str() || *end != 0 || b < 50 || b > 20000000) return "bad --baud '" + v + "': expected 50..20000000";
    o.port_settings.baud = static_cast<std::uint32_t>(b);
    o.baud_given = true;
  } else if (name == "flow") {
    if (v == "none") o.port_settings.flow = Flow::kNone;
    else if (v == "rtscts") o.port_settings.flow = Flow::kRtsCts;
    else if (v == "xonxoff") o.port_settings.flow = Flow::kXonXoff;
    else return "bad --flow '" + v + "': expected none, rtscts or xonxoff";
  } else if (name == "protocol") {
    if (v == "raw") o.protocol = Protocol::kRaw;
    else if (v == "course") o.protocol = Protocol::kCourse;
    else if (v == "framed") o.protocol = Protocol::kFramed;
    else return "bad --protocol '" + v + "': expected raw, course or framed";
  } else if (name == "size") {
    if (!minrt::parse_size(v.c_str(), o.spec.width, o.spec.height)) return "bad --size '" + v + "': expected WxH, each 1..4096";
    o.size_given = true;
  } else if (name == "format") {
    if (v == "p3" || v == "P3") o.spec.kind = PpmKind::kP3;
    else if (v == "p6" || v == "P6") o.spec.kind = PpmKind::kP6;
    else return "bad --format '" + v + "': expected p3 or p6";
  } else if (name == "program") o.program = v;
  else if (name == "endian") {
    if (v == "little") o.big_endian = false;
    else if (v == "big") o.big_endian = true;
    else return "bad --endian '" + v + "': expected little or big";
  } else if (name == "output") {
    o.output = v;
    o.output_given = true;
  } else if (name == "allow-any-output") o.allow_any_output = true;
  else if (name == "write-through") o.write_through = true;
  else if (name == "as-received") o.as_received = true;
  else if (name == "full-textures") o.full_textures = true;
  else if (name == "verify") o.verify_ref = v;
  else if (name == "expect-sha256") {
    if (!valid_sha256_hex(v)) return "bad --expect-sha256: expected 64 hex digits";
    o.expect_sha256 = v;
  } else if (name == "check") o.check = RawCheck::kRequire;
  else if (name == "no-check") o.check = RawCheck::kOff;
  else if (name == "first-byte-timeout" || name == "idle-timeout" || name == "reply-timeout" ||
           name == "sim-start-timeout") {
    double s = 0;
    if (!parse_seconds(v, s)) return "bad --" + name + " '" + v + "': expected seconds > 0";
    (name == "idle-timeout"        ? o.idle_timeout
     : name == "reply-timeout"     ? o.reply_timeout
     : name == "sim-start-timeout" ? o.sim_start_timeout
                                   : o.first_byte_timeout) = s;
  } else if (name == "list") o.list = true;
  else if (name == "probe") o.probe = true;
  else if (name == "no-handshake") o.handshake = false;
  else if (name == "quiet") o.quiet = true;
  else if (name == "progress") o.progress_forced = true;
  else if (name == "show") o.show = true;
  return "";
}

// The combinations the options cannot make; "" when the run can go ahead.
std::string check_combination(const Options& o) {
  if (!o.port.empty() && o.sim) return "--port and --sim exclude each other";
  if (o.probe) {
    if (o.port.empty()) return "--probe needs the board's port (-p DEV)";
    if (!o.handshake) return "--probe and --no-handshake exclude each other";
    if (!o.scene.empty()) return "--probe takes no scene ('" + o.scene + "')";
    return "";
  }
  if (o.scene.empty()) return "no scene file given";
  // Never render on the simulator without being asked: a student with a
  // board must not believe the board rendered the image.
  if (o.port.empty() && !o.sim)
    return "no board given: --port DEVICE for a board (host-send --list shows them), or --sim for firmware-sim";
  if (o.protocol != Protocol::kCourse && !o.program.empty()) return "--program only applies to --protocol course";
  if (o.protocol == Protocol::kFramed && o.check == RawCheck::kRequire)
    return "--check applies to --protocol raw and course (framed checks every frame)";
  return "";
}

}  // namespace

std::string default_output(const std::string& scene, const char* extension) {
  std::string base = scene;
  const std::size_t slash = base.rfind('/');
  if (slash != std::string::npos) base = base.substr(slash + 1);
  const std::size_t dot = base.rfind('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  if (base.empty()) base = "image";
  return base + extension;
}

void print_help() {
  std::fputs(
      "Usage: host-send (-p DEV | --sim [ELF]) [OPTIONS] SCENE [-o OUT]\n"
      "   or: host-send --probe -p DEV\n"
      "   or: host-send --list\n"
      "Sends a scene to the renderer firmware over a serial line and receives the\n"
      "image it renders: from a board (--port) or from firmware-sim started on a\n"
      "pseudo-terminal (--sim); one of the two is required. An SLD scene comes back\n"
      "as a PPM, a CS418, miniRT or EASTRAY scene as a PNG, a Jaworski scene as a\n"
      "BMP, over every protocol. On a terminal a progress line shows the upload,\n"
      "the wait for the board and the image coming in.\n",
      stdout);
  for (const Group& g : option_groups()) {
    std::printf("\n%s:\n", g.title);
    minrt::cli::print_options(stdout, g.options);
  }
  std::fputs(
      "\n"
      "exit status: 0 ok, 1 link or transfer error, 2 usage error, 3 the firmware\n"
      "rejected the scene (its message is printed); Ctrl-C ends host-send with\n"
      "status 130 (the simulator stopped, the port restored, nothing written).\n",
      stdout);
}

ParseResult parse_command_line(int argc, char** argv, Options& o, std::string& error) {
  bool help = false, version = false;
  const bool parsed = minrt::cli::parse(
      argc, argv, options_table(),
      [&](const Option* opt, const std::string& v) -> std::string {
        if (opt != nullptr) return take_option(opt->name, v, o, help, version);
        if (!o.scene.empty()) return "more than one scene file given ('" + o.scene + "' and '" + v + "')";
        o.scene = v;
        return "";
      },
      error);
  if (!parsed) return ParseResult::kError;
  if (help) return ParseResult::kHelp;
  if (version) return ParseResult::kVersion;
  if (o.list) return ParseResult::kRun;
  // A board file describes the simulated board, unless a real one is named.
  if (!o.sim_board.empty() && o.port.empty()) o.sim = true;
  error = check_combination(o);
  if (!error.empty()) return ParseResult::kError;
  if (o.output.empty()) o.output = default_output(o.scene, ".ppm");
  return ParseResult::kRun;
}

}  // namespace minrt::send
