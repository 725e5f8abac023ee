#include "cycle_model.hpp"

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace fwsim {
namespace {

struct ClassKey {
  const char* key;
  InsnClass cls;
};
constexpr ClassKey kClassKeys[] = {
    {"alu", InsnClass::Alu},          {"mul", InsnClass::Mul},
    {"div", InsnClass::Div},          {"load", InsnClass::Load},
    {"store", InsnClass::Store},      {"jump", InsnClass::Jump},
    {"csr", InsnClass::Csr},          {"system", InsnClass::System},
    {"fp_add", InsnClass::FpAdd},     {"fp_mul", InsnClass::FpMul},
    {"fp_div", InsnClass::FpDiv},     {"fp_sqrt", InsnClass::FpSqrt},
    {"fp_convert", InsnClass::FpCvt}, {"fp_compare", InsnClass::FpCmp},
    {"fp_move", InsnClass::FpMove},   {"fp_fused", InsnClass::FpFused},
    {"fp_load", InsnClass::FpLoad},   {"fp_store", InsnClass::FpStore},
};

std::string trim(const std::string& s) {
  size_t b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

bool is_pow2(uint64_t v) { return v && !(v & (v - 1)); }

class Parser {
 public:
  Parser(const std::string& origin, CycleModelConfig& cfg) : origin_(origin), cfg_(cfg) {}

  void line(const std::string& raw, int lineno) {
    lineno_ = lineno;
    std::string s = trim(raw.substr(0, raw.find('#')));
    if (s.empty()) return;
    size_t eq = s.find('=');
    if (eq == std::string::npos) fail("expected `key = value`");
    const std::string key = trim(s.substr(0, eq)), value = trim(s.substr(eq + 1));
    if (value.empty()) fail("missing value for " + key);
    if (key == "predictor") {
      if (!parse_predictor(value, cfg_.predictor))
        fail("unknown predictor '" + value + "' (static_not_taken, backward_taken, bimodal, gshare)");
      return;
    }
    const uint64_t v = number(value);
    for (const ClassKey& k : kClassKeys) {
      if (key == k.key) {
        cfg_.latency[static_cast<size_t>(k.cls)] = small(v);
        return;
      }
    }
    if (key == "clock_hz") { if (!v) fail("clock_hz must be > 0"); cfg_.clock_hz = v; }
    else if (key == "branch_taken") cfg_.branch_taken = small(v);
    else if (key == "branch_not_taken") cfg_.branch_not_taken = small(v);
    else if (key == "mispredict_penalty") cfg_.mispredict_penalty = small(v);
    else if (key == "load_use_stall") cfg_.load_use_stall = small(v);
    else if (key == "predictor_bits") {
      if (v < 1 || v > 24) fail("predictor_bits must be 1..24");
      cfg_.predictor_bits = static_cast<unsigned>(v);
    } else if (!cache_key(key, v, "icache_", cfg_.icache) && !cache_key(key, v, "dcache_", cfg_.dcache)) {
      fail("unknown key '" + key + "'");
    }
  }

  void check_cache(const CacheConfig& c, const char* which) {
    if (c.size == 0) return;
    lineno_ = 0;
    if (!is_pow2(c.line) || c.line < 4) fail(std::string(which) + "_line must be a power of two >= 4");
    if (c.ways == 0) fail(std::string(which) + "_ways must be >= 1");
    if (c.size % (c.line * c.ways) != 0 || c.size / (c.line * c.ways) == 0)
      fail(std::string(which) + "_size must be a multiple of line * ways");
  }

 private:
  bool cache_key(const std::string& key, uint64_t v, const std::string& prefix, CacheConfig& c) {
    if (key.rfind(prefix, 0) != 0) return false;
    const std::string k = key.substr(prefix.size());
    if (k == "size") c.size = small(v);
    else if (k == "ways") c.ways = small(v);
    else if (k == "line") c.line = small(v);
    else if (k == "miss_penalty") c.miss_penalty = small(v);
    else return false;
    return true;
  }
  uint64_t number(const std::string& s) {
    char* end = nullptr;
    errno = 0;
    unsigned long long v = std::strtoull(s.c_str(), &end, 0);
    if (errno || *end || s[0] == '-') fail("'" + s + "' is not a non-negative integer");
    return v;
  }
  uint32_t small(uint64_t v) {
    if (v > 1'000'000'000) fail("value too large");
    return static_cast<uint32_t>(v);
  }
  [[noreturn]] void fail(const std::string& why) {
    throw std::runtime_error(origin_ + (lineno_ ? ":" + std::to_string(lineno_) : "") + ": " + why);
  }

  std::string origin_;
  CycleModelConfig& cfg_;
  int lineno_ = 0;
};

CycleModelConfig parse_onto(CycleModelConfig cfg, const std::string& text, const std::string& origin) {
  Parser p(origin, cfg);
  std::istringstream in(text);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) p.line(line, n);
  p.check_cache(cfg.icache, "icache");
  p.check_cache(cfg.dcache, "dcache");
  return cfg;
}

}  // namespace

CycleModelConfig default_cycle_model() {
  static const CycleModelConfig cfg = parse_onto(CycleModelConfig{}, default_cycle_model_text(), "default model");
  return cfg;
}

CycleModelConfig parse_cycle_model(const std::string& text, const std::string& origin) {
  return parse_onto(default_cycle_model(), text, origin);
}

CycleModel::CycleModel(const CycleModelConfig& cfg)
    : cfg_(cfg),
      icache_on_(cfg.icache.size != 0),
      predictor_(cfg.predictor, cfg.predictor_bits),
      icache_(cfg.icache),
      dcache_(cfg.dcache) {
  for (size_t op = 0; op < static_cast<size_t>(Op::Count); ++op) {
    const OpInfo& info = kOpInfo[op];
    // Branch cost is added by branch() from its outcome.
    op_timing_[op].latency = info.cls == InsnClass::Branch ? 0 : cfg.latency[static_cast<size_t>(info.cls)];
    uint8_t u = 0;
    switch (info.format) {
      case Format::R: case Format::Branch: case Format::Store: u = 1 | 4; break;
      case Format::I: case Format::Shift: case Format::Load: case Format::Jalr: case Format::Csr:
      case Format::FCvtFX: case Format::FMvFX: case Format::FLoad: u = 1; break;
      case Format::FR: case Format::FSgn: case Format::FCmp: u = 2 | 8; break;
      case Format::FR4: u = 2 | 8 | 16; break;
      case Format::FUnary: case Format::FCvtXF: case Format::FMvXF: u = 2; break;
      case Format::FStore: u = 1 | 8; break;
      default: break;
    }
    op_timing_[op].uses = u;
    op_timing_[op].load_dest = info.cls == InsnClass::Load ? 1 : info.cls == InsnClass::FpLoad ? 2 : 0;
  }
}

}  // namespace fwsim
