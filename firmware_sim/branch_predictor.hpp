// Conditional-branch direction predictors for the cycle model.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace fwsim {

enum class PredictorKind : uint8_t { StaticNotTaken, BackwardTaken, Bimodal, Gshare };

bool parse_predictor(const std::string& name, PredictorKind& out);
const char* predictor_name(PredictorKind k);

class BranchPredictor {
 public:
  BranchPredictor(PredictorKind kind, unsigned table_bits);
  // Predicts, then trains with the outcome; returns true when the prediction was right.
  __attribute__((always_inline)) bool resolve(uint32_t pc, bool taken, bool backward) {
    switch (kind_) {
      case PredictorKind::StaticNotTaken: return !taken;
      case PredictorKind::BackwardTaken: return taken == backward;
      default: break;
    }
    uint32_t idx = pc >> 2;
    if (kind_ == PredictorKind::Gshare) idx ^= history_;
    idx &= mask_;
    uint8_t& c = counters_[idx];
    const bool predicted = c >= 2;
    if (taken && c < 3) ++c;
    if (!taken && c > 0) --c;
    history_ = ((history_ << 1) | taken) & mask_;
    return predicted == taken;
  }

 private:
  PredictorKind kind_;
  uint32_t mask_ = 0, history_ = 0;
  std::vector<uint8_t> counters_;  // 2-bit saturating, start weakly not-taken
};

}  // namespace fwsim
