// Counter-based random numbers: each number is a hash of (seed, stream,
// counter), so any pixel's samples can be drawn in any order, by any thread,
// on the host or the board, and come out the same. Only 32-bit integer
// multiply, xor and shifts: RV32IM has all of them.
#pragma once

#include <stdint.h>

namespace minrt {

// A 32-bit avalanche hash (the "lowbias32" constants of Chris Wellons's
// hash-prospector search, a published integer mixer).
constexpr uint32_t mix32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// One stream of numbers, e.g. one pixel: next() advances a counter.
class CounterRng {
 public:
  constexpr CounterRng(uint32_t seed, uint32_t stream)
      : key_(mix32(seed ^ mix32(stream + 0x9e3779b9u))) {}

  constexpr uint32_t next_u32() { return mix32(key_ + mix32(counter_++)); }

  // An independent stream for a branch (a reflected ray, ...), addressed by
  // this stream's position and the branch: drawing from it, or not tracing
  // the branch at all, leaves this stream's numbers unchanged, and the same
  // branch forked at another position (another sample's hit) differs.
  constexpr CounterRng fork(uint32_t branch) const {
    return CounterRng(key_, counter_ * 0x9e3779b9u + branch * 0x85ebca6bu + 0x165667b1u, 0);
  }

  // Uniform in [0, 1) with 24 random bits: exact in float and in double, so
  // the host's float and double models and the board see the same values.
  // The conversion goes through the math policy M (no int-to-float
  // instruction is assumed).
  template <class M>
  constexpr typename M::real uniform() {
    using R = typename M::real;
    return M::from_int(static_cast<int32_t>(next_u32() >> 8)) * static_cast<R>(1.0f / 16777216.0f);
  }

 private:
  constexpr CounterRng(uint32_t parent_key, uint32_t salt, int) : key_(mix32(parent_key ^ mix32(salt))) {}

  uint32_t key_;
  uint32_t counter_ = 0;
};

}  // namespace minrt
