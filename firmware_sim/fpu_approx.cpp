#include "fpu_approx.hpp"

#include <bit>
#include <cmath>
#include <cstring>

#include "fpu.hpp"

namespace fwsim {
namespace {

constexpr uint32_t kSign = 0x80000000u;
constexpr uint32_t kInf = 0x7f800000u;
constexpr uint32_t kFrac = 0x007fffffu;
constexpr uint32_t kOne = 0x3f800000u;        // 1.0
constexpr uint32_t kTwo = 0x40000000u;        // 2.0
constexpr uint32_t kThreeHalves = 0x3fc00000u;  // 1.5

bool finite_nonzero(uint32_t a) {
  const uint32_t mag = a & ~kSign;
  return mag != 0 && mag < kInf;
}
bool is_subnormal(uint32_t a) { return (a & kInf) == 0 && (a & kFrac) != 0; }

float as_float(uint32_t b) { return std::bit_cast<float>(b); }
uint32_t bits_of(float f) { return std::bit_cast<uint32_t>(f); }

// A finite nonzero magnitude as significand (float bits in [1, 2)) times
// 2^exp; subnormals are normalised first.
struct Split {
  uint32_t m;
  int exp;
};
Split split(uint32_t a) {
  uint32_t frac = a & kFrac;
  const int field = static_cast<int>((a >> 23) & 0xff);
  if (field != 0) return {kOne | frac, field - 127};
  const int lz = __builtin_clz(frac) - 8;  // bring the leading one to bit 23
  frac <<= lz;
  return {kOne | (frac & kFrac), -126 - lz};
}

// Float bits of q * 2^-(entry_bits + 1), q in [2^entry_bits, 2^(entry_bits+1)].
uint32_t entry_bits_of(uint64_t q, unsigned entry_bits) {
  if (q >> (entry_bits + 1)) return kOne;  // rounded up to 1.0
  const uint32_t frac = static_cast<uint32_t>(q - (uint64_t{1} << entry_bits)) << (23 - entry_bits);
  return (126u << 23) | frac;
}

}  // namespace

uint32_t recip_table_entry(unsigned table_bits, unsigned entry_bits, uint32_t index) {
  // Midpoint of [1 + i/2^T, 1 + (i+1)/2^T) = D / 2^(T+1) with D odd, so
  // 1/mid * 2^(E+1) = 2^(T+2+E) / D, which is never exactly halfway.
  const uint64_t d = (uint64_t{1} << (table_bits + 1)) + 2 * uint64_t{index} + 1;
  const uint64_t num = uint64_t{1} << (table_bits + 2 + entry_bits);
  return entry_bits_of((num + d / 2) / d, entry_bits);
}

uint32_t rsqrt_table_entry(unsigned table_bits, unsigned entry_bits, uint32_t index) {
  // Midpoint = M / 2^s with M = 2^T + 2j + 1 (odd) and s = T - upper, where
  // `upper` selects [2, 4). q = 2^(E+1) / sqrt(mid) = sqrt(2^(2E+2+s) / M),
  // rounded to nearest by exact integer comparisons.
  const unsigned upper = index >> (table_bits - 1);
  const uint32_t j = index & ((1u << (table_bits - 1)) - 1);
  const unsigned __int128 m = (uint64_t{1} << table_bits) + 2 * uint64_t{j} + 1;
  const unsigned s = table_bits - upper;
  const unsigned __int128 target = static_cast<unsigned __int128>(1) << (2 * entry_bits + 2 + s);
  uint64_t q = static_cast<uint64_t>(std::sqrt(static_cast<double>(target) / static_cast<double>(m)));
  while (static_cast<unsigned __int128>(q) * q * m > target) --q;
  while (static_cast<unsigned __int128>(q + 1) * (q + 1) * m <= target) ++q;
  // Round up when q + 1/2 is still below the exact value: (2q+1)^2 M < 4 target.
  const unsigned __int128 twice = 2 * static_cast<unsigned __int128>(q) + 1;
  if (twice * twice * m < 4 * target) ++q;
  return entry_bits_of(q, entry_bits);
}

FpuApprox::FpuApprox(const FpuModelConfig& cfg) : cfg_(cfg) {
  if (cfg_.div == FpuModelConfig::Div::RecipMul) {
    recip_table_.resize(size_t{1} << cfg_.recip_table_bits);
    for (uint32_t i = 0; i < recip_table_.size(); ++i)
      recip_table_[i] = recip_table_entry(cfg_.recip_table_bits, cfg_.recip_entry_bits, i);
  }
  if (cfg_.sqrt == FpuModelConfig::Sqrt::TableNewton) {
    rsqrt_table_.resize(size_t{1} << cfg_.rsqrt_table_bits);
    for (uint32_t i = 0; i < rsqrt_table_.size(); ++i)
      rsqrt_table_[i] = rsqrt_table_entry(cfg_.rsqrt_table_bits, cfg_.rsqrt_entry_bits, i);
  }
}

uint32_t FpuApprox::unit_mul(uint32_t a, uint32_t b) const {
  if (cfg_.mul == FpuModelConfig::Rounding::Truncate) {
    uint8_t ignored = 0;
    return fpu::mul(a, b, fpu::RTZ, ignored);
  }
  // In range and round to nearest even: the host's float product is the same bits.
  return bits_of(as_float(a) * as_float(b));
}

uint32_t FpuApprox::unit_sub(uint32_t a, uint32_t b) const {
  if (cfg_.add == FpuModelConfig::Rounding::Truncate) {
    uint8_t ignored = 0;
    return fpu::sub(a, b, fpu::RTZ, ignored);
  }
  return bits_of(as_float(a) - as_float(b));
}

uint32_t FpuApprox::flush_in(uint32_t a) const {
  return cfg_.flush_subnormals && is_subnormal(a) ? (a & kSign) : a;
}

uint32_t FpuApprox::flush_out(uint32_t r, uint8_t& flags) const {
  if (!cfg_.flush_subnormals || !is_subnormal(r)) return r;
  flags |= fpu::UF | fpu::NX;
  return r & kSign;
}

uint32_t FpuApprox::scale(bool negative, uint32_t q, int k, uint8_t& flags) const {
  const uint32_t sign = negative ? kSign : 0;
  const int field = static_cast<int>((q >> 23) & 0xff) + k;
  if (field >= 255) {
    flags |= fpu::OF | fpu::NX;
    return sign | kInf;
  }
  flags |= fpu::NX;  // an approximate unit cannot tell whether it was exact
  if (field >= 1) return sign | static_cast<uint32_t>(field) << 23 | (q & kFrac);
  if (cfg_.flush_subnormals) {
    flags |= fpu::UF;
    return sign;
  }
  // Denormalise the 24-bit significand, rounding to nearest even.
  const uint32_t sig = (q & kFrac) | 0x800000u;
  const int shift = 1 - field;
  uint32_t kept = 0;
  if (shift <= 25) {
    kept = sig >> shift;
    const uint32_t rem = sig & ((1u << shift) - 1), half = 1u << (shift - 1);
    if (rem > half || (rem == half && (kept & 1))) ++kept;
  }
  if (kept < 0x800000u) flags |= fpu::UF;  // 0x800000 is the smallest normal
  return sign | kept;
}

uint32_t FpuApprox::recip_significand(uint32_t m) const {
  const unsigned t = cfg_.recip_table_bits;
  uint32_t r = recip_table_[t ? (m & kFrac) >> (23 - t) : 0];
  for (unsigned i = 0; i < cfg_.recip_newton_steps; ++i) {
    const uint32_t mr = unit_mul(m, r);
    r = unit_mul(r, unit_sub(kTwo, mr));  // r (2 - m r)
  }
  return r;
}

uint32_t FpuApprox::rsqrt_significand(uint32_t m) const {
  const unsigned t = cfg_.rsqrt_table_bits;
  const uint32_t upper = (m >> 23) == 128;  // m in [2, 4)
  uint32_t r = rsqrt_table_[(upper << (t - 1)) | ((m & kFrac) >> (24 - t))];
  const uint32_t half_m = m - (1u << 23);  // m / 2, exact
  for (unsigned i = 0; i < cfg_.rsqrt_newton_steps; ++i) {
    const uint32_t rr = unit_mul(r, r);
    const uint32_t hrr = unit_mul(half_m, rr);
    r = unit_mul(r, unit_sub(kThreeHalves, hrr));  // r (1.5 - (m/2) r^2)
  }
  return r;
}

// An IEEE operation as the unit rounds it: exactly, or truncated (toward
// zero, and an overflow gives infinity: a truncating unit does not
// saturate), with subnormals flushed when the model says so.
template <class Op>
uint32_t FpuApprox::rounded(FpuModelConfig::Rounding mode, uint32_t a, uint32_t b, unsigned rm, uint8_t& flags,
                            Op op) const {
  a = flush_in(a);
  b = flush_in(b);
  if (mode == FpuModelConfig::Rounding::Exact) return flush_out(op(a, b, rm, flags), flags);
  uint8_t f = 0;
  uint32_t r = op(a, b, fpu::RTZ, f);
  if (f & fpu::OF) r = (r & kSign) | kInf;
  flags |= f;
  return flush_out(r, flags);
}

uint32_t FpuApprox::add(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const {
  return rounded(cfg_.add, a, b, rm, flags, fpu::add);
}

uint32_t FpuApprox::sub(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const {
  return add(a, fpu::is_nan(b) ? b : b ^ kSign, rm, flags);
}

uint32_t FpuApprox::mul(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const {
  return rounded(cfg_.mul, a, b, rm, flags, fpu::mul);
}

uint32_t FpuApprox::div(uint32_t a, uint32_t b, unsigned rm, uint8_t& flags) const {
  a = flush_in(a);
  b = flush_in(b);
  // Zeros, infinities and NaNs have exact IEEE results (and flags).
  if (cfg_.div == FpuModelConfig::Div::Exact || !finite_nonzero(a) || !finite_nonzero(b))
    return flush_out(fpu::div(a, b, rm, flags), flags);
  const Split x = split(a), y = split(b);
  const uint32_t q = unit_mul(x.m, recip_significand(y.m));  // in (0.5, 2)
  return scale(((a ^ b) & kSign) != 0, q, x.exp - y.exp, flags);
}

uint32_t FpuApprox::sqrt(uint32_t a, unsigned rm, uint8_t& flags) const {
  a = flush_in(a);
  if (cfg_.sqrt == FpuModelConfig::Sqrt::Exact || !finite_nonzero(a) || (a & kSign))
    return flush_out(fpu::sqrt(a, rm, flags), flags);
  Split x = split(a);
  if (x.exp & 1) {  // odd exponent: sqrt(m 2^e) = sqrt(2m) 2^((e-1)/2)
    x.m += 1u << 23;
    x.exp -= 1;
  }
  const uint32_t s = unit_mul(x.m, rsqrt_significand(x.m));  // m / sqrt(m), in [1, 2)
  return scale(false, s, x.exp / 2, flags);
}

}  // namespace fwsim
