#include "block_costs.hpp"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>

namespace fwsim {
namespace {
template <typename T>
T* zeroed(uint32_t n) {
  // calloc: pages of code memory that never run are never touched.
  T* p = static_cast<T*>(std::calloc(n, sizeof(T)));
  if (!p) throw std::bad_alloc();
  return p;
}
// A decoded word's conditional-branch direction as the interpreter runs it
// (DecodeCache::fill): false for a branch that is not one there (a target
// off the word grid or outside code memory, or the board's jump-to-itself
// halt), which calls the model itself.
bool runs_as_branch(const DecodeCache& code, uint32_t index, const DecodedInsn& d, bool& backward) {
  if (op_info(d.op).cls != InsnClass::Branch) return false;
  const int64_t target = int64_t{index} + d.imm / 4;
  if ((d.imm & 3) || target < 0 || target >= code.count()) return false;
  if (code.self_jump_halts() && d.imm == 0) return false;
  backward = d.imm < 0;
  return true;
}
}  // namespace

BlockCosts::~BlockCosts() {
  std::free(slots_);
  std::free(enters_);
  std::free(leaves_);
}

void BlockCosts::set(DecodeCache& code, const CycleModel& model, uint32_t index) {
  const Entry* e = code.entries();
  CostSlot& s = slots_[index];
  // The sentinel past the end of code memory never retires (no counts).
  if (index + 1 < count_) {
    if (index < span_lo_) span_lo_ = index;
    if (index > span_hi_) span_hi_ = index;
  }
  const bool stall = index > 0 && e[index - 1].op != 0 && model.load_use(e[index - 1], e[index]);
  s.stall = static_cast<uint16_t>(stall ? model.load_use_stall() : 0);
  s.stalls = stall;
  s.cost = model.latency(e[index]) + s.stall;
  s.taken = 0;
  if (static_branches_ && op_info(static_cast<Op>(e[index].op)).cls == InsnClass::Branch) {
    const bool backward = e[index].imm < 0;
    const uint64_t not_taken = model.branch_cycles(false, backward);
    s.cost += static_cast<uint32_t>(not_taken);
    s.taken = static_cast<int8_t>(static_cast<int64_t>(model.branch_cycles(true, backward)) -
                                  static_cast<int64_t>(not_taken));
  }
}



void BlockCosts::build(DecodeCache& code, const CycleModel& model) {
  if (!slots_) {
    count_ = code.count() + 1;  // with the sentinel
    slots_ = zeroed<CostSlot>(count_);
    enters_ = zeroed<uint64_t>(count_);
    leaves_ = zeroed<uint64_t>(count_);
  }
  model_ = &model;
  static_branches_ = false;
  if (model.static_predictor()) {
    bool fits = true;
    for (const bool backward : {false, true}) {
      const int64_t delta = static_cast<int64_t>(model.branch_cycles(true, backward)) -
                            static_cast<int64_t>(model.branch_cycles(false, backward));
      fits = fits && delta >= INT8_MIN && delta <= INT8_MAX && model.branch_cycles(false, backward) <= UINT16_MAX;
    }
    static_branches_ = fits;
  }
  const Entry* e = code.entries();
  for (uint32_t i = 0; i < count_; ++i)
    if (e[i].op != 0 || slots_[i].cost) set(code, model, i);
}

void BlockCosts::update(DecodeCache& code, const CycleModel& model, uint32_t index) {
  set(code, model, index);
  if (index + 1 < count_) set(code, model, index + 1);
}

void BlockCosts::fold(DecodeCache& code, const uint8_t* code_mem, CycleModel& model, uint32_t last) {
  const Entry* e = code.entries();
  uint64_t running = 0, stalls = 0, branches = 0, mispredicts = 0;
  // Runs start and end only at entries that were decoded, so have slots.
  for (uint32_t i = span_lo_; i <= span_hi_ && i < count_; ++i) {
    if (!enters_[i] && !running) continue;
    running += enters_[i];
    if (running) {
      uint8_t op = e[i].op;
      bool branch = false, backward = false;
      if (op == static_cast<uint8_t>(Op::UNDECODED) || op == static_cast<uint8_t>(Op::BREAKPOINT)) {
        uint32_t word;
        std::memcpy(&word, code_mem + 4 * uint64_t{i}, 4);
        const DecodedInsn d = decode(word);
        op = static_cast<uint8_t>(d.op);
        branch = runs_as_branch(code, i, d, backward);
      } else {
        branch = op_info(static_cast<Op>(op)).cls == InsnClass::Branch;
        backward = e[i].imm < 0;
      }
      model.add_executions(op, running);
      if (static_branches_ && branch) {
        // Every leave of a branch is a taken branch, except the final run's end.
        const uint64_t taken = leaves_[i] - (i == last ? 1 : 0);
        branches += running;
        mispredicts += (model.mispredicted(true, backward) ? taken : 0) +
                       (model.mispredicted(false, backward) ? running - taken : 0);
      }
      // Entered by a jump, the entry did not stall.
      if (slots_[i].stalls) stalls += running - enters_[i];
    }
    running -= leaves_[i];
    enters_[i] = leaves_[i] = 0;
  }
  model.add_load_use_stalls(stalls);
  model.add_branches(branches, mispredicts);
}

}  // namespace fwsim
