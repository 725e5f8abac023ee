#include "profiler.hpp"

namespace fwsim {

Profiler::Profiler(const SymbolTable& symbols, uint32_t entry_pc) : symbols_(symbols) {
  names_.push_back("(no symbol)");
  for (size_t i = 0; i < symbols.size(); ++i) names_.push_back(demangle(symbols.at(static_cast<int>(i)).name));
  active_.assign(names_.size(), 0);
  fn_inclusive_.assign(names_.size(), Cost{});
  for (auto& c : fn_cache_) c = {1u, 0};  // pc 1 is never a target
  nodes_.push_back(Node{function_of(entry_pc), 0, {}, {}, 1, {}});
  stack_.push_back(Frame{0, 0, Cost{}, true});
  active_[nodes_[0].fn] = 1;
}

int Profiler::function_of(uint32_t pc) {
  auto& slot = fn_cache_[(pc >> 2) & (fn_cache_.size() - 1)];
  if (slot.first != pc) slot = {pc, symbols_.find(pc) + 1};
  return slot.second;
}

void Profiler::charge_self(Cost now) {
  nodes_[current_].self += Cost{now.ir - mark_.ir, now.cycles - mark_.cycles};
  mark_ = now;
}

void Profiler::call(uint32_t target, uint32_t return_addr, Cost now) {
  charge_self(now);
  const int fn = function_of(target);
  uint32_t child = 0;
  bool found = false;
  for (const auto& [f, n] : nodes_[current_].children) {
    if (f == fn) {
      child = n;
      found = true;
      break;
    }
  }
  if (!found) {
    child = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back(Node{fn, current_, {}, {}, 0, {}});
    nodes_[current_].children.emplace_back(fn, child);
  }
  ++nodes_[child].calls;
  stack_.push_back(Frame{child, return_addr, now, active_[fn]++ == 0});
  current_ = child;
}

void Profiler::pop(Cost now) {
  const Frame f = stack_.back();
  stack_.pop_back();
  Node& n = nodes_[f.node];
  const Cost spent{now.ir - f.start.ir, now.cycles - f.start.cycles};
  n.inclusive += spent;
  --active_[n.fn];
  if (f.outermost) fn_inclusive_[n.fn] += spent;
  current_ = stack_.empty() ? 0 : stack_.back().node;
}

void Profiler::ret(uint32_t target, Cost now) {
  // Unwind to the frame this return belongs to (longjmp-style exits skip
  // frames); a return matching no frame is not a profiled call and is ignored.
  size_t depth = stack_.size();
  while (depth > 1 && stack_[depth - 1].return_addr != target) --depth;
  if (depth <= 1) return;
  charge_self(now);
  while (stack_.size() >= depth) pop(now);
}

void Profiler::finish(Cost now) {
  charge_self(now);
  while (!stack_.empty()) pop(now);
  stack_.push_back(Frame{0, 0, now, false});  // keep the root open if profiling continues
  current_ = 0;
}

std::vector<Profiler::FunctionTotals> Profiler::function_totals() const {
  std::vector<FunctionTotals> out(names_.size());
  for (size_t i = 0; i < names_.size(); ++i) {
    out[i].name = names_[i];
    out[i].inclusive = fn_inclusive_[i];
  }
  for (const Node& n : nodes_) {
    out[static_cast<size_t>(n.fn)].self += n.self;
    out[static_cast<size_t>(n.fn)].calls += n.calls;
  }
  return out;
}

}  // namespace fwsim
