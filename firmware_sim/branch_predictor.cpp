#include "branch_predictor.hpp"

namespace fwsim {

namespace {
struct Named {
  const char* name;
  PredictorKind kind;
};
constexpr Named kNames[] = {{"static_not_taken", PredictorKind::StaticNotTaken},
                            {"backward_taken", PredictorKind::BackwardTaken},
                            {"bimodal", PredictorKind::Bimodal},
                            {"gshare", PredictorKind::Gshare}};
}  // namespace

bool parse_predictor(const std::string& name, PredictorKind& out) {
  for (const Named& n : kNames) {
    if (name == n.name) {
      out = n.kind;
      return true;
    }
  }
  return false;
}

const char* predictor_name(PredictorKind k) {
  for (const Named& n : kNames)
    if (n.kind == k) return n.name;
  return "?";
}

BranchPredictor::BranchPredictor(PredictorKind kind, unsigned table_bits) : kind_(kind) {
  if (kind == PredictorKind::Bimodal || kind == PredictorKind::Gshare) {
    mask_ = (1u << table_bits) - 1;
    counters_.assign(size_t{1} << table_bits, 1);
  }
}

}  // namespace fwsim
