#include "run.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "eastray_stereo.hpp"
#include "file_input.hpp"
#include "formats/registry.hpp"
#include "image_load.hpp"
#include "image_window.hpp"
#include "png_io.hpp"
#include "port_discovery.hpp"
#include "posix/interrupt.hpp"
#include "posix/output_file.hpp"
#include "protocol_course_host.hpp"
#include "protocol_framed_host.hpp"
#include "protocol_raw.hpp"
#include "scene_upload.hpp"
#include "session_host.hpp"
#include "sim_launcher.hpp"
#include "verify.hpp"

namespace minrt::send {

namespace {

namespace formats = minrt::formats;

// RAM the firmware keeps for itself (code, data, stack, the scene and the
// tracer's tables) when textures are loaded: a conservative bound.
constexpr std::uint64_t kFirmwareReserve = 512 * 1024;

int fail(int status, const std::string& msg) {
  std::fprintf(stderr, "host-send: error: %s\n", msg.c_str());
  return status;
}

void warn(const std::string& msg) { std::fprintf(stderr, "host-send: warning: %s\n", msg.c_str()); }

// What the steps hand on to each other.
struct Job {
  const formats::Format* format = nullptr;
  std::string bytes;           // what goes over the line: any texture preamble, then the text
  bool text_format = false;    // not SLD: course and framed carry it as text behind a header
  bool png_reply = false;
  int reply_width = 0, reply_height = 0;  // a PNG's or BMP's size, from the scene
  bool scene_named_output = false;        // o.output comes from the scene (png line, output statement)
  std::string program;                    // course: --program's bytes
  Image reference;                        // --verify
  std::vector<std::string> targets;       // the output, or EASTRAY's stereo pair (_r, _l)
  // The board's PNG written as the format's own file (EASTRAY: TIFF,
  // 16-bit, a window into an existing file); empty: written as received.
  decltype(Upload::write_as) write_as;
  bool stereo = false;
  bool sparse = false;  // the textures went sparse: the board may ask for them whole
  std::string note;     // the summary's third line (how many texels went)
};

// Progress lines on stderr: on a terminal, or with --progress; never with -q.
bool progress_wanted(const Options& o) { return !o.quiet && (o.progress_forced || ::isatty(STDERR_FILENO) != 0); }

// The scene, recognised as minrt recognises it (formats/registry.hpp) and
// checked and prepared by its format's upload row (scene_upload.hpp), which
// also gives the reply's size and the scene's own output name.
int prepare_scene(Options& o, Job& job) {
  std::string scene, why;
  if (!minrt::host::read_whole_file(o.scene, scene, why, minrt::host::kMaxSceneBytes))
    return fail(kExitUsage, "cannot read " + o.scene + ": " + why);
  const auto* text = reinterpret_cast<const uint8_t*>(scene.data());
  const std::size_t bom = formats::bom_bytes(text, scene.size());
  job.format = &formats::detect_format(o.scene.c_str(), formats::text_start(text, scene.size()));
  scene.erase(0, bom);
  const formats::Format& format = *job.format;
  job.text_format = format.reply != formats::ImageKind::kPpm;  // SLD has protocols of its own
  job.png_reply = format.reply == formats::ImageKind::kPng;
  if (job.text_format && !o.verify_ref.empty())
    return fail(kExitUsage, std::string("--verify compares PPM images; it does not apply to ") + format.title + " scenes");

  const std::size_t slash = o.scene.rfind('/');
  const std::uint64_t ram = o.sim_ram_bytes != 0 ? o.sim_ram_bytes : MINRT_RAM_DEFAULT_SIZE;
  UploadRequest request{o.scene, slash == std::string::npos ? "" : o.scene.substr(0, slash + 1), ram - kFirmwareReserve,
                        o.size_given ? o.spec.width : 0, o.size_given ? o.spec.height : 0, !o.full_textures,
                        progress_wanted(o)};
  Upload upload;
  if (!upload_format(format.id).prepare(request, scene, upload, why))
    return fail(kExitFirmware, "scene rejected before sending: " + why);
  if (!o.quiet)
    for (const std::string& w : upload.scene_warnings) std::fprintf(stderr, "%s\n", w.c_str());
  job.bytes = std::move(upload.bytes);
  job.sparse = upload.sparse;
  job.note = upload.note;
  if (upload.width > 0 && format.default_width > 0) {  // a format whose reply size the board takes from --size
    o.spec.width = upload.width;
    o.spec.height = upload.height;
  }
  job.stereo = upload.stereo;
  job.write_as = upload.write_as;
  job.reply_width = upload.width;
  job.reply_height = upload.height;
  if (!o.output_given) {
    if (!upload.output.empty()) {
      o.output = upload.output;
      job.scene_named_output = true;
    } else if (job.png_reply) {
      o.output = default_output(o.scene, ".png");
    }
    if (!upload.refusal.empty()) return fail(kExitFirmware, "scene rejected before sending: " + upload.refusal);
    if (!upload.warning.empty()) warn(upload.warning);
  }
  // The texture preamble is binary and counted; the text after it must not
  // hold the byte that ends a plain raw upload.
  if (job.text_format && o.protocol == Protocol::kRaw &&
      job.bytes.find(static_cast<char>(MINRT_END_OF_INPUT), upload.text_at) != std::string::npos)
    return fail(kExitFirmware, "scene rejected before sending: it contains byte 0x04, the raw protocol's end of input");
  return kExitOk;
}

// Everything that can be refused before the link is opened, not after
// minutes of transfer: the output, an SLD scene raw would cut short, the
// program and the reference.
int check_before_sending(const Options& o, Job& job) {
  std::string why;
  if (job.scene_named_output && !o.allow_any_output && !minrt::host::scene_named_output_allowed(o.scene, o.output, why))
    return fail(kExitUsage, why);
  // EASTRAY's stereo pair (rmode 1) goes to two files, the output's name
  // with _r and _l (eastray_stereo.hpp).
  job.targets = {o.output};
  if (job.stereo && o.output != "-")
    job.targets = {minrt::host::eastray_stereo_name(o.output, 'r'), minrt::host::eastray_stereo_name(o.output, 'l')};
  for (const std::string& target : job.targets)
    if (!minrt::host::check_output_target(target, o.write_through, why)) return fail(kExitUsage, why);
  // Raw sends SLD text as it is, and the board takes MINRT_END_OF_INPUT
  // (0x04) as the end of the scene: a scene with that byte inside would be
  // cut short there. The core's reader (the words encoder reads with it)
  // refuses such a scene with minrt's message, so nothing is sent.
  if (!job.text_format && o.protocol == Protocol::kRaw &&
      job.bytes.find(static_cast<char>(MINRT_END_OF_INPUT)) != std::string::npos) {
    std::string words;
    if (!sld_to_course_words(job.bytes, false, words, why)) return fail(kExitFirmware, "scene rejected before sending: " + why);
  }
  // No larger than the board's program region (memory_map.h): a larger one
  // could only be refused by the board after the whole upload.
  if (!o.program.empty() && !minrt::host::read_whole_file(o.program, job.program, why, MINRT_PROGRAM_MAX_SIZE))
    return fail(kExitUsage, "cannot read " + o.program + ": " + why);
  if (!o.verify_ref.empty() && !load_ppm(o.verify_ref, job.reference, why)) return fail(kExitUsage, why);
  return kExitOk;
}

// Unix98 pseudo-terminal slaves have majors 136..143 (Linux devices.txt).
bool is_pseudo_terminal(int fd) {
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISCHR(st.st_mode)) return false;
  const unsigned m = major(st.st_rdev);
  return m >= 136 && m <= 143;
}

// The link: a serial device, or firmware-sim on a pty.
struct Link {
  std::unique_ptr<SimLauncher> sim;
  std::string device;
  SerialPort port;
  bool paced = false;  // a real serial line, where a share of the 8N1 limit means something
};

SimConfig simulator_config(const Options& o) {
  SimConfig cfg;
  cfg.simulator = o.sim_binary.empty() ? default_simulator() : o.sim_binary;
  cfg.board = o.sim_board;
  cfg.firmware = o.sim_elf.empty() ? default_firmware() : o.sim_elf;
  if (o.rtl) {
    // The RTL harness: the environment's, else the build's; its firmware
    // the build's rtl-reference image (docs/rtl.md).
    const char* env = std::getenv("MINRT_RTL_HARNESS");
    if (o.sim_binary.empty()) cfg.simulator = env != nullptr && *env != 0 ? env : MINRT_RTL_HARNESS_DEFAULT;
    if (o.sim_elf.empty()) cfg.firmware = MINRT_RTL_FIRMWARE_DEFAULT;
  }
  cfg.baud = o.baud_given ? o.port_settings.baud : 0;
  cfg.startup_timeout_ms = static_cast<int>(o.sim_start_timeout * 1000);
  cfg.firmware_args = {"--size", std::to_string(o.spec.width) + "x" + std::to_string(o.spec.height), "--format",
                       o.spec.kind == PpmKind::kP3 ? "p3" : "p6"};
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
  return cfg;
}

// The device to open: --port (a usb: identity resolved), or the pty of a
// simulator started here.
int find_device(const Options& o, Link& link) {
  std::string err;
  link.device = o.port;
  if (o.port.rfind("usb:", 0) == 0 && !resolve_usb_port(o.port, "/sys", link.device, err)) return fail(kExitLink, err);
  if (o.sim) {
    const SimConfig cfg = simulator_config(o);
    if (o.rtl && ::access(cfg.simulator.c_str(), X_OK) != 0)
      return fail(kExitLink, "the RTL harness " + cfg.simulator + " is not built (it needs Verilator, docs/rtl.md)");
    link.sim = std::make_unique<SimLauncher>();
    if (!link.sim->start(cfg, err)) return fail(kExitLink, err);
    link.device = link.sim->pty_path();
  }
  return kExitOk;
}

int open_port(const Options& o, Link& link) {
  try {
    link.port.open(link.device, o.port_settings);
  } catch (const PortError& e) {
    return fail(kExitLink, e.message);
  }
  if (!link.port.baud_warning().empty() && !o.sim) warn(link.port.baud_warning());
  if (o.port_settings.flow == Flow::kXonXoff && (o.spec.kind == PpmKind::kP6 || o.protocol != Protocol::kRaw))
    warn("XON/XOFF flow control corrupts binary data (P6, course, framed)");
  // A pseudo-terminal (the simulator's, or any other) has no baud rate.
  link.paced = !o.sim && !is_pseudo_terminal(link.port.fd());
  return kExitOk;
}

// The `name = ...` of a board file, or "" with the reason in `error`.
std::string board_file_name(const std::string& path, std::string& error) {
  std::string text, why;
  if (!minrt::host::read_whole_file(path, text, why, 1 << 20)) {
    error = "cannot read " + path + ": " + why;
    return "";
  }
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t nl = text.find('\n', at);
    if (nl == std::string::npos) nl = text.size();
    std::string line = text.substr(at, nl - at);
    at = nl + 1;
    line = line.substr(0, line.find('#'));
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;
    auto trim = [](std::string v) {
      const std::size_t b = v.find_first_not_of(" \t\r");
      const std::size_t e = v.find_last_not_of(" \t\r");
      return b == std::string::npos ? std::string() : v.substr(b, e - b + 1);
    };
    if (trim(line.substr(0, eq)) == "name") return trim(line.substr(eq + 1));
  }
  error = path + ": no 'name = ...' line";
  return "";
}

