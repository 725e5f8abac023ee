// core/math/soft_float.hpp against the host's hardware float (SSE on x86:
// binary32, round to nearest even, subnormals kept), bit for bit for every
// non-NaN result, NaN for NaN. Both product and quotient variants (with and
// without a multiply/divide instruction) are checked.
//   soft_float_check quick            special values, every pair of them,
//                                     rounding boundaries, 2^22 random
//                                     pairs per operation (seconds)
//   soft_float_check unary OP         all 2^32 inputs (OP: sqrt, from_int,
//                                     from_uint, to_int, to_uint)
//   soft_float_check binary OP N      N random pairs from the mixed
//                                     distributions (OP: add, sub, mul,
//                                     mul_qs, div, div_shift, compare)
// Prints what it checked; exits 1 with the first few mismatches.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "core/math/soft_float.hpp"

namespace sf = minrt::soft_float;
using u32 = uint32_t;

namespace {

float f(u32 b) {
  float x;
  std::memcpy(&x, &b, 4);
  return x;
}
u32 b(float x) {
  u32 v;
  std::memcpy(&v, &x, 4);
  return v;
}

long g_checked = 0, g_failed = 0;

bool same(u32 got, u32 want) {
  if (sf::is_nan(want)) return sf::is_nan(got);
  return got == want;
}

void report(const char* op, u32 x, u32 y, u32 got, u32 want) {
  if (++g_failed <= 10)
    std::printf("MISMATCH %s(%08x, %08x) = %08x, hardware %08x\n", op, x, y, got, want);
}

// Hardware results, through volatile so the compiler cannot fold or
// contract them.
u32 hw_add(u32 x, u32 y) { volatile float a = f(x), c = f(y); return b(a + c); }
u32 hw_sub(u32 x, u32 y) { volatile float a = f(x), c = f(y); return b(a - c); }
u32 hw_mul(u32 x, u32 y) { volatile float a = f(x), c = f(y); return b(a * c); }
u32 hw_div(u32 x, u32 y) { volatile float a = f(x), c = f(y); return b(a / c); }

enum class Op { add, sub, mul, mul_qs, div, div_shift, compare };

bool check_pair(Op op, u32 x, u32 y) {
  ++g_checked;
  u32 got = 0, want = 0;
  const char* name = "";
  switch (op) {
    case Op::add: name = "add"; got = sf::add(x, y); want = hw_add(x, y); break;
    case Op::sub: name = "sub"; got = sf::sub(x, y); want = hw_sub(x, y); break;
    case Op::mul: name = "mul"; got = sf::mul<sf::Mul64Native>(x, y); want = hw_mul(x, y); break;
    case Op::mul_qs: name = "mul_qs"; got = sf::mul<sf::MulQuarterSquares>(x, y); want = hw_mul(x, y); break;
    case Op::div: name = "div"; got = sf::div<sf::DivNative>(x, y); want = hw_div(x, y); break;
    case Op::div_shift: name = "div_shift"; got = sf::div<sf::DivShift>(x, y); want = hw_div(x, y); break;
    case Op::compare: {
      name = "compare";
      volatile float a = f(x), c = f(y);
      const bool un = std::isnan(a) || std::isnan(c);
      const int w = un ? 7 : (a < c ? -1 : (a > c ? 1 : 0));
      const int g = sf::compare(x, y, 7);
      const bool ok = g == w && sf::unordered(x, y) == un;
      if (!ok) report(name, x, y, u32(g), u32(w));
      return ok;
    }
  }
  if (!same(got, want)) {
    report(name, x, y, got, want);
    return false;
  }
  return true;
}

constexpr Op kBinaryOps[] = {Op::add, Op::sub, Op::mul, Op::mul_qs, Op::div, Op::div_shift, Op::compare};

// xorshift64*: fast, reproducible.
struct Rng {
  uint64_t s;
  u32 next() {
    s ^= s >> 12;
    s ^= s << 25;
    s ^= s >> 27;
    return u32((s * 0x2545F4914F6CDD1Dull) >> 32);
  }
};

// Operand pairs that reach every path: arbitrary bits, nearby exponents
// (cancellation, alignment by 0..30 bits), products and quotients near the
// overflow and subnormal thresholds, subnormal operands.
void random_pair(Rng& r, u32& x, u32& y) {
  const u32 k = r.next() % 6;
  x = r.next();
  y = r.next();
  switch (k) {
    case 0: break;
    case 1: {  // exponents within 32 of each other
      const u32 e = (x >> 23) & 0xffu;
      const u32 d = r.next() % 65;
      const u32 ey = (e + d + 224) & 0xffu;
      y = (y & 0x807fffffu) | (ey << 23);
      break;
    }
    case 2: {  // same exponent, mantissas differing in a few low bits
      y = (x & ~0xffu) | (y & 0xffu);
      if (r.next() & 1) y ^= 0x80000000u;
      break;
    }
    case 3: {  // exponents summing near the overflow / subnormal edges
      const u32 ex = r.next() % 256;
      const u32 target = (r.next() & 1) ? 254u + 127u : 127u;
      const int ey = int(target) - int(ex) + int(r.next() % 49) - 24;
      x = (x & 0x807fffffu) | (ex << 23);
      y = (y & 0x807fffffu) | (u32(ey < 0 ? 0 : ey > 255 ? 255 : ey) << 23);
      if (r.next() & 1) {  // quotient edges: ex - ey near the limits
        const int eq = int(ex) - int(target == 127u ? 254 : 1) + int(r.next() % 49) - 24;
        y = (y & 0x807fffffu) | (u32(eq < 0 ? 0 : eq > 255 ? 255 : eq) << 23);
      }
      break;
    }
    case 4: {  // subnormal or tiny operands
      if (r.next() & 1) x &= 0x807fffffu;
      else y &= 0x807fffffu;
      if (r.next() & 1) x >>= r.next() % 24;
      break;
    }
    case 5: {  // few mantissa bits: exact results and exact ties
      x &= 0xfff00000u | (r.next() & 0x3u);
      y &= 0xfffff000u;
      break;
    }
  }
}

std::vector<u32> special_values() {
  std::vector<u32> v;
  const u32 exps[] = {0, 1, 2, 23, 24, 25, 100, 125, 126, 127, 128, 129, 150, 200, 252, 253, 254, 255};
  const u32 fracs[] = {0, 1, 2, 3, 0x400000, 0x400001, 0x3fffff, 0x7ffffe, 0x7fffff, 0x555555, 0x2aaaaa, 0x000fff, 0x7ff000};
  for (u32 e : exps)
    for (u32 fr : fracs)
      for (u32 s : {0u, 0x80000000u}) v.push_back(s | (e << 23) | fr);
  return v;
}

bool quick() {
  const std::vector<u32> sp = special_values();
  for (Op op : kBinaryOps)
    for (u32 x : sp)
      for (u32 y : sp) check_pair(op, x, y);
  const long special_pairs = g_checked;
  // Rounding boundaries: b exactly half an ULP of a (and one ULP of b either
  // side), for addition and subtraction, at every alignment distance.
  Rng r{0x9e3779b97f4a7c15ull};
  for (int i = 0; i < 60000; ++i) {
    const u32 x = (r.next() & 0x807fffffu) | ((1 + r.next() % 253) << 23);
    const u32 ex = (x >> 23) & 0xffu;
    for (u32 d = 0; d <= 27 && d < ex; ++d) {
      const u32 y = (r.next() & 0x80000000u) | ((ex - d) << 23) | (d == 24 ? 0u : (r.next() & 0x7fffffu));
      for (u32 t : {y - 1, y, y + 1}) {
        check_pair(Op::add, x, t);
        check_pair(Op::sub, x, t);
      }
    }
  }
  // Products and quotients with an exact tie: mantissas with few bits.
  for (int i = 0; i < 500000; ++i) {
    const u32 x = (r.next() & 0xff800000u) | (r.next() & 0x7ff000u) | 0x800u;
    const u32 y = (r.next() & 0xff800000u) | (r.next() & 0x7ff800u);
    for (Op op : {Op::mul, Op::mul_qs, Op::div, Op::div_shift}) check_pair(op, x, y);
  }
  const long boundary = g_checked - special_pairs;
  for (Op op : kBinaryOps)
    for (int i = 0; i < (1 << 22); ++i) {
      u32 x, y;
      random_pair(r, x, y);
      check_pair(op, x, y);
    }
  // Unary operations on a stride through all 2^32 patterns plus the specials.
  long unary = 0;
  auto unary_check = [&](u32 x) {
    ++unary;
    volatile float a = f(x);
    const u32 want = b(std::sqrt(a));
    const u32 got = sf::sqrt(x);
    if (!same(got, want)) report("sqrt", x, 0, got, want);
    const int32_t i = int32_t(x);
    if (!same(sf::from_int(i), b(float(i)))) report("from_int", x, 0, sf::from_int(i), b(float(i)));
    if (!same(sf::from_uint(x), b(float(x)))) report("from_uint", x, 0, sf::from_uint(x), b(float(x)));
    if (std::fabs(a) < 2147483648.0f && sf::to_int(x) != int32_t(a))
      report("to_int", x, 0, u32(sf::to_int(x)), u32(int32_t(a)));
    if (a > -1.0f && a < 4294967296.0f && sf::to_uint(x) != u32(a))
      report("to_uint", x, 0, sf::to_uint(x), u32(a));
  };
  for (uint64_t x = 0; x < (1ull << 32); x += 997) unary_check(u32(x));
  for (u32 x : sp) unary_check(x);
  std::printf("quick: %ld special pairs, %ld boundary pairs, %ld random pairs, %ld unary inputs x 5 ops: %ld mismatches\n",
              special_pairs, boundary, g_checked - special_pairs - boundary, unary, g_failed);
  return g_failed == 0;
}

bool unary_all(const std::string& op) {
  for (uint64_t i = 0; i < (1ull << 32); ++i) {
    const u32 x = u32(i);
    volatile float a = f(x);
    u32 got = 0, want = 0;
    if (op == "sqrt") {
      got = sf::sqrt(x);
      want = b(std::sqrt(a));
    } else if (op == "from_int") {
      got = sf::from_int(int32_t(x));
      want = b(float(int32_t(x)));
    } else if (op == "from_uint") {
      got = sf::from_uint(x);
      want = b(float(x));
    } else if (op == "to_int") {
      if (!(std::fabs(a) < 2147483648.0f)) continue;
      got = u32(sf::to_int(x));
      want = u32(int32_t(a));
    } else if (op == "to_uint") {
      if (!(a > -1.0f && a < 4294967296.0f)) continue;
      got = sf::to_uint(x);
      want = u32(a);
    } else {
      std::fprintf(stderr, "soft_float_check: unknown unary operation '%s'\n", op.c_str());
      std::exit(2);
    }
    ++g_checked;
    if (!same(got, want)) report(op.c_str(), x, 0, got, want);
  }
  std::printf("unary %s: %ld inputs, %ld mismatches\n", op.c_str(), g_checked, g_failed);
  return g_failed == 0;
}

bool binary_random(const std::string& name, long n) {
  const char* names[] = {"add", "sub", "mul", "mul_qs", "div", "div_shift", "compare"};
  int k = -1;
  for (int i = 0; i < 7; ++i)
    if (name == names[i]) k = i;
  if (k < 0 || n <= 0) {
    std::fprintf(stderr, "soft_float_check: unknown binary operation '%s' or bad count\n", name.c_str());
    std::exit(2);
  }
  Rng r{0x243f6a8885a308d3ull + uint64_t(k)};
  for (long i = 0; i < n; ++i) {
    u32 x, y;
    random_pair(r, x, y);
    check_pair(kBinaryOps[k], x, y);
  }
  std::printf("binary %s: %ld random pairs, %ld mismatches\n", name.c_str(), g_checked, g_failed);
  return g_failed == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  bool ok;
  if (mode == "quick" && argc == 2) {
    ok = quick();
  } else if (mode == "unary" && argc == 3) {
    ok = unary_all(argv[2]);
  } else if (mode == "binary" && argc == 4) {
    ok = binary_random(argv[2], std::atol(argv[3]));
  } else {
    std::fprintf(stderr, "usage: soft_float_check quick | unary OP | binary OP COUNT\n");
    return 2;
  }
  return ok ? 0 : 1;
}
