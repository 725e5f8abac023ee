// The faults fault-relay puts on a line, decided by a seeded generator so a
// run can be repeated: drop a byte, flip one of its bits, send it twice,
// delay it, or stall the whole line for a while.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fault_relay {

struct FaultRates {
  double drop = 0, flip = 0, dup = 0, delay = 0, stall = 0;  // per byte
  int delay_ms = 5;    // longest single-byte delay
  int stall_ms = 300;  // length of a stall
  std::uint64_t skip = 0;  // bytes passed untouched at the start
  // One fault at a chosen byte (0-based index in its direction; -1 none),
  // for tests that need one exact defect: `94` -> `4`, `16` -> `116`.
  std::int64_t drop_at = -1, dup_at = -1, flip_at = -1;
};

struct FaultCounts {
  std::uint64_t bytes = 0, dropped = 0, flipped = 0, duplicated = 0, delayed = 0, stalls = 0;
  std::string summary() const;
};

// What to do with one byte.
struct Action {
  int copies = 1;        // 0 dropped, 2 duplicated
  std::uint8_t value = 0;
  int sleep_ms = 0;      // pause before sending it
};

class FaultModel {
 public:
  FaultModel(std::uint64_t seed, const FaultRates& rates) : state_(seed * 0x9E3779B97F4A7C15ull + 1), rates_(rates) {}

  Action next(std::uint8_t byte) {
    Action a;
    a.value = byte;
    const std::uint64_t index = counts_.bytes++;
    // Draw every decision for every byte so the sequence does not depend
    // on which faults are enabled.
    const double u_drop = uniform(), u_flip = uniform(), u_dup = uniform(), u_delay = uniform(), u_stall = uniform();
    const std::uint64_t r = bits();
    if (static_cast<std::int64_t>(index) == rates_.drop_at) {
      a.copies = 0;
      ++counts_.dropped;
      return a;
    }
    if (static_cast<std::int64_t>(index) == rates_.flip_at) {
      a.value = static_cast<std::uint8_t>(byte ^ 1u);
      ++counts_.flipped;
    }
    if (static_cast<std::int64_t>(index) == rates_.dup_at) {
      a.copies = 2;
      ++counts_.duplicated;
    }
    if (index < rates_.skip) return a;
    if (u_stall < rates_.stall) {
      a.sleep_ms += rates_.stall_ms;
      ++counts_.stalls;
    }
    if (u_delay < rates_.delay) {
      a.sleep_ms += 1 + static_cast<int>(r % static_cast<std::uint64_t>(rates_.delay_ms));
      ++counts_.delayed;
    }
    if (u_drop < rates_.drop) {
      a.copies = 0;
      ++counts_.dropped;
      return a;
    }
    if (u_flip < rates_.flip) {
      a.value = static_cast<std::uint8_t>(byte ^ (1u << ((r >> 16) & 7)));
      ++counts_.flipped;
    }
    if (u_dup < rates_.dup) {
      a.copies = 2;
      ++counts_.duplicated;
    }
    return a;
  }

  const FaultCounts& counts() const { return counts_; }

 private:
  // splitmix64
  std::uint64_t bits() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(bits() >> 11) * (1.0 / 9007199254740992.0); }

  std::uint64_t state_;
  FaultRates rates_;
  FaultCounts counts_;
};

inline std::string FaultCounts::summary() const {
  return std::to_string(bytes) + " bytes: " + std::to_string(dropped) + " dropped, " + std::to_string(flipped) +
         " flipped, " + std::to_string(duplicated) + " duplicated, " + std::to_string(delayed) + " delayed, " +
         std::to_string(stalls) + " stalls";
}

}  // namespace fault_relay
