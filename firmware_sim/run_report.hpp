// End-of-run reporting: the stop message on stderr and the --stats block.
#pragma once
#include <cstdint>
#include <cstdio>
#include <string>

#include "cycle_model.hpp"
#include "profiler.hpp"
#include "stop_reason.hpp"
#include "symbols.hpp"

namespace fwsim {

// "firmware-sim: illegal instruction at pc 0x80000010 (main+0x8): <insn> ..."
std::string describe_stop(const StopInfo& s, uint32_t insn_word, const SymbolTable& syms,
                          uint64_t instret);

struct RunSummary {
  uint64_t instructions, cycles;
  double wall_us;
  double cpu_us;
  const CycleModel* model;  // null in plain mode
  const CycleModelConfig& model_cfg;
  std::string model_name;
  uint64_t uart_out, uart_in, baud;
  const Profiler* profiler;
  std::string fpu_model;  // describe(FpuModelConfig)
  bool jit;               // generated code was allowed (Machine::set_jit)
  uint64_t jit_blocks;    // blocks it translated
};

// First three lines are the contract: instructions, cycles, host MIPS.
void print_stats(const RunSummary& s, std::FILE* out);

}  // namespace fwsim
