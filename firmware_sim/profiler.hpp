// Per-function profile from calls (jal/jalr with rd = ra) and returns
// (jalr x0, 0(ra)): a tree of call paths with exclusive cost per path and
// inclusive cost per activation. Written as callgrind and folded stacks by
// profile_writers.cpp.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "symbols.hpp"

namespace fwsim {

struct Cost {
  uint64_t ir = 0, cycles = 0;
  Cost& operator+=(const Cost& o) {
    ir += o.ir;
    cycles += o.cycles;
    return *this;
  }
};

class Profiler {
 public:
  struct Node {
    int fn;              // index into functions(), 0 = code outside any symbol
    uint32_t parent;
    Cost self;           // cost while this path was the innermost frame
    Cost inclusive;      // summed over completed (and, at finish, open) activations
    uint64_t calls = 0;
    std::vector<std::pair<int, uint32_t>> children;  // (fn, node)
  };
  struct FunctionTotals {
    std::string name;
    Cost self, inclusive;
    uint64_t calls = 0;
  };

  Profiler(const SymbolTable& symbols, uint32_t entry_pc);

  void call(uint32_t target, uint32_t return_addr, Cost now);
  void ret(uint32_t target, Cost now);
  // Closes the open frames (their inclusive cost runs to the end).
  void finish(Cost now);

  const std::vector<Node>& nodes() const { return nodes_; }
  const std::vector<std::string>& functions() const { return names_; }
  // Per function, recursion counted once in inclusive cost; sorted by name index.
  std::vector<FunctionTotals> function_totals() const;

 private:
  struct Frame {
    uint32_t node;
    uint32_t return_addr;
    Cost start;
    bool outermost;  // first activation of its function on the stack
  };
  int function_of(uint32_t pc);
  void charge_self(Cost now);
  void pop(Cost now);

  const SymbolTable& symbols_;
  std::vector<std::string> names_;
  std::vector<Node> nodes_;
  std::vector<Frame> stack_;
  std::vector<uint32_t> active_;  // per function: open activations
  std::vector<Cost> fn_inclusive_;
  uint32_t current_ = 0;
  Cost mark_;
  std::array<std::pair<uint32_t, int>, 1024> fn_cache_{};
};

}  // namespace fwsim