// The session (-p): the greeting, the identity checked against --board,
// the run's options. kOk, or the one line that says what to check.
TransferResult handshake(const Options& o, SerialPort& port, BoardIdentity* identity_out) {
  TransferResult r;
  const GreetResult g = greet_board(port, o.port_settings.baud);
  if (g.status != GreetResult::Status::kOk) {
    r.message = g.message;
    return r;
  }
  if (!g.note.empty() && !o.quiet) warn(g.note);
  if (identity_out != nullptr) *identity_out = g.identity;
  if (!o.sim_board.empty()) {
    std::string err;
    const std::string want = board_file_name(o.sim_board, err);
    if (want.empty()) {
      r.message = err;
      return r;
    }
    if (g.identity.get("board") != want) {
      r.message = "the board on " + port.device() + " runs firmware built for board '" + g.identity.get("board") +
                  "', not '" + want + "' (" + o.sim_board + "): load the firmware built for " + want +
                  ", or give the board file it was built for";
      return r;
    }
  }
  if (identity_out != nullptr) {
    r.status = TransferResult::Status::kOk;
    return r;
  }
  RunOptions run;
  run.width = o.spec.width;
  run.height = o.spec.height;
  run.p6 = o.spec.kind == PpmKind::kP6;
  run.protocol = o.protocol == Protocol::kCourse ? "course" : o.protocol == Protocol::kFramed ? "framed" : "raw";
  run.big_endian = o.big_endian;
  bool refused = false;
  if (!send_run_options(port, run, r.message, refused)) {
    if (refused) r.status = TransferResult::Status::kFirmwareError;
    return r;
  }
  r.status = TransferResult::Status::kOk;
  return r;
}

