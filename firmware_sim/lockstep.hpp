// Lock-step checking of a CPU against the simulator: the CPU under test
// reports each instruction it retires (a subset of RVFI, the RISC-V Formal
// Interface: pc, instruction, register written, memory access), and the
// checker steps its own Machine one instruction and compares. Loads from
// device regions take the CPU's value; float results may differ from the
// exact ones within an FPU specification and are then adopted, so a CPU
// with an approximate FPU can be checked instruction by instruction.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "machine.hpp"
#include "symbols.hpp"

namespace fwsim {

// One retired instruction. Memory fields as on the harness's data port:
// mem_addr word-aligned, masks and data in byte lanes (bit 8*i = byte
// mem_addr + i). rd = 0 when no integer register is written; for an
// instruction writing a float register, rd/rd_value are that register's.
struct Retirement {
  uint32_t pc = 0, insn = 0;
  uint8_t rd = 0;
  uint32_t rd_value = 0;
  uint32_t mem_addr = 0;
  uint8_t mem_rmask = 0, mem_wmask = 0;
  uint32_t mem_rdata = 0, mem_wdata = 0;
};

// Largest relative error accepted per float operation; 0 = bit-exact.
// The defaults are the course's FPU specification.
struct FpuSpec {
  double add = 0x1p-23;   // fadd.s, fsub.s
  double mul = 0x1p-22;   // fmul.s
  double div = 0x1p-20;   // fdiv.s
  double sqrt = 0x1p-20;  // fsqrt.s
};
// "add=2^-23,mul=1e-6,div=0,sqrt=2^-20" (any subset; 2^-N or a decimal).
// Throws std::runtime_error naming the bad item.
FpuSpec parse_fpu_spec(const std::string& text);

// Runs exactly one instruction of `m` and describes it. `stop` receives the
// run's stop (cause None/Breakpoint after a normal step). The machine must
// have its generated code disabled (set_jit(false)).
Retirement step_one(Machine& m, StopInfo& stop);

class Lockstep {
 public:
  // `ref` starts at the same pc, registers and memory as the CPU.
  Lockstep(Machine& ref, const SymbolTable* symbols, size_t history, const FpuSpec& spec)
      : ref_(ref), symbols_(symbols), history_(history), spec_(spec) {}

  // Compares one retirement; false at the first divergence (report() then
  // says what differs). `cycle` is the CPU's cycle, for the report.
  bool check(const Retirement& dut, uint64_t cycle);
  // The reference stopped (halt, fault) where the CPU went on.
  bool reference_stopped() const { return ref_stopped_; }
  uint64_t checked() const { return checked_; }
  uint64_t fp_adopted() const { return fp_adopted_; }
  // The divergence: cycle, pc, disassembly, enclosing function, expected
  // and actual, then the last `history` retired instructions.
  const std::string& report() const { return report_; }

 private:
  struct Past {
    uint64_t cycle;
    Retirement r;
  };
  std::string where(uint32_t pc) const;
  std::string line(const Retirement& r) const;
  void diverge(const Retirement& dut, const Retirement& exp, uint64_t cycle, const std::string& what,
               const std::string& expected, const std::string& actual);

  Machine& ref_;
  const SymbolTable* symbols_;
  size_t history_;
  FpuSpec spec_;
  std::vector<Past> past_;  // ring of the last `history_`
  size_t next_ = 0;
  uint64_t checked_ = 0, fp_adopted_ = 0;
  bool ref_stopped_ = false;
  std::string report_;
};

}  // namespace fwsim
