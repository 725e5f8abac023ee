#include "cli.hpp"

#include "core/base/text_numbers.hpp"
#include "eastray_stereo.hpp"
#include "file_input.hpp"
#include "image_load.hpp"
#include "image_window.hpp"
#include "png_io.hpp"
#include "posix/output_file.hpp"
#include "formats/registry.hpp"

#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <vector>

#include "port_discovery.hpp"
#include "protocol_course_host.hpp"
#include "protocol_framed_host.hpp"
#include "protocol_raw.hpp"
#include "scene_upload.hpp"
#include "sim_launcher.hpp"
#include "verify.hpp"

#ifndef MINRT_VERSION
#define MINRT_VERSION "0"
#endif

namespace minrt::send {

namespace {

bool parse_seconds(const std::string& s, double& v) {
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end != s.c_str() && *end == 0 && v > 0 && v < 1e6;
}

bool is_elf(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return false;
  unsigned char m[4] = {};
  const bool ok = std::fread(m, 1, 4, f) == 4 && m[0] == 0x7f && m[1] == 'E' && m[2] == 'L' && m[3] == 'F';
  std::fclose(f);
  return ok;
}

bool ends_with(const std::string& s, const char* tail) {
  const std::string t = tail;
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

// Unix98 pseudo-terminal slaves have majors 136..143 (Linux devices.txt).
bool is_pseudo_terminal(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
  const unsigned m = major(st.st_rdev);
  return m >= 136 && m <= 143;
}

std::string default_output(const std::string& scene) {
  std::string base = scene;
  const std::size_t slash = base.rfind('/');
  if (slash != std::string::npos) base = base.substr(slash + 1);
  const std::size_t dot = base.rfind('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  if (base.empty()) base = "image";
  return base + ".ppm";
}

const char* kind_arg(PpmKind k) { return k == PpmKind::kP3 ? "p3" : "p6"; }

int fail(int status, const std::string& msg) {
  std::fprintf(stderr, "host-send: error: %s\n", msg.c_str());
  return status;
}

}  // namespace

void print_help() {
  std::fputs(
      "Usage: host-send (-p DEV | --sim [ELF]) [OPTIONS] SCENE.sld [-o OUT.ppm]\n"
      "   or: host-send --list\n"
      "Sends an SLD scene to the min-rt firmware over a serial line and receives the\n"
      "rendered PPM image: from a board (--port) or from firmware-sim started on a\n"
      "pseudo-terminal (--sim); one of the two is required. A CS418 scene (png ...)\n"
      "comes back as its PNG, a Jaworski scene as a BMP, over every protocol.\n"
      "\n"
      "link:\n"
      "  -p, --port DEV           serial device, or usb:VID:PID[:SERIAL] (see --list)\n"
      "  --sim [ELF]              run the firmware in firmware-sim (ELF defaults to\n"
      "                           $MINRT_FIRMWARE_ELF, else the installed firmware\n"
      "                           (PREFIX/share/minrt/firmware), else the build's)\n"
      "  --sim-ram-size NM        RAM of the simulated board (default 4M, the board's);\n"
      "                           for CS418 scenes whose textures do not fit (implies --sim)\n"
      "  --board FILE             the simulated board's description (boards/*.board: memory\n"
      "                           map, UART, halt, ISA; implies --sim; default the reference)\n"
      "  --sim-binary PATH        simulator to run (default: $MINRT_FIRMWARE_SIM, else the\n"
      "                           firmware-sim next to host-send, else the build's)\n"
      "  -b, --baud N             line rate, any value (default 115200; with --sim it\n"
      "                           paces the simulated UART)\n"
      "  --flow none|rtscts|xonxoff  flow control (default none; xonxoff is unsafe for\n"
      "                           binary P6 and the framed protocol)\n"
      "  --list                   list serial ports with their USB identities\n"
      "protocol and image:\n"
      "  --protocol raw|course|framed  (default raw)\n"
      "  --size WxH               image size the board renders (default 512x512)\n"
      "  --format p3|p6           PPM flavour the board sends (default p3)\n"
      "  --program FILE           course protocol: program sent after 0x99\n"
      "  --endian little|big      course protocol: byte order of the scene words\n"
      "output and checks:\n"
      "  -o, --output FILE        image file (default SCENE's name with .ppm; - = stdout);\n"
      "                           written only when complete and valid; a FIFO, device\n"
      "                           or symbolic link is refused\n"
      "  --write-through          write into a FIFO, device or link given to -o\n"
      "  --allow-any-output       let a scene's own output name (CS418 png line, EASTRAY\n"
      "                           output) leave the scene's and the working folder\n"
      "  --as-received            write a PNG as the board sent it (stored deflate); by\n"
      "                           default it is compressed, with the same pixels\n"
      "  --verify REF.ppm         compare with a P3 or P6 reference: differing pixels,\n"
      "                           maximum channel error, PSNR\n"
      "  --expect-sha256 HEX      refuse the image unless its bytes have this SHA-256\n"
      "  --check                  raw, course: require the board's CRC-32 trailer (by\n"
      "                           default it is asked for and checked when announced)\n"
      "  --no-check               raw, course: send the scene without its CRC-32 and do\n"
      "                           not ask for the reply's (the plain protocol bytes)\n"
      "  --first-byte-timeout S   wait for the reply at most S seconds (default 120)\n"
      "  --idle-timeout S         longest silence within the reply (default 30)\n"
      "  --progress               draw the progress line even when stderr is no terminal\n"
      "  -s, --show               show the image in a window (SDL2) as its rows arrive; it\n"
      "                           stays until closed (ESC, q, close button); without a\n"
      "                           display a one-line warning\n"
      "  -q, --quiet              no summary line\n"
      "  -h, --help               this text\n"
      "  --version                version\n"
      "\n"
      "exit status: 0 ok, 1 link or transfer error, 2 usage error, 3 the firmware\n"
      "rejected the scene (its message is printed).\n",
      stdout);
}

ParseResult parse_command_line(int argc, char** argv, Options& o, std::string& error) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    std::string inline_value;
    bool has_inline = false;
    if (a.size() > 2 && a[0] == '-' && a[1] == '-') {
      const std::size_t eq = a.find('=');
      if (eq != std::string::npos) {
        inline_value = a.substr(eq + 1);
        a = a.substr(0, eq);
        has_inline = true;
      }
    }
    auto value = [&](std::string& out) -> bool {
      if (has_inline) {
        out = inline_value;
        return true;
      }
      if (i + 1 >= argc) {
        error = a + " needs a value";
        return false;
      }
      out = argv[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help") return ParseResult::kHelp;
    if (a == "--version") return ParseResult::kVersion;
    // The short forms serial tools use (picocom, esptool): -p PORT, -b BAUD.
    if (a == "-p") a = "--port";
    else if (a == "-b") a = "--baud";
    if (a == "--port") {
      if (!value(o.port)) return ParseResult::kError;
    } else if (a == "--sim") {
      o.sim = true;
      if (has_inline) o.sim_elf = inline_value;
      else if (i + 1 < argc && argv[i + 1][0] != '-' && (is_elf(argv[i + 1]) || ends_with(argv[i + 1], ".elf")))
        o.sim_elf = argv[++i];
    } else if (a == "--board") {
      if (!value(o.sim_board)) return ParseResult::kError;
      o.sim = true;  // a board file describes the simulated board
    } else if (a == "--sim-binary") {
      if (!value(o.sim_binary)) return ParseResult::kError;
      o.sim = true;  // naming a simulator asks for one
    } else if (a == "--sim-ram-size") {
      std::string v;
      if (!value(v)) return ParseResult::kError;
      uint32_t mib = 0;
      const char* p = v.c_str();
      if (!minrt::parse_decimal(p, 'M', 1024, mib) || *p != 'M' || p[1] != 0 || mib < 4) {
        error = "bad --sim-ram-size '" + v + "': expected NM, 4M..1024M";
        return ParseResult::kError;
      }
      o.sim_ram_bytes = static_cast<std::uint64_t>(mib) << 20;
      o.sim = true;
    } else if (a == "--baud") {
      if (!value(v)) return ParseResult::kError;
      char* end = nullptr;
      const unsigned long b = std::strtoul(v.c_str(), &end, 10);
      if (end == v.c_str() || *end != 0 || b < 50 || b > 20000000) {
        error = "bad --baud '" + v + "': expected 50..20000000";
        return ParseResult::kError;
      }
      o.port_settings.baud = static_cast<std::uint32_t>(b);
      o.baud_given = true;
    } else if (a == "--flow") {
      if (!value(v)) return ParseResult::kError;
      if (v == "none") o.port_settings.flow = Flow::kNone;
      else if (v == "rtscts") o.port_settings.flow = Flow::kRtsCts;
      else if (v == "xonxoff") o.port_settings.flow = Flow::kXonXoff;
      else {
        error = "bad --flow '" + v + "': expected none, rtscts or xonxoff";
        return ParseResult::kError;
      }
    } else if (a == "--protocol") {
      if (!value(v)) return ParseResult::kError;
      if (v == "raw") o.protocol = Protocol::kRaw;
      else if (v == "course") o.protocol = Protocol::kCourse;
      else if (v == "framed") o.protocol = Protocol::kFramed;
      else {
        error = "bad --protocol '" + v + "': expected raw, course or framed";
        return ParseResult::kError;
      }
    } else if (a == "--size") {
      if (!value(v)) return ParseResult::kError;
      if (!minrt::parse_size(v.c_str(), o.spec.width, o.spec.height)) {
        error = "bad --size '" + v + "': expected WxH, each 1..4096";
        return ParseResult::kError;
      }
      o.size_given = true;
    } else if (a == "--format") {
      if (!value(v)) return ParseResult::kError;
      if (v == "p3" || v == "P3") o.spec.kind = PpmKind::kP3;
      else if (v == "p6" || v == "P6") o.spec.kind = PpmKind::kP6;
      else {
        error = "bad --format '" + v + "': expected p3 or p6";
        return ParseResult::kError;
      }
    } else if (a == "--program") {
      if (!value(o.program)) return ParseResult::kError;
    } else if (a == "--endian") {
      if (!value(v)) return ParseResult::kError;
      if (v == "little") o.big_endian = false;
      else if (v == "big") o.big_endian = true;
      else {
        error = "bad --endian '" + v + "': expected little or big";
        return ParseResult::kError;
      }
    } else if (a == "-o" || a == "--output") {
      if (!value(o.output)) return ParseResult::kError;
      o.output_given = true;
    } else if (a == "--allow-any-output") {
      o.allow_any_output = true;
    } else if (a == "--write-through") {
      o.write_through = true;
    } else if (a == "--as-received") {
      o.as_received = true;
    } else if (a == "--verify") {
      if (!value(o.verify_ref)) return ParseResult::kError;
    } else if (a == "--expect-sha256") {
      if (!value(o.expect_sha256)) return ParseResult::kError;
      if (!valid_sha256_hex(o.expect_sha256)) {
        error = "bad --expect-sha256: expected 64 hex digits";
        return ParseResult::kError;
      }
    } else if (a == "--check" || a == "--no-check") {
      o.check = a == "--check" ? RawCheck::kRequire : RawCheck::kOff;
    } else if (a == "--first-byte-timeout" || a == "--idle-timeout") {
      if (!value(v)) return ParseResult::kError;
      double s = 0;
      if (!parse_seconds(v, s)) {
        error = "bad " + a + " '" + v + "': expected seconds > 0";
        return ParseResult::kError;
      }
      (a == "--idle-timeout" ? o.idle_timeout : o.first_byte_timeout) = s;
    } else if (a == "--list") {
      o.list = true;
    } else if (a == "-q" || a == "--quiet") {
      o.quiet = true;
    } else if (a == "--progress") {
      o.progress_forced = true;
    } else if (a == "-s" || a == "--show") {
      o.show = true;
    } else if (a.size() > 1 && a[0] == '-') {
      error = "unknown option '" + a + "'";
      return ParseResult::kError;
    } else if (!o.scene.empty()) {
      error = "more than one scene file given ('" + o.scene + "' and '" + a + "')";
      return ParseResult::kError;
    } else {
      o.scene = a;
    }
  }
  if (o.list) return ParseResult::kRun;
  if (!o.port.empty() && o.sim) {
    error = "--port and --sim exclude each other";
    return ParseResult::kError;
  }
  if (o.scene.empty()) {
    error = "no scene file given";
    return ParseResult::kError;
  }
  // Never render on the simulator without being asked: a student with a
  // board must not believe the board rendered the image.
  if (o.port.empty() && !o.sim) {
    error = "no board given: --port DEVICE for a board (host-send --list shows them), or --sim for firmware-sim";
    return ParseResult::kError;
  }
  if (o.protocol != Protocol::kCourse && (!o.program.empty())) {
    error = "--program only applies to --protocol course";
    return ParseResult::kError;
  }
  if (o.protocol == Protocol::kFramed && o.check == RawCheck::kRequire) {
    error = "--check applies to --protocol raw and course (framed checks every frame)";
    return ParseResult::kError;
  }
  if (o.output.empty()) o.output = default_output(o.scene);
  return ParseResult::kRun;
}

// RAM the firmware keeps for itself (code, data, stack, the scene and the
// tracer's tables) when textures are loaded: a conservative bound.
constexpr std::uint64_t kFirmwareReserve = 512 * 1024;

int run(const Options& options) {
  install_signal_handlers();
  if (options.list) return list_ports_command();

  Options o = options;
  std::string scene, why;
  bool scene_named_output = false;  // o.output comes from the scene (png line, output statement)
  if (!minrt::host::read_whole_file(o.scene, scene, why, minrt::host::kMaxSceneBytes))
    return fail(kExitUsage, "cannot read " + o.scene + ": " + why);
  // The format, as minrt recognises it (formats/registry.hpp); its upload
  // row checks the scene here and says what goes over the line and what
  // comes back (scene_upload.cpp).
  const std::size_t bom = minrt::formats::bom_bytes(reinterpret_cast<const uint8_t*>(scene.data()), scene.size());
  const minrt::formats::Format& format = minrt::formats::detect_format(
      o.scene.c_str(), minrt::formats::text_start(reinterpret_cast<const uint8_t*>(scene.data()), scene.size()));
  scene.erase(0, bom);
  const bool text_format = format.reply != minrt::formats::ImageKind::kPpm;  // SLD has protocols of its own
  const bool png_reply = format.reply == minrt::formats::ImageKind::kPng;
  if (text_format && !o.verify_ref.empty())
    return fail(kExitUsage, std::string("--verify compares PPM images; it does not apply to ") + format.title + " scenes");
  const std::size_t slash = o.scene.rfind('/');
  const std::uint64_t ram = o.sim_ram_bytes != 0 ? o.sim_ram_bytes : MINRT_RAM_DEFAULT_SIZE;
  UploadRequest request{o.scene, slash == std::string::npos ? "" : o.scene.substr(0, slash + 1), ram - kFirmwareReserve,
                        o.size_given ? o.spec.width : 0, o.size_given ? o.spec.height : 0};
  Upload upload;
  if (!upload_format(format.id).prepare(request, scene, upload, why))
    return fail(kExitFirmware, "scene rejected before sending: " + why);
  scene = std::move(upload.bytes);
  if (upload.width > 0 && format.default_width > 0) {  // a format whose reply size the board takes from --size
    o.spec.width = upload.width;
    o.spec.height = upload.height;
  }
  const int png_width = upload.width, png_height = upload.height;
  if (!o.output_given) {
    if (!upload.output.empty()) {
      o.output = upload.output;
      scene_named_output = true;
    } else if (png_reply) {
      o.output = default_output(o.scene);
      o.output.replace(o.output.size() - 4, 4, ".png");
    }
  }
  if (!upload.refusal.empty() && !o.output_given)
    return fail(kExitFirmware, "scene rejected before sending: " + upload.refusal);
  if (!upload.warning.empty() && !o.output_given) std::fprintf(stderr, "host-send: warning: %s\n", upload.warning.c_str());
  // The texture preamble is binary and counted; the text after it must not
  // hold the byte that ends a plain raw upload.
  if (text_format && o.protocol == Protocol::kRaw &&
      scene.find(static_cast<char>(MINRT_END_OF_INPUT), upload.text_at) != std::string::npos)
    return fail(kExitFirmware, "scene rejected before sending: it contains byte 0x04, the raw protocol's end of input");
  // The output is checked before the transfer, not after minutes of it.
  if (scene_named_output && !o.allow_any_output && !minrt::host::scene_named_output_allowed(o.scene, o.output, why))
    return fail(kExitUsage, why);
  // EASTRAY's stereo pair (rmode 1) goes to two files, the output's name
  // with _r and _l (eastray_stereo.hpp).
  std::vector<std::string> targets{o.output};
  if (upload.stereo && o.output != "-")
    targets = {minrt::host::eastray_stereo_name(o.output, 'r'), minrt::host::eastray_stereo_name(o.output, 'l')};
  for (const std::string& target : targets)
    if (!minrt::host::check_output_target(target, o.write_through, why)) return fail(kExitUsage, why);
  // Raw sends the text as it is, and the board takes MINRT_END_OF_INPUT
  // (0x04) as the end of the scene: a scene with that byte inside would be
  // cut short there. The core's reader (the words encoder reads with it)
  // refuses such a scene with minrt's message, so nothing is sent.
  if (!text_format && o.protocol == Protocol::kRaw && scene.find(static_cast<char>(MINRT_END_OF_INPUT)) != std::string::npos) {
    std::string words;
    if (!sld_to_course_words(scene, false, words, why))
      return fail(kExitFirmware, "scene rejected before sending: " + why);
  }
  std::string program;
  // No larger than the board's program region (memory_map.h): a larger one
  // could only be refused by the board after the whole upload.
  if (!o.program.empty() && !minrt::host::read_whole_file(o.program, program, why, MINRT_PROGRAM_MAX_SIZE))
    return fail(kExitUsage, "cannot read " + o.program + ": " + why);
  Image reference;
  if (!o.verify_ref.empty()) {
    std::string err;
    if (!load_ppm(o.verify_ref, reference, err)) return fail(kExitUsage, err);
  }

  // The link: a serial device, or firmware-sim on a pty.
  std::unique_ptr<SimLauncher> sim;
  std::string device = o.port;
  const bool use_sim = o.port.empty();
  if (!o.port.empty() && o.port.rfind("usb:", 0) == 0) {
    std::string err;
    if (!resolve_usb_port(o.port, "/sys", device, err)) return fail(kExitLink, err);
  }
  if (use_sim) {
    SimConfig cfg;
    cfg.simulator = o.sim_binary.empty() ? default_simulator() : o.sim_binary;
    cfg.board = o.sim_board;
    cfg.firmware = o.sim_elf.empty() ? default_firmware() : o.sim_elf;
    cfg.baud = o.baud_given ? o.port_settings.baud : 0;
    cfg.firmware_args = {"--size", std::to_string(o.spec.width) + "x" + std::to_string(o.spec.height), "--format",
                         kind_arg(o.spec.kind)};
    if (o.sim_ram_bytes != 0) {
      cfg.ram_size = std::to_string(o.sim_ram_bytes >> 20) + "M";
      cfg.firmware_args.push_back("--ram-size");
      cfg.firmware_args.push_back(cfg.ram_size);
    }
    if (o.protocol == Protocol::kCourse) {
      cfg.firmware_args.push_back("--protocol=course");
      if (o.big_endian) cfg.firmware_args.push_back("--endian=big");
    }
    if (o.protocol == Protocol::kFramed) cfg.firmware_args.push_back("--protocol=framed");
    sim = std::make_unique<SimLauncher>();
    std::string err;
    if (!sim->start(cfg, err)) return fail(kExitLink, err);
    device = sim->pty_path();
  }

  SerialPort port;
  try {
    port.open(device, o.port_settings);
  } catch (const PortError& e) {
    return fail(kExitLink, e.message);
  }
  if (!port.baud_warning().empty() && !use_sim) std::fprintf(stderr, "host-send: warning: %s\n", port.baud_warning().c_str());
  if (o.port_settings.flow == Flow::kXonXoff && (o.spec.kind == PpmKind::kP6 || o.protocol != Protocol::kRaw))
    std::fprintf(stderr, "host-send: warning: XON/XOFF flow control corrupts binary data (P6, course, framed)\n");

  // A share of the 8N1 limit means something only on a real serial line: a
  // pseudo-terminal (the simulator's, or any other) has no baud rate.
  const bool paced = !use_sim && !is_pseudo_terminal(port.fd());
  const std::uint64_t expected_bytes =
      png_reply ? static_cast<std::uint64_t>(png_width) * png_height * 4 + static_cast<std::uint64_t>(png_height) * 18 + 64
                : expected_image_bytes(o.spec);
  Progress progress(o.progress_forced || ::isatty(2) != 0, expected_bytes, png_reply ? png_height : o.spec.height,
                    paced ? o.port_settings.baud : 0);
  Exchange ex{port, {static_cast<int>(o.first_byte_timeout * 1000), static_cast<int>(o.idle_timeout * 1000)},
              &progress};
  ex.check = o.check;
  // --show: the window follows the image as it arrives.
  minrt::host::LiveWindow window;
  if (o.show) {
    std::string why2;
    if (!window.open("host-send: " + o.output, why2))
      std::fprintf(stderr, "host-send: warning: not showing the image: %s\n", why2.c_str());
  }
  minrt::host::ImageStreamDecoder live(window);
  if (window.is_open()) ex.live = &live;
  TransferResult r;
  CourseHostOptions course_options;
  course_options.big_endian = o.big_endian;
  if (text_format) {
    // Course and framed carry these formats as text behind a header
    // (protocol/text_scene_upload.hpp), the bytes raw would send; the image
    // is the format's own.
    const std::string& bytes = scene;  // the texture preamble, if any, and the text
    const std::uint32_t tag = format.wire_tag;
    if (o.protocol == Protocol::kFramed) {
      r = run_framed_text(ex, tag, png_reply ? FramedImage::kPng : FramedImage::kBmp, bytes, png_width, png_height);
    } else if (o.protocol == Protocol::kCourse) {
      const std::string words = text_scene_course_words(tag, bytes, o.big_endian);
      if (png_reply) {
        PngReceiver rx(png_width, png_height);
        r = run_course_words(ex, words, program, course_options, rx);
      } else {
        BmpReceiver rx;
        r = run_course_words(ex, words, program, course_options, rx);
      }
    } else if (png_reply) {
      r = run_raw_png(ex, bytes, png_width, png_height);
    } else {
      r = run_raw_bmp(ex, bytes);
    }
  } else if (o.protocol == Protocol::kRaw) {
    r = run_raw(ex, scene, o.spec);
  } else if (o.protocol == Protocol::kCourse) {
    r = run_course(ex, scene, program, course_options, o.spec);
  } else {
    r = run_framed(ex, scene, o.spec);
  }
  progress.finish();
  port.close();
  int sim_status = 0;
  if (sim) sim_status = sim->stop(r.status == TransferResult::Status::kOk ? 2000 : 500);

  if (r.status == TransferResult::Status::kSceneError)
    return fail(kExitFirmware, "scene rejected before sending: " + r.message);
  if (r.status == TransferResult::Status::kFirmwareError)
    return fail(kExitFirmware, "the board reported an error: " + r.message);
  if (r.status != TransferResult::Status::kOk) {
    if (sim) {
      std::string out = sim->output();
      while (!out.empty() && out.back() == '\n') out.pop_back();
      if (!out.empty()) {
        const std::size_t nl = out.rfind('\n');
        std::fprintf(stderr, "host-send: simulator said: %s\n", out.substr(nl == std::string::npos ? 0 : nl + 1).c_str());
      }
    }
    return fail(kExitLink, r.message);
  }
  (void)sim_status;

  const std::string digest = sha256_hex_of(r.image);
  if (!o.expect_sha256.empty() && !same_sha256(digest, o.expect_sha256))
    return fail(kExitLink, "image sha256 " + digest + " differs from the expected " + o.expect_sha256 +
                               "; not written");
  std::string err;
  const std::string* written = &r.image;
  std::string compressed;
  if (!o.as_received && r.image.compare(0, 4, "\x89PNG") == 0) {
    if (!minrt::host::compress_png(r.image, compressed, err)) return fail(kExitLink, "cannot recompress the board's PNG: " + err);
    written = &compressed;
  }
  std::vector<std::string> images{*written};
  if (targets.size() == 2) {
    images.resize(2);
    if (!minrt::host::split_stereo_png(r.image, images[0], images[1], err))
      return fail(kExitLink, "cannot cut the board's stereo pair: " + err);
  }
  for (std::size_t i = 0; i < targets.size(); ++i) {
    std::string file, warning;
    if (upload.write_as && !o.as_received && targets[i] != "-" && !upload.write_as(targets[i], images[i], file, warning, err))
      return fail(kExitLink, "cannot write " + targets[i] + ": " + err);
    if (!warning.empty() && !o.quiet) std::fprintf(stderr, "host-send: warning: %s\n", warning.c_str());
    if (!write_file_atomically(targets[i], file.empty() ? images[i] : file, o.write_through,
                               minrt::host::Durability::kSynced, err))
      return fail(kExitLink, err);
  }

  if (!o.quiet) {
    const double rate = r.seconds > 0 ? static_cast<double>(r.received) / r.seconds : 0;
    char line[320];
    const std::string shown = targets.size() == 2 ? targets[0] + " and " + targets[1] : o.output;
    int n = std::snprintf(line, sizeof line, "host-send: %s: %llu bytes in %.3f s, %.1f kB/s%s", shown.c_str(),
                          static_cast<unsigned long long>(r.received), r.seconds, rate / 1000.0,
                          use_sim ? " from the simulated board (firmware-sim)" : "");
    if ((paced || (use_sim && o.baud_given)) && n > 0)  // the simulator (or stand-in) paces at --baud too
      n += std::snprintf(line + n, sizeof line - n, ", %.1f%% of the 8N1 limit at %u baud", rate * 1000.0 / o.port_settings.baud,
                         static_cast<unsigned>(o.port_settings.baud));
    if (r.retransmitted_rows > 0 && n > 0)
      std::snprintf(line + n, sizeof line - n, ", %d rows re-sent", r.retransmitted_rows);
    std::fprintf(stderr, "%s\n", line);
    std::fprintf(stderr, "host-send: sha256 %s%s%s\n", digest.c_str(), written != &r.image ? " as the board sent it" : "", r.crc_checked ? " (CRC-32 trailer checked)" : "");
  }
  if (window.is_open()) {
    // Rows the stream could not hand over live (the framed protocol, a
    // compressed PNG) come from the file as written.
    minrt::host::RgbaImage written;
    std::string why2;
    if (o.output != "-" && minrt::host::load_image(o.output, written, why2)) {
      if (window.width() == 0) window.begin(written.width, written.height);
      window.fill(written);
    }
    if (!window.finish_and_wait(why2)) std::fprintf(stderr, "host-send: warning: %s\n", why2.c_str());
  }
  if (!o.verify_ref.empty()) {
    Image got;
    std::string perr;
    parse_ppm(r.image, got, perr);
    const Comparison c = compare_images(got, reference);
    if (!c.same_size)
      std::fprintf(stderr, "host-send: verify: image is %dx%d, reference %dx%d\n", got.width, got.height,
                   reference.width, reference.height);
    else
      std::fprintf(stderr, "host-send: verify: %s\n", describe(c).c_str());
  }
  return kExitOk;
}

}  // namespace minrt::send