// --probe: the board's identity on stdout.
int probe_command(const Options& o) {
  Link link;
  if (const int status = find_device(o, link); status != kExitOk) return status;
  minrt::host::InterruptsHeld held;
  if (const int status = open_port(o, link); status != kExitOk) return status;
  BoardIdentity id;
  const TransferResult r = handshake(o, link.port, &id);
  link.port.close();
  if (r.status != TransferResult::Status::kOk) return fail(kExitLink, r.message);
  std::fputs(describe_identity(id).c_str(), stdout);
  return kExitOk;
}

// The protocol's exchange for the scene's format.
TransferResult exchange_scene(const Options& o, const Job& job, Exchange& ex) {
  CourseHostOptions course;
  course.big_endian = o.big_endian;
  if (!job.text_format) {
    if (o.protocol == Protocol::kRaw) return run_raw(ex, job.bytes, o.spec);
    if (o.protocol == Protocol::kCourse) return run_course(ex, job.bytes, job.program, course, o.spec);
    return run_framed(ex, job.bytes, o.spec);
  }
  // Course and framed carry the other formats as text behind a header
  // (protocol/text_scene_upload.hpp), the bytes raw would send; the image
  // is the format's own.
  const std::uint32_t tag = job.format->wire_tag;
  const int w = job.reply_width, h = job.reply_height;
  if (o.protocol == Protocol::kFramed)
    return run_framed_text(ex, tag, job.png_reply ? FramedImage::kPng : FramedImage::kBmp, job.bytes, w, h);
  if (o.protocol == Protocol::kCourse) {
    const std::string words = text_scene_course_words(tag, job.bytes, o.big_endian);
    if (job.png_reply) {
      PngReceiver rx(w, h);
      return run_course_words(ex, words, job.program, course, rx);
    }
    BmpReceiver rx;
    return run_course_words(ex, words, job.program, course, rx);
  }
  return job.png_reply ? run_raw_png(ex, job.bytes, w, h) : run_raw_bmp(ex, job.bytes);
}

