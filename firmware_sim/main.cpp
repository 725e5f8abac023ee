// firmware-sim: wires the command line to a Machine, runs it, reports.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include "board_file.hpp"
#include "boot_args.hpp"
#include "cli_options.hpp"
#include "disassembler.hpp"
#include "elf_loader.hpp"
#include "flame_graph.hpp"
#include "fpu_approx.hpp"
#include "fpu_check.hpp"
#include "fpu_model_config.hpp"
#include "gdb_stub.hpp"
#include "hex_image.hpp"
#include "machine.hpp"
#include "memory_map.hpp"
#include "output_check.hpp"
#include "posix/input_file.hpp"
#include "posix/output_file.hpp"
#include "profile_writers.hpp"
#include "pty_backend.hpp"
#include "run_progress.hpp"
#include "run_report.hpp"
#include "trace_stream.hpp"

#ifndef FWSIM_VERSION
#define FWSIM_VERSION "0"
#endif

namespace {

using namespace fwsim;

struct ExitNow {
  int status;
};

[[noreturn]] void die(int status, const std::string& msg) {
  // Messages quote the user's files (a board file's bad key): control bytes
  // are escaped, so a file cannot write escape sequences to the terminal.
  std::string shown;
  for (const char ch : msg) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f) {
      shown.push_back(ch);
    } else {
      char esc[5];
      std::snprintf(esc, sizeof esc, "\\x%02x", c);
      shown += esc;
    }
  }
  std::fprintf(stderr, "firmware-sim: error: %s\n", shown.c_str());
  throw ExitNow{status};
}

// CPU time of this process: with other jobs on the machine it shows the
// simulator's own speed, which wall-clock MIPS cannot.
double cpu_seconds() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

int open_file(const std::string& path, int flags) {
  int fd = ::open(path.c_str(), flags | O_CLOEXEC, 0644);
  if (fd < 0) die(kExitUsage, path + ": " + std::strerror(errno));  // a bad option value
  return fd;
}

// Board, machine, cycle-model and FPU-model files are a few kilobytes.
constexpr size_t kMaxConfigFileBytes = size_t{1} << 20;

std::string read_text(const std::string& path, const char* what) {
  std::string text, why;
  if (!minrt::host::read_whole_file(path, text, why, kMaxConfigFileBytes))
    die(kExitUsage, path + ": cannot read " + what + ": " + why);
  return text;
}

// Profiles go through posix/output_file.hpp: a unique temporary file next
// to the target, renamed over it only when complete; a FIFO, device or
// symbolic link is refused; "-" is standard output.
template <typename Writer>
void write_output(const std::string& path, Writer w) {
  std::ostringstream text;
  w(text);
  std::string error;
  if (!minrt::host::write_file_atomically(path, text.str(), false, minrt::host::Durability::kSynced, error)) die(kExitIo, error);
}

