#include "cli_options.hpp"

#include <cerrno>
#include <cstdlib>

#include "posix/command_line.hpp"

namespace fwsim {
namespace {

uint64_t parse_count(const std::string& opt, const std::string& v, bool allow_suffix) {
  if (v.empty() || v[0] == '-') throw UsageError(opt + " needs a positive number, got '" + v + "'");
  char* end = nullptr;
  errno = 0;
  unsigned long long n = std::strtoull(v.c_str(), &end, 0);
  uint64_t mult = 1;
  if (allow_suffix && *end && !end[1]) {
    if (*end == 'K' || *end == 'k') mult = 1024, ++end;
    else if (*end == 'M' || *end == 'm') mult = 1024 * 1024, ++end;
    else if (*end == 'G' || *end == 'g') mult = 1024 * 1024 * 1024, ++end;
  }
  if (errno || *end || n == 0 || n > UINT64_MAX / mult)
    throw UsageError(opt + " needs a positive number, got '" + v + "'");
  return n * mult;
}

uint64_t parse_port(const std::string& opt, const std::string& v) {
  if (v == "0") return 0;
  const uint64_t port = parse_count(opt, v, false);
  if (port > 65535) throw UsageError(opt + " needs a TCP port 0..65535, got '" + v + "'");
  return port;
}

const minrt::cli::Tool& cli_tool() {
  static const minrt::cli::Tool tool{
      "firmware-sim",
      R"(Usage: firmware-sim [OPTIONS] ELF [-- ARGS...]
       firmware-sim [OPTIONS] --load-hex FILE [-- ARGS...]
       firmware-sim [--fpu-model FILE] [--fpu KEY=VALUE,...] --fpu-check
Runs a bare-metal RV32IMF ELF; exits with the firmware's exit code. On a terminal,
a long run shows its progress on stderr; Ctrl-C stops it with a summary (status 130).
)",
      {
          {"uart-in", 0, "FILE", "UART input from FILE (default stdin)"},
          {"uart-out", 0, "FILE", "UART output to FILE (default stdout)"},
          {"pty", 0, nullptr, "UART on a new pseudo-terminal (path printed on stderr)"},
          {"real-board", 0, nullptr,
           "run as a real board: no boot arguments, and with --pty start at once and keep running as hosts "
           "open and close the pty (output nobody reads is lost, as on a serial line)"},
          {"baud", 0, "N", "pace the UART at N baud, 8N1, in simulated time"},
          {"cycle-model", 0, "FILE", "cycle model file ('default' = built-in model)"},
          {"fpu-model", 0, "FILE", "FPU model file (approximate div/sqrt, truncation...)"},
          {"fpu", 0, "KEY=VALUE,...", "FPU model settings, applied after --fpu-model\n(may be given again)"},
          {"fpu-check", 0, nullptr,
           "measure the FPU model against the course's error rules\n(exit 0 if every op meets them, 1 if one misses)"},
          {"profile-out", 0, "FILE", "per-function profile in callgrind format"},
          {"folded-out", 0, "FILE", "folded call stacks (cycles) for flame graphs"},
          {"flame-out", 0, "FILE", "flame graph (SVG, opens in any web browser)"},
          {"load-hex", 0, "FILE",
           "run a memory image of 32-bit words ($readmemh .hex/.mem,\nor .coe) loaded at the reset/ROM address, "
           "instead of an ELF"},
          {"max-instructions", 0, "N", "stop with an error after N instructions\n(default 4000000000000)"},
          {"max-output", 0, "N", "stop with an error once the firmware has sent N UART\nbytes (K/M/G suffix ok; default 1G)"},
          {"no-limit", 0, nullptr, "no bound on instructions or UART output"},
          {"no-jit", 0, nullptr,
           "interpret every instruction (no generated host code for\nhot loops; same results, slower)"},
          {nullptr, 0, nullptr, "Memory map (default: the board's, include/minrt/memory_map.h):"},
          {"ram", 0, "BASE:SIZE",
           "RAM at BASE, SIZE bytes (K/M suffix ok; default\n0x80000000:4M); e.g. --ram 0:1M for a program linked at 0"},
          {"ram-size", 0, "N", "RAM size only (default 4M)"},
          {"uart", 0, "ADDR", "NS16550A UART base (default 0x10000000)"},
          {"finisher", 0, "ADDR", "exit device (SiFive test finisher) base (default 0x100000)"},
          {"machine", 0, "FILE",
           "memory map from a file of key = value lines\n(ram = BASE:SIZE, uart = ADDR, finisher = ADDR)"},
          {"board", 0, "FILE",
           "model a board description (boards/NAME.board): its ISA,\nRAM/ROM, UART kind, halt method and reset address"},
          {nullptr, 0, nullptr, "Debugging:"},
          {"stats", 0, nullptr, "print instructions, cycles, host MIPS... on stderr"},
          {"trace", 0, nullptr, "print every executed instruction with the registers\nand memory it writes, on stderr"},
          {"commit-log", 0, "FILE", "the same in spike's --log-commits layout, to FILE"},
          {"gdb", 0, "PORT",
           "wait for GDB on 127.0.0.1:PORT (0 = any free port;\nthe port is printed on stderr) and run under its "
           "control"},
      },
      "Exit status: firmware's code; 2 usage, 3 bad ELF, 4 trap, 5 instruction or\noutput limit, "
      "6 UART input exhausted while polled,\n7 host I/O error (a failed write), 8 killed from gdb, "
      "130 interrupted (Ctrl-C).\n"};
  return tool;
}

// The options that exclude each other, and what must be given.
void check_combination(const CliOptions& o) {
  if (o.fpu_check) {
    if (!o.elf.empty()) throw UsageError("--fpu-check runs no firmware: drop '" + o.elf + "'");
    return;
  }
  if (o.elf.empty()) throw UsageError("missing ELF file (or --load-hex FILE)");
  if (o.pty && (!o.uart_in.empty() || !o.uart_out.empty()))
    throw UsageError("--pty cannot be combined with --uart-in/--uart-out");
  if (!o.board_file.empty() && !o.machine_file.empty())
    throw UsageError("--board and --machine cannot be combined (the board file holds the map)");
  if (o.trace && !o.commit_log.empty()) throw UsageError("--trace and --commit-log cannot be combined");
  if (o.gdb_port >= 0 && o.pty) throw UsageError("--gdb cannot be combined with --pty");
  if (o.real_board && !o.args.empty()) throw UsageError("--real-board passes no boot arguments: drop the ones after --");
}

}  // namespace