// The progress line's measure of the reply: its rows, and about how many
// bytes carry them (the board's PNG is stored, not compressed).
Progress make_progress(const Options& o, const Job& job, const Link& link) {
  const bool sized = job.text_format && job.reply_height > 0;
  const int rows = sized ? job.reply_height : o.spec.height;
  const std::uint64_t pixels = sized ? static_cast<std::uint64_t>(job.reply_width) * job.reply_height : 0;
  const std::uint64_t bytes = !job.text_format ? expected_image_bytes(o.spec)
                              : job.png_reply  ? pixels * 4 + static_cast<std::uint64_t>(rows) * 18 + 64
                                               : pixels * 4 + 138;
  return Progress(progress_wanted(o), bytes, rows,
                  link.paced ? o.port_settings.baud : 0, static_cast<int>(o.first_byte_timeout));
}

// The transfer, with the progress line and the --show window following it.
TransferResult transfer(const Options& o, const Job& job, Link& link, minrt::host::LiveWindow& window) {
  Progress progress = make_progress(o, job, link);
  Exchange ex{link.port,
              {static_cast<int>(o.first_byte_timeout * 1000), static_cast<int>(o.idle_timeout * 1000)},
              &progress};
  ex.check = o.check;
  ex.timeouts.reply_ms = static_cast<long long>(o.reply_timeout * 1000);
  minrt::host::ImageStreamDecoder live(window);
  if (window.is_open()) ex.live = &live;
  if (!o.sim && o.handshake) {
    TransferResult h = handshake(o, link.port, nullptr);
    if (h.status != TransferResult::Status::kOk) {
      progress.finish();
      return h;
    }
  }
  TransferResult r = exchange_scene(o, job, ex);
  progress.finish();
  return r;
}

