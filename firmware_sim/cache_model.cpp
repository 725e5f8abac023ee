#include "cache_model.hpp"

namespace fwsim {

CacheModel::CacheModel(const CacheConfig& cfg) {
  if (cfg.size == 0) return;
  enabled_ = true;
  line_shift_ = static_cast<unsigned>(__builtin_ctz(cfg.line));
  ways_ = cfg.ways;
  sets_ = cfg.size / (cfg.line * cfg.ways);
  tags_.assign(std::size_t{sets_} * ways_, ~0u);
  stamp_.assign(tags_.size(), 0);
}

bool CacheModel::access(uint32_t addr) {
  ++accesses_;
  ++clock_;
  const uint32_t line = addr >> line_shift_;
  const uint32_t set = line % sets_;
  uint32_t* tags = &tags_[std::size_t{set} * ways_];
  uint64_t* stamp = &stamp_[std::size_t{set} * ways_];
  unsigned victim = 0;
  for (unsigned w = 0; w < ways_; ++w) {
    if (tags[w] == line) {
      stamp[w] = clock_;
      return true;
    }
    if (stamp[w] < stamp[victim]) victim = w;
  }
  ++misses_;
  tags[victim] = line;
  stamp[victim] = clock_;
  return false;
}

}  // namespace fwsim
