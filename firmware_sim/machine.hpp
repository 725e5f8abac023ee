// One RV32IMF hart with its RAM, devices and pre-decoded code; runs the
// interpreter (interpreter.cpp) in a plain or a timed variant.
#pragma once
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <vector>

#include "bus.hpp"
#include "csr.hpp"
#include "cycle_model.hpp"
#include "block_costs.hpp"
#include "block_jit.hpp"
#include "decode_cache.hpp"
#include "hart_state.hpp"
#include "profiler.hpp"
#include "stop_reason.hpp"

namespace fwsim {

class FpuApprox;

class Machine {
 public:
  explicit Machine(const MemoryMap& map) : bus_(map), code_(bus_.code_size()) {
    code_.set_ram_base(bus_.ram_base());
    if (map.halt == HaltKind::Loop) code_.configure(kReferenceIsa, true);
  }
  explicit Machine(uint32_t ram_size) : Machine(map_with_ram(ram_size)) {}

  Bus& bus() { return bus_; }
  HartState& hart() { return hart_; }
  CsrFile& csr() { return csr_; }
  // The board's instruction set: instructions outside it stop the run with
  // StopCause::OutsideIsa. Call before running.
  void set_isa(const IsaSpec& isa) { code_.configure(isa, bus_.map().halt == HaltKind::Loop); }
  // The board has the C extension: instructions at any halfword.
  bool compressed() const { return code_.compressed(); }

  // With a model (and optionally a profiler or a trace stream) the timed
  // variant runs; without, the plain one, which counts instructions only.
  void set_cycle_model(CycleModel* m) {
    model_ = m;
    if (m) csr_.set_clock_hz(m->config().clock_hz);
  }
  void set_profiler(Profiler* p) { profiler_ = p; }
  // `spike` = spike's commit-log layout (--commit-log) instead of --trace's.
  void set_trace(std::FILE* out, bool spike = false) {
    trace_ = out;
    spike_trace_ = spike;
  }
  // Null (the default) = exact IEEE arithmetic; otherwise the model's
  // arithmetic for the ops it replaces (fpu_approx.hpp).
  void set_fpu_model(const FpuApprox* m) { fpu_model_ = m; }
  // Plain runs, and timed runs without caches, trace or watchpoints,
  // translate hot code to host code (block_jit.hpp) unless disabled; counts, cycles, statistics, profiles, output and stops are
  // the same either way.
  void set_jit(bool on) { jit_enabled_ = on; }
  bool jit_enabled() const { return jit_enabled_; }
  uint64_t jit_blocks() const {
    return (jit_ ? jit_->blocks_made() : 0) + (timed_jit_ ? timed_jit_->blocks_made() : 0);
  }

  // Debugger support (gdb_stub.hpp). A breakpoint stops a run with
  // StopCause::Breakpoint before the instruction at `pc` executes; false when
  // `pc` is not a word of code memory. Code written from outside (a debugger's memory
  // write) must be invalidated to be decoded again.
  bool set_breakpoint(uint32_t pc) {
    const uint32_t unit = 1u << code_.shift();
    if (!bus_.in_code(pc, unit) || (pc & (unit - 1))) return false;
    code_.set_breakpoint((pc - bus_.code_base()) >> code_.shift());
    return true;
  }
  void clear_breakpoint(uint32_t pc) { invalidate_code(pc, 1u << code_.shift()); }
  void invalidate_code(uint32_t addr, uint32_t len) {
    const uint32_t base = bus_.code_base(), size = bus_.code_size();
    uint32_t lo = addr, n = len;
    if (lo - base >= size) {  // starts below or above code memory
      if (addr < base && uint64_t{addr} + len > base) {
        n = static_cast<uint32_t>(uint64_t{addr} + len - base);
        lo = base;
      } else {
        return;
      }
    }
    code_.invalidate_bytes(lo - base, n);
  }

  // Debugger watchpoints: a load (kind 3), store (2) or either (4)
  // touching [addr, addr + len) stops the run with StopCause::Watchpoint
  // after that instruction. While any is set, runs take the timed loop with
  // per-access hooks.
  void add_watchpoint(uint32_t addr, uint32_t len, uint8_t kind) { watches_.push_back({addr, len, kind}); }
  void clear_watchpoints() { watches_.clear(); }
  bool remove_watchpoint(uint32_t addr, uint32_t len, uint8_t kind) {
    for (size_t i = 0; i < watches_.size(); ++i)
      if (watches_[i].addr == addr && watches_[i].len == len && watches_[i].kind == kind) {
        watches_.erase(watches_.begin() + static_cast<long>(i));
        return true;
      }
    return false;
  }

  // Runs from hart().pc until the firmware stops, faults, or more than
  // `max_instructions` (total, counted from reset) have retired.
  StopInfo run(uint64_t max_instructions = std::numeric_limits<uint64_t>::max());

 private:
  // 0 plain, 1 timed with block costs (and generated code for hot runs
  // unless disabled), 2 timed with per-instruction hooks, 3 plain with
  // generated code for hot runs
  template <int Mode>
  StopInfo run_loop(uint64_t max_instructions);
  void trace_instruction(uint32_t pc);
  // The instruction at `pc` in code memory: 16 bits (zero-extended) when
  // compressed on a board with C, else 32.
  uint32_t instruction_at(uint32_t pc);
  // The kind of the first watchpoint an access hits, or 0.
  uint8_t watch_hit(uint32_t addr, uint32_t size, bool store) const {
    for (const Watch& w : watches_)
      if (addr - w.addr < w.len || w.addr - addr < size)
        if (w.kind == 4 || (w.kind == 2) == store) return w.kind;
    return 0;
  }
  struct Watch {
    uint32_t addr, len;
    uint8_t kind;
  };
  std::vector<Watch> watches_;

  Bus bus_;
  HartState hart_;
  CsrFile csr_;
  DecodeCache code_;
  BlockCosts costs_;
  uint32_t resume_pc_ = ~0u;  // where the last timed run stopped after straight-line code
  CycleModel* model_ = nullptr;
  Profiler* profiler_ = nullptr;
  std::FILE* trace_ = nullptr;
  bool spike_trace_ = false;
  const FpuApprox* fpu_model_ = nullptr;
  bool jit_enabled_ = true;
  std::unique_ptr<BlockJit> jit_;  // made on the first run that uses it
  std::unique_ptr<BlockJit> timed_jit_;  // the same for the block-costed timed loop
};

}  // namespace fwsim
