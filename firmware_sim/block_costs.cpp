#include "block_costs.hpp"

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
}  // namespace

BlockCosts::~BlockCosts() {
  std::free(slots_);
  std::free(enters_);
  std::free(leaves_);
}

void BlockCosts::set(DecodeCache& code, const CycleModel& model, uint32_t index) {
  const Entry* e = code.entries();
  CostSlot& s = slots_[index];
  const bool stall = index > 0 && e[index - 1].op != 0 && model.load_use(e[index - 1], e[index]);
  s.stall = static_cast<uint16_t>(stall ? model.load_use_stall() : 0);
  s.stalls = stall;
  s.cost = model.latency(e[index]) + s.stall;
}

void BlockCosts::build(DecodeCache& code, const CycleModel& model) {
  if (!slots_) {
    count_ = code.count() + 1;  // with the sentinel
    slots_ = zeroed<CostSlot>(count_);
    enters_ = zeroed<uint64_t>(count_);
    leaves_ = zeroed<uint64_t>(count_);
  }
  model_ = &model;
  const Entry* e = code.entries();
  for (uint32_t i = 0; i < count_; ++i)
    if (e[i].op != 0 || slots_[i].cost) set(code, model, i);
}

void BlockCosts::update(DecodeCache& code, const CycleModel& model, uint32_t index) {
  set(code, model, index);
  if (index + 1 < count_) set(code, model, index + 1);
}

void BlockCosts::fold(DecodeCache& code, const uint8_t* code_mem, CycleModel& model) {
  const Entry* e = code.entries();
  uint64_t running = 0, stalls = 0;
  for (uint32_t i = 0; i < count_; ++i) {
    if (!enters_[i] && !running) continue;
    running += enters_[i];
    if (running) {
      uint8_t op = e[i].op;
      if (op == static_cast<uint8_t>(Op::UNDECODED) || op == static_cast<uint8_t>(Op::BREAKPOINT)) {
        uint32_t word;
        std::memcpy(&word, code_mem + 4 * uint64_t{i}, 4);
        op = static_cast<uint8_t>(decode(word).op);
      }
      model.add_executions(op, running);
      // Entered by a jump, the entry did not stall.
      if (slots_[i].stalls) stalls += running - enters_[i];
    }
    running -= leaves_[i];
    enters_[i] = leaves_[i] = 0;
  }
  model.add_load_use_stalls(stalls);
}

}  // namespace fwsim
