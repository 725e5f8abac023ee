// Generated x86-64 code for hot straight-line runs of the plain interpreter
// and of the block-costed timed one (BlockCosts: a cycle model without
// caches). A run entered by a taken jump often enough is translated from
// its decoded entries (never from memory, so stores to code and fence.i
// behave exactly as in the interpreter); its code reads and writes the guest
// register file directly, keeps the instruction count in a host register and
// jumps from block to block through the per-entry table without returning.
// Anything it does not translate (devices, misaligned or out-of-RAM
// accesses, CSRs, rounding modes other than RNE, ...) leaves to the
// interpreter before that instruction. Timed blocks add the cost slots of
// their instructions as constants, count straight-line runs in BlockCosts'
// enters/leaves exactly where the interpreter does, and call helpers for the
// profiler's calls and returns and for a dynamic branch predictor. Other
// hosts get no blocks (available() is false) and the interpreter runs
// everything.
#pragma once
#include <cstddef>
#include <cstdint>

#include "block_costs.hpp"
#include "decode_cache.hpp"

namespace fwsim {

class CycleModel;
class Profiler;

class BlockJit {
 public:
  // Per-entry table values below kCompiled are hotness counts; kNoBlock
  // marks a run that cannot be translated; larger values are code addresses.
  static constexpr uintptr_t kHot = 16;
  static constexpr uintptr_t kNoBlock = kHot + 1;
  static constexpr uintptr_t kCompiled = kNoBlock + 1;

  // How generated code handed control back.
  enum class Exit : uint32_t {
    Target = 0,  // at a jump target or fall-through not translated yet
    Here = 1,    // before an instruction the interpreter must run
    Limit = 2,   // a taken jump went past the instruction limit
  };
  // Shared with the generated code (fixed offsets, see block_jit.cpp).
  struct State {
    uint32_t* x;        // x[0..32] then f[0..31] (HartState layout)
    uint8_t* ram;
    uintptr_t* table;
    uint64_t count;     // instructions retired since the run started
    uint64_t limit;     // a taken jump with count > limit stops
    uint32_t exit;      // Exit
    // Timed blocks only:
    uint32_t run_start;  // entry the last taken jump entered (the current run's start)
    uint64_t cycles;     // the cycle count
    uint64_t ir_base;    // instructions retired before `count` started (profile costs)
    Profiler* profiler;  // with Timing::profile
  };
  // What timed blocks update: BlockCosts' arrays (which must not move while
  // the translator exists), with `profile` State::profiler, and with
  // `predictor` (a model whose branch cycles are not in the slots, see
  // BlockCosts::static_branches()) that model's branch().
  struct Timing {
    const CostSlot* slots;
    uint64_t* enters;
    uint64_t* leaves;
    bool profile;
    CycleModel* predictor;
    bool operator==(const Timing&) const = default;
  };

  // Without `timing`, plain blocks; with it, timed ones. `shift`: log2 of
  // the code bytes per entry (DecodeCache::shift()).
  BlockJit(uint32_t entry_count, uint32_t code_base, uint32_t ram_size, const Timing* timing = nullptr,
           unsigned shift = 2);
  ~BlockJit();
  BlockJit(const BlockJit&) = delete;
  BlockJit& operator=(const BlockJit&) = delete;

  // False on hosts without a code generator or when executable memory
  // could not be mapped.
  bool available() const { return code_ != nullptr; }
  uintptr_t* table() { return table_; }
  // Translates the run starting at entry `index`; returns the table value
  // stored for it (a code address, or kNoBlock).
  uintptr_t compile(const Entry* entries, uint32_t index);
  // Runs generated code at `code` (a table value >= kCompiled) until it
  // exits; returns the entry index to continue at, st.exit says how.
  uint32_t run(State& st, uintptr_t code) { return enter_(&st, code); }
  // Drops every block (decoded entries changed); counts restart.
  void flush();
  // Drops the block starting at entry `index`, if any: its first
  // instruction's cost slot changed (the entry before it was decoded).
  void drop(uint32_t index) {
    if (table_ && table_[index] >= kNoBlock) table_[index] = 0;
  }
  bool timed() const { return timing_.slots != nullptr; }
  const Timing& timing() const { return timing_; }
  // DecodeCache::epoch() the blocks were made from.
  uint64_t epoch() const { return epoch_; }
  void set_epoch(uint64_t e) { epoch_ = e; }
  // Blocks translated so far (flushes included): for tests and statistics.
  uint64_t blocks_made() const { return blocks_made_; }
  void add_blocks_made(uint64_t n) { blocks_made_ += n; }

 private:
  using EnterFn = uint32_t (*)(State*, uintptr_t);
  uint32_t count_;
  uint32_t code_base_;
  uint32_t ram_size_;
  unsigned shift_;
  uintptr_t* table_ = nullptr;
  uint8_t* code_ = nullptr;
  size_t code_size_ = 0;
  size_t used_ = 0;
  size_t prologue_end_ = 0;  // start of the first block (after the entry/exit code)
  size_t exit_offsets_[3] = {};  // code setting State::exit to each Exit, then leaving
  EnterFn enter_ = nullptr;
  uint32_t touched_lo_ = UINT32_MAX, touched_hi_ = 0;
  uint64_t epoch_ = 0;
  uint64_t blocks_made_ = 0;
  Timing timing_{};
};

}  // namespace fwsim
