// minrt-rtl: runs a CPU's RTL (Verilator model of rtl/harness/minrt_rtl_top.sv
// around the module minrt_cpu) as the board a board file describes: RAM and
// ROM from the firmware image, the board's UART at register level or as an
// 8N1 serial line, the halt, a pseudo-terminal for host-send, and
// optionally lock-step checking of every retired instruction against
// firmware-sim's core. The command line follows firmware-sim's where they
// overlap (--pty, --board, --baud, ELF -- ARGS), so host-send starts it as
// it starts the simulator. docs/rtl.md.
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "Vminrt_rtl_top.h"
#include "board_file.hpp"
#include "boot_args.hpp"
#include "bus.hpp"
#include "elf_loader.hpp"
#include "hex_image.hpp"
#include "lockstep.hpp"
#include "machine.hpp"
#include "pty_backend.hpp"
#include "serial_line.hpp"
#include "uart.hpp"
#include "verilated.h"
#include "verilated_fst_c.h"

namespace {

using namespace fwsim;

// Exit statuses besides the firmware's own (firmware-sim's where they mean
// the same).
constexpr int kUsage = 2, kLoad = 3, kFault = 4, kLimit = 5, kStall = 6, kIo = 7, kDiverged = 9;

[[noreturn]] void die(int status, const std::string& msg) {
  std::fprintf(stderr, "minrt-rtl: %s\n", msg.c_str());
  std::exit(status);
}

std::string read_text(const std::string& path, const char* what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die(kUsage, std::string("cannot read ") + what + " " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

uint64_t number(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(v.c_str(), &end, 0);
  if (v.empty() || *end || errno || v[0] == '-') die(kUsage, "bad " + opt + " '" + v + "': expected a number");
  return n;
}

struct Options {
  std::string board = MINRT_RTL_DEFAULT_BOARD;
  std::string image;
  std::vector<std::string> firmware_args;
  bool pty = false;
  std::string uart_in, uart_out;
  uint64_t baud = 0, clock_hz = 50000000;
  std::string serial;  // "", "harness", "cpu"
  uint64_t cycles_per_bit = 0;
  bool lockstep = false;
  size_t history = 16;
  std::string fpu_spec;
  std::string fault;
  std::string trace;
  uint64_t trace_start = 0, trace_cycles = 10000;
  uint64_t max_cycles = 0;
  unsigned mem_wait = 0;
  bool quiet = false;
};

const char* kUsageText =
    "Usage: minrt-rtl [--board FILE] [OPTIONS] IMAGE [-- FIRMWARE-ARGS]\n"
    "Runs the CPU's RTL (Verilator) as the board FILE describes, IMAGE (ELF, .hex\n"
    "or .bin) in its memory. The UART is stdin/stdout unless --pty or --uart-in/out.\n"
    "  --board FILE         board file (default boards/rtl-reference.board)\n"
    "  --pty                the UART on a pseudo-terminal, announced on stderr\n"
    "  --uart-in F, --uart-out F   the UART's input and output files\n"
    "  --baud N             pace the register-level UART at N baud of --clock-hz\n"
    "  --clock-hz N         the CPU clock for --baud and MHz figures (default 50000000)\n"
    "  --serial[=harness|cpu]  8N1 serial line: the harness's UART (default) or the\n"
    "                       CPU's own uart_tx/uart_rx pins; clocks per bit from the\n"
    "                       board's uart_divisor or --cycles-per-bit N\n"
    "  --lockstep           check every retired instruction against firmware-sim\n"
    "  --history N          instructions shown before a divergence (default 16)\n"
    "  --fpu-spec SPEC      float bounds, e.g. add=2^-23,mul=2^-22,div=2^-20,sqrt=2^-20\n"
    "  --fault NAME         reference core test builds: sltu, load-sign or load-use\n"
    "  --trace FILE.fst     write a waveform window: --trace-start C, --trace-cycles N\n"
    "  --max-cycles N       stop (status 5) after N cycles\n"
    "  --mem-wait N         memory answers after N wait cycles (default 0)\n"
    "  -q                   no report line\n";

Options parse(int argc, char** argv) {
  Options o;
  bool have_image = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    std::string v;
    bool has_v = false;
    if (a.rfind("--", 0) == 0 && a.find('=') != std::string::npos) {
      v = a.substr(a.find('=') + 1);
      a = a.substr(0, a.find('='));
      has_v = true;
    }
    auto value = [&]() -> std::string {
      if (has_v) return v;
      if (i + 1 >= argc) die(kUsage, a + " needs a value");
      return argv[++i];
    };
    if (a == "--") {
      for (++i; i < argc; ++i) o.firmware_args.push_back(argv[i]);
    } else if (a == "-h" || a == "--help") {
      std::fputs(kUsageText, stdout);
      std::exit(0);
    } else if (a == "--board") o.board = value();
    else if (a == "--pty") o.pty = true;
    else if (a == "--uart-in") o.uart_in = value();
    else if (a == "--uart-out") o.uart_out = value();
    else if (a == "--baud") o.baud = number(a, value());
    else if (a == "--clock-hz") o.clock_hz = number(a, value());
    else if (a == "--ram-size") value();  // host-send passes it; the board file decides
    else if (a == "--serial") {
      o.serial = has_v ? v : "harness";
      if (o.serial != "harness" && o.serial != "cpu") die(kUsage, "bad --serial '" + o.serial + "': harness or cpu");
    } else if (a == "--cycles-per-bit") o.cycles_per_bit = number(a, value());
    else if (a == "--lockstep") o.lockstep = true;
    else if (a == "--history") o.history = number(a, value());
    else if (a == "--fpu-spec") o.fpu_spec = value();
    else if (a == "--fault") o.fault = value();
    else if (a == "--trace") o.trace = value();
    else if (a == "--trace-start") o.trace_start = number(a, value());
    else if (a == "--trace-cycles") o.trace_cycles = number(a, value());
    else if (a == "--max-cycles") o.max_cycles = number(a, value());
    else if (a == "--mem-wait") o.mem_wait = static_cast<unsigned>(number(a, value()));
    else if (a == "-q") o.quiet = true;
    else if (!a.empty() && a[0] == '-') die(kUsage, "unknown option '" + a + "' (see --help)");
    else if (have_image) die(kUsage, "more than one image: '" + o.image + "' and '" + a + "'");
    else {
      o.image = a;
      have_image = true;
    }
  }
  if (!have_image) die(kUsage, "no image given (see --help)");
  if (o.pty && (!o.uart_in.empty() || !o.uart_out.empty())) die(kUsage, "--pty and --uart-in/--uart-out exclude each other");
  return o;
}

bool ends_with(const std::string& s, const char* tail) {
  const size_t n = std::strlen(tail);
  return s.size() >= n && s.compare(s.size() - n, n, tail) == 0;
}

// Loads the image into `bus`; the ELF's symbols into `symbols`.
void load_image(const std::string& path, Bus& bus, uint32_t reset, SymbolTable* symbols) {
  if (ends_with(path, ".hex") || ends_with(path, ".mem") || ends_with(path, ".coe")) {
    load_hex_image(path, bus, reset);
  } else if (ends_with(path, ".bin")) {
    const std::string bytes = read_text(path, "image");
    uint8_t* p = bus.host_at(reset, static_cast<uint32_t>(bytes.size()));
    if (!p) throw std::runtime_error(path + ": " + std::to_string(bytes.size()) + " bytes do not fit at the reset address");
    std::memcpy(p, bytes.data(), bytes.size());
  } else {
    LoadedElf elf = load_elf(path, bus);
    if (symbols) *symbols = std::move(elf.symbols);
  }
}

// The boot stub: with firmware arguments, the first fetches from the reset
// address are answered with a few instructions that set a0..a3 and sp as
// firmware-sim's boot convention does (include/minrt/boot_args.h) and jump
// back to the reset address, where the image's own code then runs.
std::vector<uint32_t> boot_stub(const HartState& h) {
  std::vector<uint32_t> w;
  for (unsigned r : {10u, 11u, 12u, 13u, 2u}) {
    const uint32_t v = h.x[r];
    const uint32_t hi = (v + 0x800) & 0xfffff000u;
    w.push_back(hi | r << 7 | 0x37);                               // lui r, hi
    w.push_back((v - hi) << 20 | r << 15 | r << 7 | 0x13);          // addi r, r, lo
  }
  const uint32_t off = static_cast<uint32_t>(-4 * static_cast<int32_t>(w.size()));
  w.push_back(((off >> 20) & 1) << 31 | ((off >> 1) & 0x3ff) << 21 | ((off >> 11) & 1) << 20 |
              ((off >> 12) & 0xff) << 12 | 0x6f);                  // jal x0, reset
  return w;
}

int fault_number(const std::string& name) {
  if (name.empty()) return 0;
  if (name == "sltu") return 1;
  if (name == "load-sign") return 2;
  if (name == "load-use") return 3;
  die(kUsage, "bad --fault '" + name + "': sltu, load-sign or load-use");
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);

  Board board;
  try {
    board = parse_board_file(read_text(o.board, "board file"), o.board);
    check_memory_map(board.map);
  } catch (const std::runtime_error& e) {
    die(kUsage, e.what());
  }
  const MemoryMap& map = board.map;
  const uint32_t uart_size = uart_region_size(map.uart);

  Bus bus(map);
  SymbolTable symbols;
  try {
    load_image(o.image, bus, board.reset, &symbols);
  } catch (const std::runtime_error& e) {
    die(kLoad, e.what());
  }
  symbols.finalize();

  HartState boot;
  std::vector<uint32_t> stub;
  if (!o.firmware_args.empty()) {
    std::vector<std::string> args{o.image};
    args.insert(args.end(), o.firmware_args.begin(), o.firmware_args.end());
    try {
      place_boot_args(bus, boot, args);
    } catch (const std::runtime_error& e) {
      die(kUsage, e.what());
    }
    stub = boot_stub(boot);
  }

  // The lock-step reference: firmware-sim's core on the same memory.
  std::unique_ptr<Machine> ref;
  std::unique_ptr<Uart> ref_uart;
  std::unique_ptr<Lockstep> lockstep;
  if (o.lockstep) {
    ref = std::make_unique<Machine>(map);
    ref->set_isa(board.isa);
    ref->set_jit(false);
    try {
      load_image(o.image, ref->bus(), board.reset, nullptr);
      if (!o.firmware_args.empty()) {
        std::vector<std::string> args{o.image};
        args.insert(args.end(), o.firmware_args.begin(), o.firmware_args.end());
        place_boot_args(ref->bus(), ref->hart(), args);
      }
    } catch (const std::runtime_error& e) {
      die(kLoad, e.what());
    }
    ref->hart().pc = board.reset;
    Uart::Config rc;
    rc.layout = map.uart;
    rc.in_fd = -1;
    rc.out_fd = ::open("/dev/null", O_WRONLY);
    ref_uart = std::make_unique<Uart>(rc);
    ref->bus().attach_uart(ref_uart.get());
    FpuSpec spec;
    try {
      if (!o.fpu_spec.empty()) spec = parse_fpu_spec(o.fpu_spec);
    } catch (const std::runtime_error& e) {
      die(kUsage, e.what());
    }
    lockstep = std::make_unique<Lockstep>(*ref, &symbols, o.history, spec);
  }

  // The UART's host side.
  int in_fd = 0, out_fd = 1;
  if (o.pty) {
    try {
      in_fd = out_fd = open_uart_pty("minrt-rtl");
    } catch (const std::runtime_error& e) {
      die(kIo, e.what());
    }
  }
  if (!o.uart_in.empty() && (in_fd = ::open(o.uart_in.c_str(), O_RDONLY)) < 0)
    die(kIo, "cannot open " + o.uart_in + ": " + std::strerror(errno));
  if (!o.uart_out.empty() && (out_fd = ::open(o.uart_out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644)) < 0)
    die(kIo, "cannot open " + o.uart_out + ": " + std::strerror(errno));

  Uart::Config ucfg;
  ucfg.layout = map.uart;
  ucfg.in_fd = in_fd;
  ucfg.out_fd = out_fd;
  ucfg.interactive = o.pty;
  if (o.baud) ucfg.cycles_per_byte = std::max<uint64_t>(1, o.clock_hz * 10 / o.baud);
  Uart uart(ucfg);
  bus.attach_uart(&uart);

  std::unique_ptr<SerialLine> line;
  if (!o.serial.empty()) {
    const uint64_t cpb = o.cycles_per_bit ? o.cycles_per_bit : board.uart_divisor.value_or(0);
    if (cpb < 4 || cpb > 65535) die(kUsage, "--serial needs 4..65535 clocks per bit: the board's uart_divisor or --cycles-per-bit");
    if (o.serial == "harness" && map.uart.kind != UartKind::Generic)
      die(kUsage, "--serial=harness models the generic UART kind only; the board has another (use --serial=cpu with your UART)");
    line = std::make_unique<SerialLine>(in_fd, out_fd, static_cast<unsigned>(cpb));
  }

  // The model.
  auto ctx = std::make_unique<VerilatedContext>();
  std::vector<std::string> vargs{"minrt-rtl"};
  if (const int f = fault_number(o.fault)) vargs.push_back("+minrt_fault=" + std::to_string(f));
  std::vector<const char*> vargv;
  for (auto& s : vargs) vargv.push_back(s.c_str());
  ctx->commandArgs(static_cast<int>(vargv.size()), vargv.data());
  if (!o.trace.empty()) ctx->traceEverOn(true);
  auto top = std::make_unique<Vminrt_rtl_top>(ctx.get());
  std::unique_ptr<VerilatedFstC> fst;
  top->serial_mode = o.serial.empty() ? 0 : o.serial == "harness" ? 1 : 2;
  top->uart_base = map.uart_base;
  top->uart_size = uart_size;
  top->cycles_per_bit = line ? static_cast<uint16_t>(line->cycles_per_bit()) : 16;
  top->uart_data_offset = map.uart.data;
  top->uart_status_offset = map.uart.status;
  top->uart_tx_ready_mask = map.uart.tx_ready;
  top->uart_rx_ready_mask = map.uart.rx_ready;
  top->ser_rx = 1;

  uint64_t cycle = 0;
  auto tick = [&] {
    top->clk = 0;
    top->eval();
    if (fst && cycle >= o.trace_start && cycle < o.trace_start + o.trace_cycles) fst->dump(2 * cycle);
  };
  auto tock = [&] {
    top->clk = 1;
    top->eval();
    if (fst && cycle >= o.trace_start && cycle < o.trace_start + o.trace_cycles) fst->dump(2 * cycle + 1);
    ++cycle;
  };
  if (!o.trace.empty()) {
    fst = std::make_unique<VerilatedFstC>();
    top->trace(fst.get(), 99);
    fst->open(o.trace.c_str());
  }
  top->rst = 1;
  for (int i = 0; i < 4; ++i) {
    top->imem_ready = top->dmem_ready = 0;
    tick();
    tock();
  }
  top->rst = 0;
  cycle = 0;

  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  uint64_t retired = 0;
  uint32_t shadow[32] = {};
  for (unsigned r = 0; r < 32; ++r) shadow[r] = boot.x[r];
  size_t stub_left = stub.size();      // stub words not yet fetched
  uint64_t stub_retire = stub.size();  // stub instructions not yet retired (not checked)
  unsigned iwait = 0, dwait = 0;
  int status = -1;           // the run's end, once known
  std::string stop_msg;
  uint64_t stop_at = 0;      // cycles after the halt that still collect retirements

  auto stop = [&](int st, const std::string& msg) {
    if (status < 0) {
      status = st;
      stop_msg = msg;
      stop_at = cycle + 8;
    }
  };

  while (status < 0 || cycle < stop_at) {
    if (o.max_cycles && cycle >= o.max_cycles && status < 0) stop(kLimit, "stopped after --max-cycles " + std::to_string(o.max_cycles));
    // Instruction port.
    top->imem_ready = 0;
    if (top->imem_valid && status < 0) {
      if (iwait < o.mem_wait) ++iwait;
      else {
        iwait = 0;
        const uint32_t a = top->imem_addr;
        uint32_t w = 0;
        if (stub_left && a - board.reset < 4 * stub.size()) {
          w = stub[(a - board.reset) / 4];
          if ((a - board.reset) / 4 == stub.size() - 1) stub_left = 0;
        } else if (const uint8_t* p = bus.host_at(a & ~3u, 4)) {
          std::memcpy(&w, p, 4);
        } else {
          char b[64];
          std::snprintf(b, sizeof b, "instruction fetch outside memory at 0x%08x", a);
          stop(kFault, b);
        }
        top->imem_rdata = w;
        top->imem_ready = 1;
        // A jump to itself is the "loop" halt: the status is in a0.
        if (w == 0x0000006f && map.halt == HaltKind::Loop) stop(static_cast<int>(shadow[10] & 0xff), "");
      }
    }
    // Data port.
    top->dmem_ready = 0;
    if (top->dmem_valid && status < 0) {
      if (dwait < o.mem_wait) ++dwait;
      else {
        dwait = 0;
          const uint32_t a = top->dmem_addr & ~3u;
        const unsigned strb = top->dmem_wstrb ? top->dmem_wstrb : 0xf;
        const unsigned lane = static_cast<unsigned>(__builtin_ctz(strb));
        const unsigned size = static_cast<unsigned>(__builtin_popcount(strb));
        uint32_t rdata = 0;
        if (uint8_t* p = bus.in_ram(a, 4) ? bus.ram_at(a) : nullptr) {
          if (top->dmem_we) {
            for (unsigned i = 0; i < 4; ++i)
              if (strb & (1u << i)) p[i] = static_cast<uint8_t>(top->dmem_wdata >> (8 * i));
          } else std::memcpy(&rdata, p, 4);
        } else if (!top->dmem_we && bus.host_at(a, 4)) {
          std::memcpy(&rdata, bus.host_at(a, 4), 4);  // ROM
        } else if (line && top->serial_mode == 2 && a - map.uart_base < uart_size) {
          // the CPU's own UART answers inside minrt_cpu; nothing comes out here
        } else {
          Bus::Result r;
          if (top->dmem_we) r = bus.store(a + lane, size, top->dmem_wdata >> (8 * lane), cycle);
          else {
            uint32_t v = 0;
            r = bus.load(a + lane, size, v, cycle);
            rdata = v << (8 * lane);
          }
          if (bus.finished()) stop(bus.exit_code(), "");
          else if (r == Bus::Result::Stop) stop(uart.io_error() ? kIo : kStall, uart.io_error() ? "UART host I/O error" : "the firmware polls the UART after its input ended");
          else if (r != Bus::Result::Ok) {
            char b[80];
            std::snprintf(b, sizeof b, "%s fault at 0x%08x (mask 0x%x)", top->dmem_we ? "store" : "load", a, strb);
            stop(kFault, b);
          }
        }
        top->dmem_rdata = rdata;
        top->dmem_ready = 1;
      }
    }
    if (line) {
      if (top->uart_touched) line->open();
      top->ser_rx = line->rx_bit(cycle);
    }
    tick();
    if (line) line->tx_sample(top->ser_tx, cycle);
    if (top->rvfi_valid) {
      ++retired;
      Retirement r;
      r.pc = top->rvfi_pc_rdata;
      r.insn = top->rvfi_insn;
      r.rd = top->rvfi_rd_addr;
      r.rd_value = top->rvfi_rd_wdata;
      r.mem_addr = top->rvfi_mem_addr;
      r.mem_rmask = top->rvfi_mem_rmask;
      r.mem_wmask = top->rvfi_mem_wmask;
      r.mem_rdata = top->rvfi_mem_rdata;
      r.mem_wdata = top->rvfi_mem_wdata;
      if (r.rd) shadow[r.rd] = r.rd_value;
      if (line && r.mem_rmask && r.mem_addr - map.uart_base < uart_size) line->open();
      if (r.insn == 0x00000073 && map.halt == HaltKind::Ecall && shadow[17] == kEcallExit)
        stop(static_cast<int>(shadow[10] & 0xff), "");
      if (stub_retire) --stub_retire;
      else if (lockstep && !lockstep->check(r, cycle)) {
        std::fputs(lockstep->report().c_str(), stderr);
        status = kDiverged;
        stop_msg = "lock-step divergence";
        break;
      }
    }
    tock();
  }
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  uart.flush();
  if (line) line->flush();
  if (fst) fst->close();
  top->final();
  if (o.pty) drain_uart_pty(in_fd, 2000);

  if (!stop_msg.empty() && status != kDiverged) std::fprintf(stderr, "minrt-rtl: %s\n", stop_msg.c_str());
  if (!o.quiet) {
    const double cpi = retired ? static_cast<double>(cycle) / static_cast<double>(retired) : 0;
    std::fprintf(stderr,
                 "minrt-rtl: %llu cycles, %llu instructions retired, CPI %.3f, %.2f s wall, %.2f s CPU, "
                 "%.2f MHz simulated",
                 static_cast<unsigned long long>(cycle), static_cast<unsigned long long>(retired), cpi, secs, cpu,
                 cpu > 0 ? static_cast<double>(cycle) / cpu / 1e6 : 0.0);
    if (lockstep)
      std::fprintf(stderr, ", lock-step: %llu checked, %llu float results adopted",
                   static_cast<unsigned long long>(lockstep->checked()),
                   static_cast<unsigned long long>(lockstep->fp_adopted()));
    if (line && top->ser_overruns) std::fprintf(stderr, ", %u bytes lost to UART overrun", top->ser_overruns);
    if (line && line->framing_errors())
      std::fprintf(stderr, ", %llu framing errors", static_cast<unsigned long long>(line->framing_errors()));
    std::fputc('\n', stderr);
  }
  return status;
}
