// Set-associative cache with LRU replacement, for the cycle model. Only tags
// are kept: the model needs hit/miss, not data.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fwsim {

struct CacheConfig {
  uint32_t size = 0;  // bytes; 0 = no cache
  uint32_t ways = 1;
  uint32_t line = 32;
  uint32_t miss_penalty = 0;
};

class CacheModel {
 public:
  explicit CacheModel(const CacheConfig& cfg);
  bool enabled() const { return enabled_; }
  unsigned line_shift() const { return line_shift_; }
  // Looks the line up, fills it on a miss; returns true on a hit.
  bool access(uint32_t addr);
  uint64_t accesses() const { return accesses_; }
  uint64_t misses() const { return misses_; }

 private:
  bool enabled_ = false;
  unsigned line_shift_ = 5;
  uint32_t sets_ = 1, ways_ = 1;
  std::vector<uint32_t> tags_;   // sets_*ways_, ~0u = invalid
  std::vector<uint64_t> stamp_;  // last use, for LRU
  uint64_t clock_ = 0, accesses_ = 0, misses_ = 0;
};

}  // namespace fwsim
