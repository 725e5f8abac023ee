#include "cli_options.hpp"

#include <cerrno>
#include <cstdlib>


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

}  // namespace

const char* cli_help_text() {
  return "Usage: firmware-sim [OPTIONS] ELF [-- ARGS...]\n"
         "       firmware-sim [OPTIONS] --load-hex FILE [-- ARGS...]\n"
         "       firmware-sim [--fpu-model FILE] [--fpu KEY=VALUE,...] --fpu-check\n"
         "Runs a bare-metal RV32IMF ELF; exits with the firmware's exit code.\n"
         "  --uart-in FILE         UART input from FILE (default stdin)\n"
         "  --uart-out FILE        UART output to FILE (default stdout)\n"
         "  --pty                  UART on a new pseudo-terminal (path printed on stderr)\n"
         "  --baud N               pace the UART at N baud, 8N1, in simulated time\n"
         "  --cycle-model FILE     cycle model file ('default' = built-in model)\n"
         "  --fpu-model FILE       FPU model file (approximate div/sqrt, truncation...)\n"
         "  --fpu KEY=VALUE,...    FPU model settings, applied after --fpu-model\n"
         "  --fpu-check            measure the FPU model against the course's error rules\n"
         "                         (exit 0 if every op meets them, 1 if one misses)\n"
         "  --profile-out FILE     per-function profile in callgrind format\n"
         "  --folded-out FILE      folded call stacks (cycles) for flame graphs\n"
         "  --flame-out FILE       flame graph (SVG, opens in any web browser)\n"
         "  --load-hex FILE        run a memory image of 32-bit words ($readmemh .hex/.mem,\n"
         "                         or .coe) loaded at the reset/ROM address, instead of an ELF\n"
         "  --max-instructions N   stop with an error after N instructions\n"
         "Memory map (default: the board's, include/minrt/memory_map.h):\n"
         "  --ram BASE:SIZE        RAM at BASE, SIZE bytes (K/M suffix ok; default\n"
         "                         0x80000000:4M); e.g. --ram 0:1M for a program linked at 0\n"
         "  --ram-size N           RAM size only (default 4M)\n"
         "  --uart ADDR            NS16550A UART base (default 0x10000000)\n"
         "  --finisher ADDR        exit device (SiFive test finisher) base (default 0x100000)\n"
         "  --machine FILE         memory map from a file of key = value lines\n"
         "                         (ram = BASE:SIZE, uart = ADDR, finisher = ADDR)\n"
         "  --board FILE           model a board description (boards/NAME.board): its ISA,\n"
         "                         RAM/ROM, UART kind, halt method and reset address\n"
         "Debugging:\n"
         "  --stats                print instructions, cycles, host MIPS... on stderr\n"
         "  --trace                print every executed instruction with the registers\n"
         "                         and memory it writes, on stderr\n"
         "  --commit-log FILE      the same in spike's --log-commits layout, to FILE\n"
         "  --gdb PORT             wait for GDB on 127.0.0.1:PORT (0 = any free port;\n"
         "                         the port is printed on stderr) and run under its control\n"
         "  -h, --help             this help\n"
         "  --version              the version\n"
         "Exit status: firmware's code; 2 usage, 3 bad ELF, 4 trap, 5 instruction limit,\n"
         "6 UART input exhausted while polled, 7 host I/O error, 8 killed from gdb.\n";
}

CliOptions parse_cli(const std::vector<std::string>& argv) {
  CliOptions o;
  size_t i = 0;
  auto value = [&](const std::string& opt) -> std::string {
    if (i + 1 >= argv.size()) throw UsageError(opt + " needs a value");
    return argv[++i];
  };
  for (; i < argv.size(); ++i) {
    const std::string& a = argv[i];
    if (a == "--") {
      o.args.assign(argv.begin() + static_cast<long>(i) + 1, argv.end());
      break;
    }
    if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--version") o.version = true;
    else if (a == "--uart-in") o.uart_in = value(a);
    else if (a == "--uart-out") o.uart_out = value(a);
    else if (a == "--pty") o.pty = true;
    else if (a == "--baud") o.baud = parse_count(a, value(a), false);
    else if (a == "--cycle-model") o.cycle_model = value(a);
    else if (a == "--fpu-model") o.fpu_model = value(a);
    else if (a == "--fpu") o.fpu_settings.push_back(value(a));
    else if (a == "--fpu-check") o.fpu_check = true;
    else if (a == "--profile-out") o.profile_out = value(a);
    else if (a == "--folded-out") o.folded_out = value(a);
    else if (a == "--max-instructions") o.max_instructions = parse_count(a, value(a), false);
    else if (a == "--ram-size") {
      uint64_t r = parse_count(a, value(a), true);
      if (r % 4096 || r < 65536 || r > 0x7ffff000ull)
        throw UsageError("--ram-size must be a multiple of 4096 between 64K and 2047M");
      o.ram_size = static_cast<uint32_t>(r);
    } else if (a == "--ram") o.ram_spec = value(a);
    else if (a == "--uart") o.uart_base = value(a);
    else if (a == "--finisher") o.finisher_base = value(a);
    else if (a == "--machine") o.machine_file = value(a);
    else if (a == "--board") o.board_file = value(a);
    else if (a == "--flame-out") o.flame_out = value(a);
    else if (a == "--gdb") {
      const uint64_t port = parse_port(a, value(a));
      o.gdb_port = static_cast<int>(port);
    } else if (a == "--stats") o.stats = true;
    else if (a == "--trace") o.trace = true;
    else if (a == "--commit-log") o.commit_log = value(a);
    else if (a == "--load-hex") {
      if (o.load_hex || !o.elf.empty()) throw UsageError("--load-hex replaces the ELF: give one image");
      o.elf = value(a);
      o.load_hex = true;
    }
    else if (a.size() > 1 && a[0] == '-') throw UsageError("unknown option " + a);
    else if (o.load_hex) throw UsageError("--load-hex replaces the ELF: drop '" + a + "'");
    else if (o.elf.empty()) o.elf = a;
    else throw UsageError("unexpected argument '" + a + "' (firmware arguments go after --)");
  }
  if (o.help || o.version) return o;
  if (o.fpu_check) {
    if (!o.elf.empty()) throw UsageError("--fpu-check runs no firmware: drop '" + o.elf + "'");
    return o;
  }
  if (o.elf.empty()) throw UsageError("missing ELF file (or --load-hex FILE)");
  if (o.pty && (!o.uart_in.empty() || !o.uart_out.empty()))
    throw UsageError("--pty cannot be combined with --uart-in/--uart-out");
  if (!o.board_file.empty() && !o.machine_file.empty())
    throw UsageError("--board and --machine cannot be combined (the board file holds the map)");
  if (o.trace && !o.commit_log.empty()) throw UsageError("--trace and --commit-log cannot be combined");
  if (o.gdb_port >= 0 && o.pty) throw UsageError("--gdb cannot be combined with --pty");
  return o;
}

}  // namespace fwsim