bool parse_cli(int argc, char** argv, const char* version, CliOptions& o, int& status) {
  try {
    const bool go_on = minrt::cli::parse_tool(
        argc, argv, cli_tool(), version,
        [&](const minrt::cli::Option* opt, const std::string& v) -> std::string {
          if (opt == nullptr) {
            if (o.load_hex) return "--load-hex replaces the ELF: drop '" + v + "'";
            if (!o.elf.empty()) return "unexpected argument '" + v + "' (firmware arguments go after --)";
            o.elf = v;
            return "";
          }
          const std::string name = opt->name;
          const std::string a = "--" + name;
          if (name == "uart-in") o.uart_in = v;
          else if (name == "uart-out") o.uart_out = v;
          else if (name == "pty") o.pty = true;
          else if (name == "real-board") o.real_board = true;
          else if (name == "baud") o.baud = parse_count(a, v, false);
          else if (name == "cycle-model") o.cycle_model = v;
          else if (name == "fpu-model") o.fpu_model = v;
          else if (name == "fpu") o.fpu_settings.push_back(v);
          else if (name == "fpu-check") o.fpu_check = true;
          else if (name == "profile-out") o.profile_out = v;
          else if (name == "folded-out") o.folded_out = v;
          else if (name == "flame-out") o.flame_out = v;
          else if (name == "max-instructions") o.max_instructions = parse_count(a, v, false);
          else if (name == "max-output") o.max_output = parse_count(a, v, true);
          else if (name == "no-limit") o.max_instructions = o.max_output = UINT64_MAX;
          else if (name == "ram-size") {
            const uint64_t r = parse_count(a, v, true);
            if (r % 4096 || r < 65536 || r > 0x7ffff000ull)
              return "--ram-size must be a multiple of 4096 between 64K and 2047M";
            o.ram_size = static_cast<uint32_t>(r);
          } else if (name == "ram") o.ram_spec = v;
          else if (name == "uart") o.uart_base = v;
          else if (name == "finisher") o.finisher_base = v;
          else if (name == "machine") o.machine_file = v;
          else if (name == "board") o.board_file = v;
          else if (name == "gdb") o.gdb_port = static_cast<int>(parse_port(a, v));
          else if (name == "stats") o.stats = true;
          else if (name == "no-jit") o.jit = false;
          else if (name == "trace") o.trace = true;
          else if (name == "commit-log") o.commit_log = v;
          else if (name == "load-hex") {
            if (o.load_hex || !o.elf.empty()) return "--load-hex replaces the ELF: give one image";
            o.elf = v;
            o.load_hex = true;
          }
          return "";
        },
        status, nullptr, &o.args);
    if (!go_on) return false;
    check_combination(o);
  } catch (const UsageError& e) {
    status = minrt::cli::usage_error("firmware-sim", e.what());
    return false;
  }
  return true;
}

}  // namespace fwsim
