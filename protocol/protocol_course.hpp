// Course protocol, shared by the host and the board. Freestanding: no heap,
// no exceptions, only <stdint.h>/<stddef.h> and the core's ByteSource.
//
//   board 0x99            host: program size (u32) + program bytes
//   board 0xaa            host: the scene as 4-byte words (ints and IEEE
//                         floats) in the order min-rt reads its tokens
//   board PPM image, or one MINRT_ERROR_MARKER line (as in the raw protocol)
//
// The word order (SceneLayout): 5 floats (screen position and rotation),
// 1 int (light count), 3 floats (light rotation and brightness), per object
// 4 ints (texture, form, reflection type, rotation flag) and 12 floats
// (size 3, position 3, invert 1, reflection 2, colour 3) plus 3 rotation
// floats when the flag is non-zero; -1 ends the objects (at most 60); the
// AND networks (ints, each ended by -1, the list ended by a network that
// starts with -1) and the OR networks (likewise) are all ints.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt::send::course {

inline constexpr uint8_t kProgramRequest = 0x99;
inline constexpr uint8_t kSceneRequest = 0xaa;
inline constexpr int kMaxObjects = 60;

enum class Endian { kLittle, kBig };

inline void put_u32(uint8_t* p, uint32_t v, Endian e) {
  for (int i = 0; i < 4; ++i) p[e == Endian::kLittle ? i : 3 - i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint32_t get_u32(const uint8_t* p, Endian e) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(p[e == Endian::kLittle ? i : 3 - i]) << (8 * i);
  return v;
}

enum class Kind { kInt, kFloat, kEnd };

// Which kind the next word is, given the ones before.
class SceneLayout {
 public:
  Kind next() const {
    switch (phase_) {
      case kScreen:
      case kLight:
        return Kind::kFloat;
      case kObject:
        return left_ > 12 + extra_ ? Kind::kInt : Kind::kFloat;
      case kDone:
        return Kind::kEnd;
      default:
        return Kind::kInt;
    }
  }
  // Records the word just read (its integer value for kInt words).
  void consume(int32_t int_value) {
    switch (phase_) {
      case kScreen:
        if (++count_ == 5) phase_ = kLightCount;
        return;
      case kLightCount:
        phase_ = kLight;
        count_ = 0;
        return;
      case kLight:
        if (++count_ == 3) start_object();
        return;
      case kObject:
        if (left_ == 16 && int_value == -1) {  // texture -1 ends the objects
          phase_ = kAndStart;
          return;
        }
        if (left_ == 13 && int_value != 0) {  // rotation flag
          extra_ = 3;
          left_ += 3;
        }
        if (--left_ == 0) {
          ++objects_;
          if (objects_ == kMaxObjects) phase_ = kAndStart;
          else start_object();
        }
        return;
      case kAndStart:
        phase_ = int_value == -1 ? kOrStart : kAndBody;
        return;
      case kAndBody:
        if (int_value == -1) phase_ = kAndStart;
        return;
      case kOrStart:
        phase_ = int_value == -1 ? kDone : kOrBody;
        return;
      case kOrBody:
        if (int_value == -1) phase_ = kOrStart;
        return;
      case kDone:
        return;
    }
  }
  bool done() const { return phase_ == kDone; }
  int objects() const { return objects_; }

 private:
  void start_object() {
    phase_ = kObject;
    left_ = 16;
    extra_ = 0;
  }
  enum Phase { kScreen, kLightCount, kLight, kObject, kAndStart, kAndBody, kOrStart, kOrBody, kDone };
  Phase phase_ = kScreen;
  int count_ = 0;
  int left_ = 0;   // words left in the current object (ints first)
  int extra_ = 0;  // 3 when the object is rotated
  int objects_ = 0;
};

// Writes the exact decimal value of an IEEE single (every float is a finite
// decimal fraction), so any correctly rounding reader gets the same float
// back. Non-finite values come out as "nan"/"inf" for the reader to reject.
// `out` needs 160 bytes; returns the length.
inline size_t format_float_exact(uint32_t bits, char* out) {
  size_t n = 0;
  if (bits >> 31) out[n++] = '-';
  const uint32_t exp = (bits >> 23) & 0xFF;
  uint32_t mant = bits & 0x7FFFFF;
  if (exp == 0xFF) {
    const char* s = mant != 0 ? "nan" : "inf";
    while (*s) out[n++] = *s++;
    return n;
  }
  if (exp == 0 && mant == 0) {
    out[n++] = '0';
    return n;
  }
  int e;  // value = mant * 2^e
  if (exp == 0) {
    e = -149;
  } else {
    mant |= 0x800000;
    e = static_cast<int>(exp) - 150;
  }
  // Big number in base 1e9 limbs, little end first: mant * 2^e, or for e<0
  // mant * 5^-e with the decimal point -e digits from the right.
  uint32_t limb[20] = {mant % 1000000000u, mant / 1000000000u};
  int used = 2;
  auto mul = [&](uint32_t m) {
    uint64_t carry = 0;
    for (int i = 0; i < used; ++i) {
      const uint64_t v = static_cast<uint64_t>(limb[i]) * m + carry;
      limb[i] = static_cast<uint32_t>(v % 1000000000u);
      carry = v / 1000000000u;
    }
    while (carry != 0) {
      limb[used++] = static_cast<uint32_t>(carry % 1000000000u);
      carry /= 1000000000u;
    }
  };
  int frac_digits = 0;
  if (e >= 0) {
    for (int i = 0; i < e; ++i) mul(2);
  } else {
    for (int i = 0; i < -e; ++i) mul(5);
    frac_digits = -e;
  }
  while (used > 1 && limb[used - 1] == 0) --used;
  char digits[200];
  int nd = 0;
  for (int i = 0; i < used; ++i) {
    uint32_t v = limb[i];
    for (int k = 0; k < 9; ++k) {
      digits[nd++] = static_cast<char>('0' + v % 10);
      v /= 10;
    }
  }
  // digits[] is little end first; drop leading zeros above the point.
  while (nd > frac_digits + 1 && digits[nd - 1] == '0') --nd;
  // Trailing zeros of the fraction.
  int low = 0;
  while (low < frac_digits && (low >= nd || digits[low] == '0')) ++low;
  const int int_digits = nd > frac_digits ? nd - frac_digits : 0;
  if (int_digits == 0) out[n++] = '0';
  for (int i = nd - 1; i >= frac_digits; --i) out[n++] = digits[i];
  if (low < frac_digits) {
    out[n++] = '.';
    for (int i = frac_digits - 1; i >= low; --i) out[n++] = i < nd ? digits[i] : '0';
  }
  return n;
}

inline size_t format_int(int32_t v, char* out) {
  size_t n = 0;
  uint32_t u = v < 0 ? 0u - static_cast<uint32_t>(v) : static_cast<uint32_t>(v);
  if (v < 0) out[n++] = '-';
  char d[12];
  int k = 0;
  do {
    d[k++] = static_cast<char>('0' + u % 10);
    u /= 10;
  } while (u != 0);
  while (k > 0) out[n++] = d[--k];
  return n;
}

// Board side: a ByteSource that reads the scene words from `words` (the
// UART) and hands the renderer the same scene as SLD text, one token per
// line, so the existing SLD reader parses it unchanged. It reads a word
// only when the reader asks for more text, and nothing after the layout
// is complete.
class SceneTextSource {
 public:
  SceneTextSource(ByteSource words, Endian endian) : words_(words), endian_(endian) {}

  ByteSource source() { return ByteSource{&read_fn, this}; }
  bool failed() const { return failed_; }

 private:
  static int read_fn(void* ctx) { return static_cast<SceneTextSource*>(ctx)->next(); }
  int next() {
    if (pos_ < len_) return static_cast<uint8_t>(text_[pos_++]);
    const Kind kind = layout_.next();
    if (kind == Kind::kEnd || failed_) return -1;
    uint8_t w[4];
    for (int i = 0; i < 4; ++i) {
      const int c = words_.get();
      if (c < 0) {
        failed_ = true;
        return -1;
      }
      w[i] = static_cast<uint8_t>(c);
    }
    const uint32_t v = get_u32(w, endian_);
    if (kind == Kind::kInt) {
      len_ = format_int(static_cast<int32_t>(v), text_);
      layout_.consume(static_cast<int32_t>(v));
    } else {
      len_ = format_float_exact(v, text_);
      layout_.consume(0);
    }
    text_[len_++] = '\n';
    pos_ = 0;
    return static_cast<uint8_t>(text_[pos_++]);
  }

  ByteSource words_;
  Endian endian_;
  SceneLayout layout_;
  char text_[200] = {};
  size_t len_ = 0, pos_ = 0;
  bool failed_ = false;
};

}  // namespace minrt::send::course
