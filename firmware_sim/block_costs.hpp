// Pre-computed per-instruction costs for the timed interpreter when the
// cycle model needs no per-access state (no caches, no trace): each decoded
// entry gets a slot holding its latency plus the load-use stall it suffers
// after the entry before it, so the hot loop adds one number per
// instruction. Straight-line runs are counted at their ends (enters at
// jump targets, leaves at taken jumps) and turned into per-op execution
// counts and stall counts afterwards (fold), as the per-instruction model
// would have counted them.
#pragma once
#include <cstdint>

#include "cycle_model.hpp"
#include "decode_cache.hpp"

namespace fwsim {

struct CostSlot {
  uint32_t cost;       // latency + stall (+ a branch's not-taken cycles, static_branches())
  uint16_t stall;      // load-use stall cycles included in cost (not charged when entered by a jump)
  uint8_t stalls;      // 1 when the entry suffers a load-use stall after its predecessor
  int8_t taken;        // a branch's taken cycles minus its not-taken cycles (static_branches())
};
static_assert(sizeof(CostSlot) == sizeof(Entry), "slots parallel the entries, same stride");

class BlockCosts {
 public:
  BlockCosts() = default;
  ~BlockCosts();
  BlockCosts(const BlockCosts&) = delete;
  BlockCosts& operator=(const BlockCosts&) = delete;

  // Computes every slot for `code` under `model` (allocating on first use).
  void build(DecodeCache& code, const CycleModel& model);
  // Entry `index` was (re)decoded: its slot and its successor's change.
  void update(DecodeCache& code, const CycleModel& model, uint32_t index);
  // Adds the counted runs to the model's op and stall counts (and with
  // static_branches() its branch and misprediction counts), then clears
  // them. `code_mem` decodes entries no longer decoded (debugger changes);
  // `last` is the entry the final run ended at (its leave is not a taken
  // jump), kNoEntry when none.
  static constexpr uint32_t kNoEntry = UINT32_MAX;
  void fold(DecodeCache& code, const uint8_t* code_mem, CycleModel& model, uint32_t last);
  // The slots include conditional branches' cycles: the model's predictor
  // is static and the taken/not-taken difference fits CostSlot::taken. The
  // loop then adds `taken` on a taken branch instead of calling the model.
  bool static_branches() const { return static_branches_; }

  CostSlot* slots() { return slots_; }
  uint64_t* enters() { return enters_; }
  uint64_t* leaves() { return leaves_; }
  const CycleModel* built_for() const { return model_; }

 private:
  void set(DecodeCache& code, const CycleModel& model, uint32_t index);

  const CycleModel* model_ = nullptr;
  bool static_branches_ = false;
  uint32_t span_lo_ = UINT32_MAX, span_hi_ = 0;  // entries set() has visited
  uint32_t count_ = 0;
  CostSlot* slots_ = nullptr;
  uint64_t* enters_ = nullptr;
  uint64_t* leaves_ = nullptr;
};

}  // namespace fwsim
