// Fixed-capacity unsigned big integer, just enough for correctly rounded
// decimal-to-binary conversion of number tokens (no heap, integer-only so it
// runs the same on a CPU without an FPU).
#pragma once

#include <stdint.h>

namespace minrt {

class BigUint {
 public:
  // 4096 bits: a 256-digit mantissa times 10^~350, or shifted up to that.
  static constexpr int kLimbs = 128;

  BigUint() = default;
  explicit BigUint(uint64_t v) { set_u64(v); }

  void set_u64(uint64_t v) {
    size_ = 0;
    while (v != 0) {
      limb_[size_++] = static_cast<uint32_t>(v);
      v >>= 32;
    }
  }
  bool is_zero() const { return size_ == 0; }

  // Returns false when the result would not fit (the caller treats that as
  // overflow to infinity / underflow to zero before it can happen).
  bool mul_add_small(uint32_t mul, uint32_t add) {
    uint64_t carry = add;
    for (int i = 0; i < size_; ++i) {
      uint64_t t = static_cast<uint64_t>(limb_[i]) * mul + carry;
      limb_[i] = static_cast<uint32_t>(t);
      carry = t >> 32;
    }
    if (carry != 0) {
      if (size_ == kLimbs) return false;
      limb_[size_++] = static_cast<uint32_t>(carry);
    }
    return true;
  }

  bool mul_pow10(int n) {
    for (; n >= 9; n -= 9)
      if (!mul_add_small(1000000000u, 0)) return false;
    static constexpr uint32_t kPow10[9] = {1, 10, 100, 1000, 10000, 100000,
                                                1000000, 10000000, 100000000};
    return mul_add_small(kPow10[n], 0);
  }

  bool shift_left(int bits) {
    if (is_zero() || bits == 0) return true;
    const int words = bits / 32, rem = bits % 32;
    const int new_size = size_ + words + (rem != 0 ? 1 : 0);
    if (new_size > kLimbs) return false;
    // Top-down so each source limb is read before it is overwritten.
    for (int i = new_size - 1; i >= 0; --i) {
      const int src = i - words;
      const uint32_t hi = (src >= 0 && src < size_) ? limb_[src] : 0;
      const uint32_t lo = (src >= 1 && src - 1 < size_) ? limb_[src - 1] : 0;
      limb_[i] = rem == 0 ? hi : (hi << rem) | (lo >> (32 - rem));
    }
    size_ = new_size;
    trim();
    return true;
  }

  void shift_right_one() {
    for (int i = 0; i < size_; ++i) {
      uint32_t next = i + 1 < size_ ? limb_[i + 1] : 0;
      limb_[i] = (limb_[i] >> 1) | (next << 31);
    }
    trim();
  }

  int bit_length() const {
    if (size_ == 0) return 0;
    return (size_ - 1) * 32 + (32 - __builtin_clz(limb_[size_ - 1]));
  }
  bool bit(int i) const {
    const int w = i / 32;
    return w < size_ && ((limb_[w] >> (i % 32)) & 1u) != 0;
  }
  // True when any bit below position `n` is set.
  bool any_below(int n) const {
    for (int i = 0; i < size_ && i * 32 < n; ++i) {
      const int keep = n - i * 32;
      const uint32_t mask = keep >= 32 ? 0xffffffffu : ((1u << keep) - 1u);
      if ((limb_[i] & mask) != 0) return true;
    }
    return false;
  }
  // Bits [lo, lo+64) as an integer.
  uint64_t bits_from(int lo) const {
    uint64_t v = 0;
    for (int i = 63; i >= 0; --i) v = (v << 1) | (bit(lo + i) ? 1u : 0u);
    return v;
  }

  int compare(const BigUint& o) const {
    if (size_ != o.size_) return size_ < o.size_ ? -1 : 1;
    for (int i = size_ - 1; i >= 0; --i)
      if (limb_[i] != o.limb_[i]) return limb_[i] < o.limb_[i] ? -1 : 1;
    return 0;
  }
  // *this -= o; requires *this >= o.
  void subtract(const BigUint& o) {
    int64_t borrow = 0;
    for (int i = 0; i < size_; ++i) {
      int64_t t = static_cast<int64_t>(limb_[i]) - borrow -
                       (i < o.size_ ? static_cast<int64_t>(o.limb_[i]) : 0);
      borrow = t < 0 ? 1 : 0;
      limb_[i] = static_cast<uint32_t>(t + (borrow << 32));
    }
    trim();
  }

 private:
  void trim() {
    while (size_ > 0 && limb_[size_ - 1] == 0) --size_;
  }

  uint32_t limb_[kLimbs] = {};
  int size_ = 0;
};

}  // namespace minrt