// The port's settings back, then the simulator stopped (given time to end
// by itself after a good transfer). On failure, the simulator's last line.
void close_link(Link& link, const TransferResult& r) {
  link.port.close();
  if (!link.sim) return;
  const bool ok = r.status == TransferResult::Status::kOk;
  link.sim->stop(minrt::host::interrupted() ? 0 : ok ? 2000 : 500);
  if (ok || minrt::host::interrupted()) return;
  std::string out = link.sim->output();
  while (!out.empty() && out.back() == '\n') out.pop_back();
  if (out.empty()) return;
  const std::size_t nl = out.rfind('\n');
  std::fprintf(stderr, "host-send: simulator said: %s\n", out.substr(nl == std::string::npos ? 0 : nl + 1).c_str());
}

// The board read a texel of a sparse texture that host-send did not send
// (its render differs from host-send's): the error line says so.
bool unsent_texel(const TransferResult& r) {
  return r.status == TransferResult::Status::kFirmwareError && r.message.find(MINRT_UNSENT_TEXEL_ERROR) != std::string::npos;
}

int transfer_error(const Job& job, const TransferResult& r) {
  if (r.status == TransferResult::Status::kSceneError) return fail(kExitFirmware, "scene rejected before sending: " + r.message);
  if (unsent_texel(r))
    return fail(kExitFirmware, "the board read a texel host-send did not send (" + r.message +
                                   "); reset the board and send again with --full-textures");
  // A board older than sparse textures does not know their marker.
  if (r.status == TransferResult::Status::kFirmwareError && job.sparse)
    return fail(kExitFirmware, "the board reported an error: " + r.message +
                                   " (the textures went sparse: a board without them needs --full-textures)");
  if (r.status == TransferResult::Status::kFirmwareError)
    return fail(kExitFirmware, "the board reported an error: " + r.message);
  return fail(kExitLink, r.message);
}

// The image checked against --expect-sha256 and written whole (a board's
// stored PNG compressed first unless --as-received; a stereo pair cut in
// two; the format's own file when it has one); `file_bytes` gets the
// bytes written.
int write_image(const Options& o, const Job& job, const TransferResult& r, const std::string& digest,
                std::size_t& file_bytes, bool& recompressed) {
  if (!o.expect_sha256.empty() && !same_sha256(digest, o.expect_sha256))
    return fail(kExitLink, "image sha256 " + digest + " differs from the expected " + o.expect_sha256 + "; not written");
  std::string err;
  recompressed = !o.as_received && r.image.compare(0, 4, "\x89PNG") == 0;
  std::vector<std::string> images(1);
  if (!recompressed) images[0] = r.image;
  else if (!minrt::host::compress_png(r.image, images[0], err))
    return fail(kExitLink, "cannot recompress the board's PNG: " + err);
  if (job.targets.size() == 2) {
    images.resize(2);
    if (!minrt::host::split_stereo_png(r.image, images[0], images[1], err))
      return fail(kExitLink, "cannot cut the board's stereo pair: " + err);
  }
  file_bytes = 0;
  for (std::size_t i = 0; i < job.targets.size(); ++i) {
    std::string file, warning;
    const std::string& target = job.targets[i];
    if (job.write_as && !o.as_received && target != "-" && !job.write_as(target, images[i], file, warning, err))
      return fail(kExitLink, "cannot write " + target + ": " + err);
    if (!warning.empty() && !o.quiet) warn(warning);
    const std::string& bytes = file.empty() ? images[i] : file;
    if (!write_file_atomically(target, bytes, o.write_through, minrt::host::Durability::kSynced, err))
      return fail(kExitLink, err);
    file_bytes += bytes.size();
  }
  return kExitOk;
}

// "host-send: OUT: 154756 bytes; received 154769 in 12.345 s, 12.5 kB/s ...":
// the file's size, then what crossed the line (with the CRC-32 trailer,
// frames, a PNG's stored blocks) and how fast.
void print_summary(const Options& o, const Job& job, const Link& link, const TransferResult& r, std::size_t file_bytes,
                   const std::string& digest, bool recompressed) {
  const std::string shown = job.targets.size() == 2 ? job.targets[0] + " and " + job.targets[1] : o.output;
  const double rate = r.seconds > 0 ? static_cast<double>(r.received) / r.seconds : 0;
  char line[400];
  int n = std::snprintf(line, sizeof line, "host-send: %s: %zu bytes; received %llu in %.3f s, %.1f kB/s%s", shown.c_str(),
                        file_bytes, static_cast<unsigned long long>(r.received), r.seconds, rate / 1000.0,
                        o.rtl ? " from the RTL harness (minrt-rtl)" : o.sim ? " from the simulated board (firmware-sim)" : "");
  if ((link.paced || (o.sim && o.baud_given)) && n > 0 && n < static_cast<int>(sizeof line))  // the simulator paces at --baud too
    n += std::snprintf(line + n, sizeof line - n, ", %.1f%% of the 8N1 limit at %u baud",
                       rate * 1000.0 / o.port_settings.baud, static_cast<unsigned>(o.port_settings.baud));
  if (r.retransmitted_rows > 0 && n > 0 && n < static_cast<int>(sizeof line))
    std::snprintf(line + n, sizeof line - n, ", %d rows re-sent", r.retransmitted_rows);
  std::fprintf(stderr, "%s\n", line);
  std::fprintf(stderr, "host-send: sha256 %s%s%s\n", digest.c_str(), recompressed ? " as the board sent it" : "",
               r.crc_checked ? " (CRC-32 trailer checked)" : "");
  if (!job.note.empty()) std::fprintf(stderr, "host-send: %s\n", job.note.c_str());
}

