// Cycle model: per-class latencies, load-use stall, branch prediction and
// optional caches, configured by a `key = value` file (docs/firmware_sim.md,
// models/default.cfg). Only the interpreter's timed loop calls into it.
#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "branch_predictor.hpp"
#include "cache_model.hpp"
#include "decode_cache.hpp"
#include "isa_table.hpp"

namespace fwsim {

struct CycleModelConfig {
  uint64_t clock_hz = 100'000'000;
  std::array<uint32_t, static_cast<size_t>(InsnClass::Count)> latency{};
  uint32_t branch_taken = 1, branch_not_taken = 1, mispredict_penalty = 0, load_use_stall = 0;
  PredictorKind predictor = PredictorKind::StaticNotTaken;
  unsigned predictor_bits = 10;
  CacheConfig icache, dcache;
};

// Parses a model; keys not given keep the compiled-in default model's value.
// Throws std::runtime_error("origin:line: reason") on bad input.
CycleModelConfig parse_cycle_model(const std::string& text, const std::string& origin);
CycleModelConfig default_cycle_model();
const char* default_cycle_model_text();  // models/default.cfg, embedded at build time

class CycleModel {
 public:
  explicit CycleModel(const CycleModelConfig& cfg);
  const CycleModelConfig& config() const { return cfg_; }

  // Cycle count; the interpreter keeps a local copy while running and
  // passes it to the hooks below (so it can live in a register).
  uint64_t cycles = 0;

  // Called once per executed instruction.
  __attribute__((always_inline)) void instruction(const Entry& e, uint32_t pc, uint64_t& cycles) {
    const OpTiming& t = op_timing_[e.op];
    ++op_count_[e.op];
    cycles += t.latency;
    if (pending_load_ != kNoReg) [[unlikely]] {
      if (reads(e, t.uses, pending_load_)) {
        cycles += cfg_.load_use_stall;
        ++load_use_stalls_;
      }
      pending_load_ = kNoReg;
    }
    if (t.load_dest) [[unlikely]]
      pending_load_ = t.load_dest == 1 ? (e.rd == 32 ? kNoReg : e.rd) : static_cast<uint8_t>(32 + e.rd);
    if (icache_on_) {
      const uint32_t line = pc >> icache_.line_shift();
      if (line != last_fetch_line_) {
        last_fetch_line_ = line;
        if (!icache_.access(pc)) cycles += cfg_.icache.miss_penalty;
      }
    }
  }
  __attribute__((always_inline)) void branch(uint32_t pc, bool taken, bool backward, uint64_t& cycles) {
    ++branches_;
    cycles += taken ? cfg_.branch_taken : cfg_.branch_not_taken;
    if (!predictor_.resolve(pc, taken, backward)) {
      ++mispredicts_;
      cycles += cfg_.mispredict_penalty;
    }
  }
  __attribute__((always_inline)) void data(uint32_t addr, uint64_t& cycles) {
    if (dcache_.enabled() && !dcache_.access(addr)) cycles += cfg_.dcache.miss_penalty;
  }

  // For the block-costed timed loop (block_costs.hpp), which adds a
  // pre-computed cost per instruction instead of calling instruction():
  // whether it may run (no cache to consult per access), an instruction's
  // fixed latency, the load-use stall `next` suffers right after `prev`, and
  // the executions and stalls it counted, added afterwards.
  bool per_access_state() const { return icache_on_ || dcache_.enabled(); }
  uint32_t latency(const Entry& e) const { return op_timing_[e.op].latency; }
  bool load_use(const Entry& prev, const Entry& next) const {
    const OpTiming& t = op_timing_[prev.op];
    if (!t.load_dest) return false;
    const uint8_t r = t.load_dest == 1 ? (prev.rd == 32 ? kNoReg : prev.rd) : static_cast<uint8_t>(32 + prev.rd);
    return r != kNoReg && reads(next, op_timing_[next.op].uses, r);
  }
  uint32_t load_use_stall() const { return cfg_.load_use_stall; }
  void add_executions(uint8_t op, uint64_t n) { op_count_[op] += n; }
  // With a static predictor a conditional branch's cycles depend only on
  // its outcome and direction, so the block-costed loop charges them from
  // pre-computed slots and the branch and misprediction counts are added
  // afterwards from the per-entry execution and taken counts.
  bool static_predictor() const {
    return cfg_.predictor == PredictorKind::StaticNotTaken || cfg_.predictor == PredictorKind::BackwardTaken;
  }
  bool mispredicted(bool taken, bool backward) const {
    const bool predicted_taken = cfg_.predictor == PredictorKind::BackwardTaken && backward;
    return taken != predicted_taken;
  }
  uint64_t branch_cycles(bool taken, bool backward) const {
    return uint64_t{taken ? cfg_.branch_taken : cfg_.branch_not_taken} +
           (mispredicted(taken, backward) ? cfg_.mispredict_penalty : 0);
  }
  void add_branches(uint64_t n, uint64_t mispredicted) {
    branches_ += n;
    mispredicts_ += mispredicted;
  }
  void add_load_use_stalls(uint64_t n) { load_use_stalls_ += n; }

  uint64_t op_count(Op op) const { return op_count_[static_cast<size_t>(op)]; }
  uint64_t branches() const { return branches_; }
  uint64_t mispredicts() const { return mispredicts_; }
  uint64_t load_use_stalls() const { return load_use_stalls_; }
  const CacheModel& icache() const { return icache_; }
  const CacheModel& dcache() const { return dcache_; }

 private:
  static constexpr uint8_t kNoReg = 0xff;
  // Whether e reads unified register r (0..31 = x, 32..63 = f).
  static bool reads(const Entry& e, uint8_t u, uint8_t r) {
    return ((u & 1) && e.rs1 == r) || ((u & 2) && 32u + e.rs1 == r) || ((u & 4) && e.rs2 == r) ||
           ((u & 8) && 32u + e.rs2 == r) || ((u & 16) && 32u + entry_rs3(e) == r);
  }

  CycleModelConfig cfg_;
  struct OpTiming {
    uint32_t latency;
    uint8_t uses;       // operand-read mask, see reads()
    uint8_t load_dest;  // 1 = integer load, 2 = FP load
  };
  std::array<OpTiming, 256> op_timing_{};
  bool icache_on_;
  std::array<uint64_t, 256> op_count_{};
  uint8_t pending_load_ = kNoReg;
  uint32_t last_fetch_line_ = ~0u;
  BranchPredictor predictor_;
  CacheModel icache_, dcache_;
  uint64_t branches_ = 0, mispredicts_ = 0, load_use_stalls_ = 0;
};

}  // namespace fwsim
