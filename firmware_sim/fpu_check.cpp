#include "fpu_check.hpp"

#include <bit>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "fpu.hpp"
#include "fpu_approx.hpp"

namespace fwsim {
namespace {

enum class Kind { Add, Sub, Mul, Div, Sqrt };

double value(uint32_t b) { return std::bit_cast<float>(b); }

// The course's operand domain: zero, or normal with magnitude below 2^127.
bool in_domain(uint32_t a) {
  const uint32_t field = (a >> 23) & 0xff;
  return (a & 0x7fffffffu) == 0 || (field >= 1 && field <= 253);
}

uint32_t make(bool negative, int exp, uint32_t frac) {
  return (negative ? 0x80000000u : 0u) | static_cast<uint32_t>(exp + 127) << 23 | (frac & 0x7fffffu);
}

class Checker {
 public:
  Checker(const FpuApprox& unit, Kind kind, FpuOpCheck& out) : unit_(unit), kind_(kind), out_(out) {
    floor_ = std::ldexp(1.0, -126 - out.bound_log2);
  }

  void sample(uint32_t a, uint32_t b) {
    if (!in_domain(a) || (kind_ != Kind::Sqrt && !in_domain(b))) return;
    const double x = value(a), y = value(b);
    double exact = 0;
    uint32_t r = 0;
    uint8_t flags = 0;
    switch (kind_) {
      case Kind::Add: exact = x + y; r = unit_.add(a, b, fpu::RNE, flags); break;
      case Kind::Sub: exact = x - y; r = unit_.sub(a, b, fpu::RNE, flags); break;
      case Kind::Mul: exact = x * y; r = unit_.mul(a, b, fpu::RNE, flags); break;
      case Kind::Div:
        if (y == 0) return;
        exact = x / y;
        r = unit_.div(a, b, fpu::RNE, flags);
        break;
      case Kind::Sqrt:
        if (x < 0) return;
        exact = std::sqrt(x);
        r = unit_.sqrt(a, fpu::RNE, flags);
        break;
    }
    if (!(std::fabs(exact) < 0x1p127)) return;
    ++out_.operands;
    double err;
    if ((r & 0x7fffffffu) >= 0x7f800000u) {
      ++out_.invalid;
      err = HUGE_VAL;
    } else {
      double scale = std::fabs(exact);
      if (kind_ == Kind::Add || kind_ == Kind::Sub) scale = std::max({scale, std::fabs(x), std::fabs(y)});
      err = std::fabs(value(r) - exact) / std::max(scale, floor_);
    }
    if (err > out_.max_error) {
      out_.max_error = err;
      out_.worst_a = a;
      out_.worst_b = b;
      out_.worst_result = r;
      out_.worst_exact = exact;
    }
  }

 private:
  const FpuApprox& unit_;
  Kind kind_;
  FpuOpCheck& out_;
  double floor_;
};

constexpr uint32_t kEdges[] = {
    0x00000000u,  // 0
    0x3f800000u,  // 1
    0x3f800001u,  // 1 + ulp
    0x3fffffffu,  // 2 - ulp
    0x3fc00000u,  // 1.5
    0x40400000u,  // 3
    0x3dcccccdu,  // 0.1
    0x3eaaaaabu,  // 1/3
    0x40490fdbu,  // pi
    0x00800000u,  // smallest normal
    0x00800001u, 0x00ffffffu,
    0x0d800000u,  // 2^-100
    0x7e800000u,  // 2^126
    0x7effffffu,  // largest below 2^127
};

std::string rounding_text(FpuModelConfig::Rounding r) {
  return r == FpuModelConfig::Rounding::Exact ? "exact (round to nearest even)" : "truncate (toward zero)";
}

}  // namespace

bool FpuOpCheck::meets() const { return invalid == 0 && max_error < std::ldexp(1.0, bound_log2); }

bool FpuCheckReport::all_meet() const {
  return std::all_of(ops.begin(), ops.end(), [](const FpuOpCheck& o) { return o.meets(); });
}

FpuCheckReport check_fpu_model(const FpuModelConfig& cfg, uint64_t random_samples) {
  const FpuApprox unit(cfg);
  FpuCheckReport report;
  report.model = describe(cfg);
  const std::string flush = cfg.flush_subnormals ? ", subnormals flushed" : "";
  auto steps = [](unsigned n) { return std::to_string(n) + (n == 1 ? " Newton step" : " Newton steps"); };
  const std::string div_text =
      cfg.div == FpuModelConfig::Div::Exact
          ? "exact (round to nearest even)"
          : "recip-mul: table " + std::to_string(cfg.recip_table_bits) + " bits x " +
                std::to_string(cfg.recip_entry_bits) + ", " + steps(cfg.recip_newton_steps);
  const std::string sqrt_text =
      cfg.sqrt == FpuModelConfig::Sqrt::Exact
          ? "exact (round to nearest even)"
          : "table-newton: table " + std::to_string(cfg.rsqrt_table_bits) + " bits x " +
                std::to_string(cfg.rsqrt_entry_bits) + ", " + steps(cfg.rsqrt_newton_steps);
  struct Spec {
    const char* name;
    Kind kind;
    int bound;
    std::string text;
  } specs[] = {{"fadd", Kind::Add, -23, rounding_text(cfg.add)},
               {"fsub", Kind::Sub, -23, rounding_text(cfg.add)},
               {"fmul", Kind::Mul, -22, rounding_text(cfg.mul)},
               {"fdiv", Kind::Div, -20, div_text},
               {"fsqrt", Kind::Sqrt, -20, sqrt_text}};

  for (const Spec& spec : specs) {
    FpuOpCheck op;
    op.op = spec.name;
    op.arithmetic = spec.text + flush;
    op.bound_log2 = spec.bound;
    Checker c(unit, spec.kind, op);
    std::mt19937_64 rng(0x5eed0000u + static_cast<unsigned>(spec.kind));
    auto bits = [&] { return static_cast<uint32_t>(rng() >> 32); };
    auto exp_in = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<uint64_t>(hi - lo + 1)); };