// --show: rows the stream could not hand over live (the framed protocol, a
// compressed PNG) come from the file as written; then the window stays
// until closed.
void show_written(const Options& o, minrt::host::LiveWindow& window) {
  std::string why;
  minrt::host::RgbaImage written;
  if (o.output != "-" && minrt::host::load_image(o.output, written, why)) {
    if (window.width() == 0) window.begin(written.width, written.height);
    window.fill(written);
  }
  if (!window.finish_and_wait(why)) warn(why);
}

void print_verification(const TransferResult& r, const Image& reference) {
  Image got;
  std::string err;
  parse_ppm(r.image, got, err);
  const Comparison c = compare_images(got, reference);
  if (!c.same_size)
    std::fprintf(stderr, "host-send: verify: image is %dx%d, reference %dx%d\n", got.width, got.height, reference.width,
                 reference.height);
  else
    std::fprintf(stderr, "host-send: verify: %s\n", describe(c).c_str());
}

}  // namespace

int run(const Options& options) {
  // Ctrl-C ends host-send with status 130 and nothing left behind
  // (posix/interrupt.hpp); a closed pty is an error to report, not a signal.
  ::signal(SIGPIPE, SIG_IGN);
  minrt::host::install_signal_cleanup();
  if (options.list) return list_ports_command();
  if (options.probe) return probe_command(options);

  Options o = options;
  Job job;
  if (const int status = prepare_scene(o, job); status != kExitOk) return status;
  if (const int status = check_before_sending(o, job); status != kExitOk) return status;

  std::unique_ptr<Link> link_held;
  minrt::host::LiveWindow window;
  TransferResult r;
  for (;;) {
    link_held = std::make_unique<Link>();
    Link& link = *link_held;
    if (const int status = find_device(o, link); status != kExitOk) return status;
    {
      // While the port is open, an interrupt only ends the transfer: the
      // port's settings go back and the simulator stops first, and the
      // interrupt takes effect at the end of this block.
      minrt::host::InterruptsHeld held;
      if (const int status = open_port(o, link); status != kExitOk) return status;
      if (o.show && !window.is_open() && !window.open("host-send: " + o.output, r.message))
        warn("not showing the image: " + r.message);
      r = transfer(o, job, link, window);
      close_link(link, r);
    }
    // A simulated board that read a texel not sent starts again, and gets
    // every texel; a real one needs a reset first (transfer_error says so).
    if (!(o.sim && job.sparse && unsent_texel(r))) break;
    warn("the board read a texel host-send did not send (" + r.message + "); sending the textures whole");
    o.full_textures = true;
    job = Job{};
    if (const int status = prepare_scene(o, job); status != kExitOk) return status;
    if (const int status = check_before_sending(o, job); status != kExitOk) return status;
  }
  if (r.status != TransferResult::Status::kOk) return transfer_error(job, r);
  const Link& link = *link_held;

  const std::string digest = sha256_hex_of(r.image);
  std::size_t file_bytes = 0;
  bool recompressed = false;
  if (const int status = write_image(o, job, r, digest, file_bytes, recompressed); status != kExitOk) return status;
  if (!o.quiet) print_summary(o, job, link, r, file_bytes, digest, recompressed);
  if (window.is_open()) show_written(o, window);
  if (!o.verify_ref.empty()) print_verification(r, job.reference);
  return kExitOk;
}

}  // namespace minrt::send