int run(int argc, char** argv) {
  CliOptions opt;
  if (int status = 0; !parse_cli(argc, argv, FWSIM_VERSION, opt, status)) return status;

  FpuModelConfig fpu_cfg;
  try {
    if (!opt.fpu_model.empty()) fpu_cfg = parse_fpu_model(read_text(opt.fpu_model, "FPU model"), opt.fpu_model);
    for (const std::string& list : opt.fpu_settings) apply_fpu_settings(fpu_cfg, list);
  } catch (const std::runtime_error& e) {
    die(kExitUsage, e.what());
  }
  if (opt.fpu_check) {
    const FpuCheckReport report = check_fpu_model(fpu_cfg);
    print_fpu_check(report, stdout);
    return report.all_meet() ? 0 : 1;
  }
  // Only a non-IEEE model changes the interpreter's dispatch.
  std::unique_ptr<FpuApprox> fpu_model;
  if (!fpu_cfg.is_ieee()) fpu_model = std::make_unique<FpuApprox>(fpu_cfg);

  // The memory map: the board file's (default: the reference board), or the
  // machine file, then the options.
  MemoryMap map;
  std::optional<Board> board;
  try {
    if (!opt.board_file.empty()) {
      board = parse_board_file(read_text(opt.board_file, "board file"), opt.board_file);
      map = board->map;
    }
    if (!opt.machine_file.empty()) parse_machine_file(read_text(opt.machine_file, "machine file"), opt.machine_file, map);
    if (!opt.ram_spec.empty()) parse_ram_spec(opt.ram_spec, map);
    if (opt.ram_size) map.ram_size = opt.ram_size;
    if (!opt.uart_base.empty()) map.uart_base = parse_address(opt.uart_base, "--uart");
    if (!opt.finisher_base.empty()) map.finisher_base = parse_address(opt.finisher_base, "--finisher");
    check_memory_map(map);
  } catch (const std::runtime_error& e) {
    die(kExitUsage, e.what());
  }

  // Output files are written after the run: check now that they can be.
  // Profiles replace only a regular file or a new name (a FIFO or device
  // is refused now, not after the run); the commit log is a stream and may
  // go to a FIFO.
  for (const std::string* out : {&opt.profile_out, &opt.folded_out, &opt.flame_out, &opt.commit_log}) {
    if (out->empty()) continue;
    std::string problem = output_path_problem(*out);
    if (problem.empty() && out != &opt.commit_log && !minrt::host::check_output_target(*out, false, problem))
      problem = problem.substr(0, problem.find(" (--write-through"));  // an option firmware-sim does not have
    if (!problem.empty()) die(kExitUsage, problem);
  }

  std::unique_ptr<CycleModel> model;
  CycleModelConfig model_cfg = default_cycle_model();
  const bool profiling = !opt.profile_out.empty() || !opt.folded_out.empty() || !opt.flame_out.empty();
  const bool timed = !opt.cycle_model.empty() || profiling;
  try {
    if (!opt.cycle_model.empty() && opt.cycle_model != "default")
      model_cfg = parse_cycle_model(read_text(opt.cycle_model, "cycle model"), opt.cycle_model);
  } catch (const std::runtime_error& e) {
    die(kExitUsage, e.what());
  }
  // A board file's clock, unless a cycle model names its own.
  if (board && board->clock_hz != 0 && opt.cycle_model.empty()) model_cfg.clock_hz = board->clock_hz;
  if (timed) model = std::make_unique<CycleModel>(model_cfg);

  // The ELF argument must name a readable regular file (status 2 like any
  // bad argument); what it contains is the loader's business (status 3).
  {
    std::string why;
    const int fd = minrt::host::open_regular_file(opt.elf, why);
    if (fd < 0) die(kExitUsage, opt.elf + ": " + why);
    ::close(fd);
  }
  Machine m(map);
  if (board) m.set_isa(board->isa);
  LoadedElf elf;
  try {
    if (opt.load_hex) {
      // The image starts at the board's ROM, else its reset address, else RAM.
      const uint32_t base = map.rom_size ? map.rom_base : board ? board->reset : map.ram_base;
      const LoadedImage img = load_hex_image(opt.elf, m.bus(), base);
      elf.entry = base;
      elf.text_begin = img.begin;
      elf.text_end = img.end;
    } else {
      elf = load_elf(opt.elf, m.bus());
    }
    // A real board gets no boot arguments: a3 is not the magic, and crt0
    // calls main(0, NULL), the build-time defaults.
    if (!opt.real_board) {
      std::vector<std::string> fw_args{opt.elf};
      fw_args.insert(fw_args.end(), opt.args.begin(), opt.args.end());
      place_boot_args(m.bus(), m.hart(), fw_args);
    }
  } catch (const std::runtime_error& e) {
    die(kExitLoad, e.what());
  }
  // A board starts at its reset address, whatever the ELF's entry says.
  m.hart().pc = board ? board->reset : elf.entry;
  if (board && elf.entry != board->reset)
    std::fprintf(stderr, "firmware-sim: warning: %s: entry 0x%08x is not board %s's reset address 0x%08x; starting at reset\n",
                 opt.elf.c_str(), elf.entry, board->name.c_str(), board->reset);
  m.csr().set_clock_hz(model_cfg.clock_hz);

  // Listen before anything slow, so a busy port fails at once.
  std::unique_ptr<GdbStub> gdb;
  if (opt.gdb_port >= 0) {
    try {
      gdb = std::make_unique<GdbStub>(opt.gdb_port);
    } catch (const std::runtime_error& e) {
      die(kExitIo, e.what());
    }
  }

  Uart::Config ucfg;
  ucfg.layout = map.uart;
  ucfg.real_board = opt.real_board;
  ucfg.clock_hz = model_cfg.clock_hz;
  int held_slave = -1;
  if (opt.pty) {
    try {
      ucfg.in_fd = ucfg.out_fd = opt.real_board ? open_uart_pty_for_board(held_slave) : open_uart_pty();
    } catch (const std::runtime_error& e) {
      die(kExitIo, e.what());
    }
    ucfg.interactive = true;
  }
  if (!opt.uart_in.empty()) {
    // A stream on purpose (a FIFO, a terminal), but not a directory; a FIFO
    // without a writer does not block the open.
    std::string why;
    ucfg.in_fd = minrt::host::open_input_stream(opt.uart_in, why);
    if (ucfg.in_fd < 0) die(kExitUsage, opt.uart_in + ": " + why);
  }
  if (!opt.uart_out.empty()) ucfg.out_fd = open_file(opt.uart_out, O_WRONLY | O_CREAT | O_TRUNC);
  if (opt.baud) ucfg.cycles_per_byte = model_cfg.clock_hz * 10 / opt.baud;
  if (opt.baud && !ucfg.cycles_per_byte) ucfg.cycles_per_byte = 1;
  ucfg.max_output = opt.max_output;
  Uart uart(ucfg);
  m.bus().attach_uart(&uart);

  std::unique_ptr<Profiler> profiler;
  if (profiling)
    profiler = std::make_unique<Profiler>(elf.symbols, elf.entry);
  m.set_cycle_model(model.get());
  m.set_profiler(profiler.get());
  // The trace goes to stderr through its own buffered stream: unbuffered
  // stderr would cost a system call per instruction.
  // Every write to it is checked (trace_stream.hpp).
  TraceStream trace;
  if (opt.trace || !opt.commit_log.empty()) {
    const bool to_stdout = opt.commit_log == "-";
    const int fd = opt.trace || to_stdout ? ::fcntl(opt.trace ? STDERR_FILENO : STDOUT_FILENO, F_DUPFD_CLOEXEC, 3)
                                          : ::open(opt.commit_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    const std::string name = opt.trace ? "the trace (standard error)" : to_stdout ? "the commit log (standard output)"
                                                                               : "the commit log " + opt.commit_log;
    if (fd < 0) die(kExitIo, "cannot open " + name + ": " + std::strerror(errno));
    std::string why;
    if (!trace.open(fd, name, why)) die(kExitIo, why);
    m.set_trace(trace.file(), !opt.trace);
  }
  m.set_fpu_model(fpu_model.get());
  m.set_jit(opt.jit);

  const double cpu0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const uint64_t max_instructions = opt.max_instructions;
  StopInfo stop;
  bool killed = false, interrupted = false;
  if (gdb) {
    try {
      stop = gdb->serve(m, max_instructions, killed);
    } catch (const std::runtime_error& e) {
      die(kExitIo, e.what());
    }
  } else {
    // The progress line only where it is alone on the terminal: not over a
    // trace, nor over the firmware's own output on the same terminal.
    const bool uart_on_terminal = !opt.pty && opt.uart_out.empty() && ::isatty(STDOUT_FILENO);
    RunProgress progress(::isatty(STDERR_FILENO) && !opt.trace && !uart_on_terminal, stderr);
    if (trace.file() != nullptr) progress.stop_when([&trace] { return trace.failed(); });
    stop = progress.run(m, max_instructions);
    interrupted = progress.interrupted() && stop.cause == StopCause::None;
  }
  const auto t1 = std::chrono::steady_clock::now();
  const double cpu1 = cpu_seconds();
  // Lost output is an error (status 7 and a line), whatever the firmware's
  // own status: a full disk, /dev/full, a reader gone.
  uart.flush();
  std::string trace_error;
  const bool trace_ok = trace.close(trace_error);
  m.set_trace(nullptr);
  if (opt.pty && !opt.real_board) drain_uart_pty(ucfg.in_fd, 2000);
  if (held_slave >= 0) ::close(held_slave);
  if (!timed) m.hart().cycles = m.hart().instret;
  if (uart.bytes_dropped())
    std::fprintf(stderr,
                 "firmware-sim: warning: %llu bytes dropped while the UART was off (the board file's uart_enable "
                 "condition; the firmware switches it on with uart_init)\n",
                 static_cast<unsigned long long>(uart.bytes_dropped()));

  if (interrupted) {
    // What ran so far, and no profile of a run cut short.
    std::fprintf(stderr, "firmware-sim: interrupted at pc 0x%08x after %llu instructions (%.1f s, %.0f MIPS)\n",
                 m.hart().pc, static_cast<unsigned long long>(m.hart().instret),
                 std::chrono::duration<double>(t1 - t0).count(),
                 static_cast<double>(m.hart().instret) / std::chrono::duration<double, std::micro>(t1 - t0).count());
    return kExitInterrupted;
  }
  if (uart.output_limited()) {
    std::fprintf(stderr, "firmware-sim: error: output limit: the firmware sent %llu UART bytes at pc 0x%08x after %llu "
                 "instructions (--max-output N, --no-limit)\n", static_cast<unsigned long long>(opt.max_output),
                 m.hart().pc, static_cast<unsigned long long>(m.hart().instret));
    return kExitLimit;
  }
  if (uart.write_errno() != 0 || !trace_ok) {
    if (uart.write_errno() != 0)
      std::fprintf(stderr, "firmware-sim: error: cannot write the UART output %s: %s [after %llu instructions]\n",
                   opt.uart_out.empty() ? "(standard output)" : opt.uart_out.c_str(), std::strerror(uart.write_errno()),
                   static_cast<unsigned long long>(m.hart().instret));
    if (!trace_ok)
      std::fprintf(stderr, "firmware-sim: error: %s [after %llu instructions]\n", trace_error.c_str(),
                   static_cast<unsigned long long>(m.hart().instret));
    return kExitIo;
  }
  if (killed) {
    std::fprintf(stderr, "firmware-sim: error: killed by gdb at pc 0x%08x [after %llu instructions, exit status %d]\n",
                 m.hart().pc, static_cast<unsigned long long>(m.hart().instret), kExitKilled);
  } else if (stop.cause != StopCause::Exit) {
    uint32_t word = 0;
    if (const uint8_t* p = m.bus().host_at(stop.pc, 4)) std::memcpy(&word, p, 4);
    else if (const uint8_t* p2 = m.bus().host_at(stop.pc, 2)) std::memcpy(&word, p2, 2);
    std::fprintf(stderr, "firmware-sim: error: %s\n", describe_stop(stop, word, elf.symbols, m.hart().instret).c_str());
  }
  if (profiler) {
    profiler->finish(Cost{m.hart().instret, m.hart().cycles});
    std::string cmd = "firmware-sim " + opt.elf;
    for (const auto& a : opt.args) cmd += " " + a;
    if (!opt.profile_out.empty())
      write_output(opt.profile_out, [&](std::ostream& o) { write_callgrind(*profiler, o, cmd, opt.elf); });
    if (!opt.folded_out.empty())
      write_output(opt.folded_out, [&](std::ostream& o) { write_folded(*profiler, o); });
    if (!opt.flame_out.empty()) {
      const std::string base = opt.elf.substr(opt.elf.find_last_of('/') + 1);
      const std::string title = base + ": " + (opt.cycle_model.empty() ? "default" : opt.cycle_model) +
                                " cycle model, " + std::to_string(m.hart().cycles) + " cycles";
      write_output(opt.flame_out, [&](std::ostream& o) { write_flame_graph_svg(*profiler, o, title); });
    }
  }
  if (opt.stats) {
    RunSummary s{m.hart().instret, m.hart().cycles,
                 std::chrono::duration<double, std::micro>(t1 - t0).count(), (cpu1 - cpu0) * 1e6,
                 model.get(), model_cfg,
                 opt.cycle_model.empty() ? (timed ? "default" : "none") : opt.cycle_model,
                 uart.bytes_out(), uart.bytes_in(), opt.baud, profiler.get(), describe(fpu_cfg),
                 opt.jit, m.jit_blocks()};
    print_stats(s, stderr);
  }
  return killed ? kExitKilled : exit_status(stop);
}

}  // namespace

int main(int argc, char** argv) {
  // A reader that goes away (host-send stopped, `| head`) makes the UART's
  // writes fail with EPIPE, which ends the run with the I/O status (7);
  // the default SIGPIPE would kill the simulator instead (141).
  std::signal(SIGPIPE, SIG_IGN);
  try {
    return run(argc, argv);
  } catch (const ExitNow& e) {
    return e.status;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "firmware-sim: error: out of memory\n");
    return kExitIo;
  }
}