    // Random bit patterns over the whole domain.
    for (uint64_t i = 0; i < random_samples; ++i) c.sample(bits(), bits());
    // Random significands at moderate exponents, where results stay in range.
    for (uint64_t i = 0; i < random_samples; ++i) {
      const uint32_t a = make(bits() & 1, exp_in(-20, 20), bits());
      uint32_t b;
      if (spec.kind == Kind::Add || spec.kind == Kind::Sub) {
        const int ea = static_cast<int>((a >> 23) & 0xff) - 127;
        if (i % 4 == 0)  // near-cancellation: same magnitude up to the low bits
          b = (a & ~0xfffu) | (bits() & 0xfffu) | (bits() & 1 ? 0x80000000u : 0u);
        else
          b = make(bits() & 1, ea + exp_in(-26, 26), bits());
      } else {
        b = make(bits() & 1, exp_in(-20, 20), bits());
      }
      c.sample(spec.kind == Kind::Sqrt ? a & 0x7fffffffu : a, b);
    }
    // Edge operands, every pair and sign.
    for (uint32_t a : kEdges)
      for (uint32_t b : kEdges)
        for (uint32_t s = 0; s < 4; ++s) c.sample(a ^ (s & 1 ? 0x80000000u : 0), b ^ (s & 2 ? 0x80000000u : 0));
    // Exhaustive where the model's result depends only on the significand:
    // every divisor significand (against 1 and a random dividend), every
    // square-root operand significand at both exponent parities.
    if (spec.kind == Kind::Div) {
      for (uint32_t frac = 0; frac < (1u << 23); ++frac) {
        c.sample(0x3f800000u, 0x3f800000u | frac);
        c.sample(0x3f800000u | (bits() & 0x7fffffu), 0x3f800000u | frac);
      }
    }
    if (spec.kind == Kind::Sqrt) {
      for (uint32_t frac = 0; frac < (1u << 23); ++frac) {
        c.sample(0x3f800000u | frac, 0);
        c.sample(0x40000000u | frac, 0);
      }
    }
    report.ops.push_back(op);
  }
  return report;
}

void print_fpu_check(const FpuCheckReport& report, std::FILE* out) {
  std::fprintf(out, "fpu model: %s\n", report.model.c_str());
  std::fprintf(out, "error = |result - exact| / max(scale, 2^-126 / bound); scale = |exact| "
                    "(fadd/fsub: also |x| and |y|)\n");
  std::fprintf(out, "%-6s %-48s %10s %10s %6s  %s\n", "op", "arithmetic", "operands", "max error", "rule",
               "result");
  for (const FpuOpCheck& o : report.ops) {
    char err[32];
    if (o.invalid) std::snprintf(err, sizeof err, "invalid");
    else if (o.max_error == 0) std::snprintf(err, sizeof err, "0");
    else std::snprintf(err, sizeof err, "2^%.2f", std::log2(o.max_error));
    std::fprintf(out, "%-6s %-48s %10llu %10s  2^%d  %s\n", o.op.c_str(), o.arithmetic.c_str(),
                 static_cast<unsigned long long>(o.operands), err, o.bound_log2, o.meets() ? "meet" : "MISS");
  }
  for (const FpuOpCheck& o : report.ops) {
    if (o.max_error == 0) continue;
    char operands[40];
    if (o.op == "fsqrt") std::snprintf(operands, sizeof operands, "0x%08x", o.worst_a);
    else std::snprintf(operands, sizeof operands, "0x%08x, 0x%08x", o.worst_a, o.worst_b);
    std::fprintf(out, "worst %s: %s(%s) = 0x%08x = %.9g, exact %.9g\n", o.op.c_str(), o.op.c_str(), operands,
                 o.worst_result, value(o.worst_result), o.worst_exact);
  }
  if (report.ops.empty()) return;
  std::fprintf(out, "%s\n", report.all_meet() ? "all ops meet the course's rules"
                                                : "some ops MISS the course's rules");
}

}  // namespace fwsim
