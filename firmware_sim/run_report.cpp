#include "run_report.hpp"

#include <algorithm>

#include "disassembler.hpp"

namespace fwsim {

std::string describe_stop(const StopInfo& s, uint32_t word, const SymbolTable& syms, uint64_t instret) {
  char buf[512];
  const bool has_addr = s.cause == StopCause::LoadFault || s.cause == StopCause::StoreFault ||
                        s.cause == StopCause::MisalignedLoad || s.cause == StopCause::MisalignedStore ||
                        s.cause == StopCause::FetchFault || s.cause == StopCause::MisalignedFetch;
  std::string where = syms.describe(s.pc);
  std::string insn = word ? disassemble(word, s.pc) : std::string("(no instruction)");
  if (word && (word & 3) != 3) {
    // Outside the ISA: the encoding alone; otherwise its expansion too.
    if (s.cause == StopCause::OutsideIsa) std::snprintf(buf, sizeof buf, "compressed instruction 0x%04x", word & 0xffff);
    else std::snprintf(buf, sizeof buf, "compressed instruction 0x%04x (%s)", word & 0xffff, insn.c_str());
    insn = buf;
  }
  std::snprintf(buf, sizeof buf, "%s at pc 0x%08x (%s): %s", describe(s.cause), s.pc,
                where.c_str(), insn.c_str());
  std::string msg = buf;
  if (s.detail) msg += std::string(": needs ") + s.detail;
  if (has_addr) {
    std::snprintf(buf, sizeof buf, ", address 0x%08x", s.addr);
    msg += buf;
  }
  std::snprintf(buf, sizeof buf, " [after %llu instructions, exit status %d]",
                static_cast<unsigned long long>(instret), exit_status(s));
  return msg + buf;
}

void print_stats(const RunSummary& s, std::FILE* out) {
  std::fprintf(out, "instructions: %llu\n", static_cast<unsigned long long>(s.instructions));
  std::fprintf(out, "cycles: %llu\n", static_cast<unsigned long long>(s.cycles));
  std::fprintf(out, "host MIPS: %.1f\n", s.wall_us > 0 ? s.instructions / s.wall_us : 0.0);
  std::fprintf(out, "host CPU MIPS: %.1f (per CPU-second of the simulator process)\n",
               s.cpu_us > 0 ? s.instructions / s.cpu_us : 0.0);
  std::fprintf(out, "cycle model: %s%s\n", s.model_name.c_str(),
               s.model ? "" : " (1 cycle per instruction; use --cycle-model for timing)");
  std::fprintf(out, "fpu model: %s\n", s.fpu_model.c_str());
  // Only plain runs with the IEEE FPU use generated code.
  if (!s.jit) std::fprintf(out, "jit: off (--no-jit)\n");
  else std::fprintf(out, "jit: %llu blocks translated\n", static_cast<unsigned long long>(s.jit_blocks));
  const double hz = static_cast<double>(s.model_cfg.clock_hz);
  std::fprintf(out, "CPI: %.3f\n", s.instructions ? static_cast<double>(s.cycles) / s.instructions : 0.0);
  const double cpu_s = s.cycles / hz;
  std::fprintf(out, "clock: %.0f Hz, simulated time: %.6f s\n", hz, cpu_s);
  std::fprintf(out, "uart: %llu bytes out, %llu bytes in\n", static_cast<unsigned long long>(s.uart_out),
               static_cast<unsigned long long>(s.uart_in));
  const uint64_t baud = s.baud ? s.baud : 115200;
  const double uart_s = (s.uart_out + s.uart_in) * 10.0 / static_cast<double>(baud);
  if (s.baud) {
    // Paced: the firmware already waited for the UART inside the cycle count.
    std::fprintf(out, "board time: %.6f s (UART paced at %llu baud, transfer time %.6f s included)\n",
                 cpu_s, static_cast<unsigned long long>(baud), uart_s);
  } else {
    std::fprintf(out, "board time: %.6f s (compute %.6f s + UART %.6f s at %llu baud, not overlapped)\n",
                 cpu_s + uart_s, cpu_s, uart_s, static_cast<unsigned long long>(baud));
  }
  if (!s.model) return;
  std::fprintf(out, "instruction mix:");
  uint64_t per_class[static_cast<size_t>(InsnClass::Count)] = {};
  for (size_t op = 0; op < static_cast<size_t>(Op::Count); ++op)
    per_class[static_cast<size_t>(kOpInfo[op].cls)] += s.model->op_count(static_cast<Op>(op));
  for (size_t c = 0; c < static_cast<size_t>(InsnClass::Count); ++c) {
    if (per_class[c])
      std::fprintf(out, " %s=%llu", class_name(static_cast<InsnClass>(c)),
                   static_cast<unsigned long long>(per_class[c]));
  }
  std::fprintf(out, "\nbranches: %llu, mispredicted: %llu (%s), load-use stalls: %llu\n",
               static_cast<unsigned long long>(s.model->branches()),
               static_cast<unsigned long long>(s.model->mispredicts()), predictor_name(s.model_cfg.predictor),
               static_cast<unsigned long long>(s.model->load_use_stalls()));
  auto cache_line = [&](const char* name, const CacheModel& c) {
    if (c.enabled())
      std::fprintf(out, "%s: %llu accesses, %llu misses\n", name, static_cast<unsigned long long>(c.accesses()),
                   static_cast<unsigned long long>(c.misses()));
  };
  cache_line("icache", s.model->icache());
  cache_line("dcache", s.model->dcache());
  if (!s.profiler) return;
  auto totals = s.profiler->function_totals();
  std::sort(totals.begin(), totals.end(),
            [](const auto& a, const auto& b) { return a.self.cycles > b.self.cycles; });
  // Names last: demangled C++ names are long.
  std::fprintf(out, "top functions:\n  %12s %12s %12s %8s  %s\n", "self cycles", "self instr", "incl cycles", "calls",
               "function");
  for (size_t i = 0; i < totals.size() && i < 10 && totals[i].self.cycles; ++i) {
    std::fprintf(out, "  %12llu %12llu %12llu %8llu  %s\n", static_cast<unsigned long long>(totals[i].self.cycles),
                 static_cast<unsigned long long>(totals[i].self.ir),
                 static_cast<unsigned long long>(totals[i].inclusive.cycles),
                 static_cast<unsigned long long>(totals[i].calls), totals[i].name.c_str());
  }
}

}  // namespace fwsim
