// minrt-lockstep-fpu: the lock-step checker (firmware_sim/lockstep.hpp)
// with firmware-sim's approximate FPU (fpu_approx.hpp, --fpu keys as in
// firmware-sim) playing the CPU under test and the exact simulator as the
// reference: shows what an RTL run with such an FPU reports, without RTL.
// Every float result inside the FPU specification is adopted; the first
// one outside it stops the run (status 9) with the lock-step report.
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "boot_args.hpp"
#include "elf_loader.hpp"
#include "fpu_approx.hpp"
#include "fpu_model_config.hpp"
#include "lockstep.hpp"
#include "machine.hpp"
#include "uart.hpp"

namespace {

using namespace fwsim;

[[noreturn]] void die(int status, const std::string& msg) {
  std::fprintf(stderr, "minrt-lockstep-fpu: %s\n", msg.c_str());
  std::exit(status);
}

const char* kUsage =
    "Usage: minrt-lockstep-fpu --fpu KEY=VALUE,... [--fpu-spec SPEC] [--history N]\n"
    "                          [--uart-in FILE] [--uart-out FILE] ELF [-- ARGS]\n"
    "Runs ELF (the reference board's firmware) twice in lock-step: with the FPU\n"
    "model --fpu describes (firmware-sim's keys) as the CPU under test, and with\n"
    "exact IEEE arithmetic as the reference. SPEC: add=,mul=,div=,sqrt= bounds on\n"
    "the relative error (default the course's: 2^-23, 2^-22, 2^-20, 2^-20).\n";

}  // namespace

int main(int argc, char** argv) {
  std::string fpu, spec_text, uart_in, uart_out, elf_path;
  std::vector<std::string> fw_args;
  size_t history = 16;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) die(2, a + " needs a value");
      return argv[++i];
    };
    if (a == "--") {
      for (++i; i < argc; ++i) fw_args.push_back(argv[i]);
    } else if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      return 0;
    } else if (a == "--fpu") fpu = value();
    else if (a == "--fpu-spec") spec_text = value();
    else if (a == "--history") history = std::strtoul(value().c_str(), nullptr, 10);
    else if (a == "--uart-in") uart_in = value();
    else if (a == "--uart-out") uart_out = value();
    else if (!a.empty() && a[0] == '-') die(2, "unknown option '" + a + "' (see --help)");
    else if (!elf_path.empty()) die(2, "more than one ELF");
    else elf_path = a;
  }
  if (elf_path.empty() || fpu.empty()) die(2, "needs --fpu KEY=VALUE,... and an ELF (see --help)");

  FpuModelConfig cfg;
  FpuSpec spec;
  try {
    apply_fpu_settings(cfg, fpu);
    if (!spec_text.empty()) spec = parse_fpu_spec(spec_text);
  } catch (const std::runtime_error& e) {
    die(2, e.what());
  }
  FpuApprox approx(cfg);

  const MemoryMap map;  // the reference board's
  Machine dut(map), ref(map);
  SymbolTable symbols;
  std::vector<std::string> args{elf_path};
  args.insert(args.end(), fw_args.begin(), fw_args.end());
  try {
    for (Machine* m : {&dut, &ref}) {
      LoadedElf elf = load_elf(elf_path, m->bus());
      m->hart().pc = elf.entry;
      if (m == &ref) symbols = std::move(elf.symbols);
      if (!fw_args.empty()) place_boot_args(m->bus(), m->hart(), args);
      m->set_jit(false);
    }
  } catch (const std::runtime_error& e) {
    die(3, e.what());
  }
  symbols.finalize();
  dut.set_fpu_model(&approx);

  Uart::Config dc;
  dc.layout = map.uart;
  dc.in_fd = uart_in.empty() ? 0 : ::open(uart_in.c_str(), O_RDONLY);
  dc.out_fd = uart_out.empty() ? 1 : ::open(uart_out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (dc.in_fd < 0 || dc.out_fd < 0) die(7, std::string("cannot open the UART files: ") + std::strerror(errno));
  Uart dut_uart(dc);
  dut.bus().attach_uart(&dut_uart);
  Uart::Config rc = dc;
  rc.in_fd = -1;
  rc.out_fd = ::open("/dev/null", O_WRONLY);
  Uart ref_uart(rc);
  ref.bus().attach_uart(&ref_uart);

  Lockstep ls(ref, &symbols, history, spec);
  for (;;) {
    StopInfo stop;
    const Retirement r = step_one(dut, stop);
    if (!ls.check(r, dut.hart().instret)) {
      std::fputs(ls.report().c_str(), stderr);
      return 9;
    }
    if (stop.cause != StopCause::None && stop.cause != StopCause::Breakpoint) {
      dut_uart.flush();
      std::fprintf(stderr, "minrt-lockstep-fpu: %s; %llu instructions checked, %llu float results adopted (%s)\n",
                   describe(stop.cause), static_cast<unsigned long long>(ls.checked()),
                   static_cast<unsigned long long>(ls.fp_adopted()), describe(cfg).c_str());
      return exit_status(stop);
    }
  }
}
