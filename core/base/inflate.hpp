// A raw deflate decoder (RFC 1951) for the board: no heap, no tables beyond
// the object itself (about 1.4 KB), the output written straight into a
// caller's buffer that also serves as the history window. Work is bounded
// by the input read plus the output written: every step of the loop takes
// bits or writes a byte, and the output never grows past its capacity.
// A code of up to kFastBits bits is decoded by one look-up in a table of
// 2^kFastBits entries; longer ones, and the last codes of a stream, a bit
// at a time against the canonical code's counts.
//
// In place: the compressed bytes may lie in the same memory above the
// output. Then every byte is written only when it lies below the first
// input byte not yet read, or the decoder stops with kOverrun, so a damaged
// stream can never overwrite what it has yet to read.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt {

enum class InflateStatus : uint8_t {
  kDone,      // the final block ended
  kCut,       // the input ended inside the stream
  kCorrupt,   // a bad block type, code, length or distance
  kOverflow,  // more output than the buffer holds
  kOverrun,   // in place: the output would overwrite unread input
};

inline const char* inflate_message(InflateStatus s) {
  switch (s) {
    case InflateStatus::kDone: return "complete";
    case InflateStatus::kCut: return "compressed data cut short";
    case InflateStatus::kCorrupt: return "compressed data corrupt";
    case InflateStatus::kOverflow: return "compressed data decodes to more bytes than expected";
    case InflateStatus::kOverrun: return "compressed data would overwrite itself";
  }
  return "?";
}

class Inflater {
 public:
  // Decodes one raw deflate stream from `in` into out[0, capacity). With
  // `in_place`, the address of the stream's first byte in the same memory
  // as `out` (above it), writes are held below the unread input.
  InflateStatus run(ByteSource in, uint8_t* out, size_t capacity, const uint8_t* in_place = nullptr) {
    in_ = in;
    out_ = out;
    cap_ = capacity;
    pos_ = 0;
    consumed_ = 0;
    bits_ = 0;
    nbits_ = 0;
    lead_ = 0;
    guard_ = in_place != nullptr;
    in_addr_ = reinterpret_cast<uintptr_t>(in_place);
    out_addr_ = reinterpret_cast<uintptr_t>(out);
    for (;;) {
      uint32_t last = 0, type = 0;
      if (!need(1, last) || !need(2, type)) return InflateStatus::kCut;
      InflateStatus s = InflateStatus::kCorrupt;
      if (type == 0) s = stored();
      else if (type == 1) s = fixed();
      else if (type == 2) s = dynamic();
      if (s != InflateStatus::kDone) return s;
      if (last != 0) return InflateStatus::kDone;
    }
  }

  size_t produced() const { return pos_; }
  size_t consumed() const { return consumed_; }
  // The largest (bytes written) - (bytes read) seen at any write: a stream
  // decoded in place needs its output to start at least this far below it.
  long long lead() const { return lead_; }

 private:
  static constexpr int kMaxBits = 15;
  static constexpr int kLitCodes = 288;
  static constexpr int kDistCodes = 32;
  static constexpr int kFastBits = 9;

  struct Code {
    uint16_t count[kMaxBits + 1];
    uint16_t symbol[kLitCodes];
    // Indexed by the next kFastBits bits: length << kFastBits | symbol, or
    // 0 when the code there is longer.
    uint16_t fast[1 << kFastBits];
  };

  // Bits come least significant first; a byte is read only when needed.
  bool need(int n, uint32_t& v) {
    while (nbits_ < n) {
      const int c = in_.get();
      if (c < 0) return false;
      ++consumed_;
      bits_ |= static_cast<uint32_t>(c) << nbits_;
      nbits_ += 8;
    }
    v = bits_ & ((1u << n) - 1u);
    bits_ >>= n;
    nbits_ -= n;
    return true;
  }

  bool put(uint8_t b) {
    const long long lead = static_cast<long long>(pos_ + 1) - static_cast<long long>(consumed_);
    if (lead > lead_) lead_ = lead;
    if (guard_ && out_addr_ + pos_ >= in_addr_ + consumed_) return false;
    out_[pos_++] = b;
    return true;
  }

  InflateStatus stored() {
    const int pad = nbits_ % 8;  // the rest of the current byte; whole bytes read ahead stay
    bits_ >>= pad;
    nbits_ -= pad;
    uint32_t len = 0, nlen = 0;
    if (!need(16, len) || !need(16, nlen)) return InflateStatus::kCut;
    if ((len ^ 0xFFFFu) != nlen) return InflateStatus::kCorrupt;
    for (uint32_t i = 0; i < len; ++i) {
      uint32_t b = 0;
      if (!need(8, b)) return InflateStatus::kCut;
      if (pos_ >= cap_) return InflateStatus::kOverflow;
      if (!put(static_cast<uint8_t>(b))) return InflateStatus::kOverrun;
    }
    return InflateStatus::kDone;
  }

  // Canonical code from the lengths; false when over-subscribed. An
  // incomplete code is accepted: its missing codes fail in decode().
  static bool build(Code& code, const uint8_t* lengths, int n) {
    for (int i = 0; i <= kMaxBits; ++i) code.count[i] = 0;
    for (int i = 0; i < n; ++i) ++code.count[lengths[i]];
    code.count[0] = 0;
    int left = 1;
    for (int len = 1; len <= kMaxBits; ++len) {
      left = 2 * left - code.count[len];
      if (left < 0) return false;
    }
    uint16_t offset[kMaxBits + 2];
    offset[1] = 0;
    for (int len = 1; len <= kMaxBits; ++len) offset[len + 1] = static_cast<uint16_t>(offset[len] + code.count[len]);
    for (int i = 0; i < n; ++i)
      if (lengths[i] != 0) code.symbol[offset[lengths[i]]++] = static_cast<uint16_t>(i);
    // The short codes in the look-up table: canonical codes go most
    // significant bit first, the stream least significant first, so each
    // fills every entry whose low bits are its code reversed.
    for (uint16_t& e : code.fast) e = 0;
    uint32_t next = 0;
    int index = 0;
    for (int len = 1; len <= kFastBits; ++len) {
      for (int k = 0; k < code.count[len]; ++k, ++next) {
        uint32_t reversed = 0;
        for (int b = 0; b < len; ++b) reversed |= ((next >> b) & 1u) << (len - 1 - b);
        const uint16_t entry = static_cast<uint16_t>(len << kFastBits | code.symbol[index++]);
        for (uint32_t r = reversed; r < (1u << kFastBits); r += 1u << len) code.fast[r] = entry;
      }
      next <<= 1;
    }
    return true;
  }

  // One symbol: -1 when the input ends, -2 for a code the table lacks.
  int decode(const Code& code) {
    while (nbits_ < kFastBits) {  // read ahead for the table, as far as the input goes
      const int c = in_.get();
      if (c < 0) break;
      ++consumed_;
      bits_ |= static_cast<uint32_t>(c) << nbits_;
      nbits_ += 8;
    }
    const uint16_t e = code.fast[bits_ & ((1u << kFastBits) - 1u)];
    const int len = e >> kFastBits;
    if (e != 0 && len <= nbits_) {
      bits_ >>= len;
      nbits_ -= len;
      return e & ((1 << kFastBits) - 1);
    }
    int value = 0, first = 0, index = 0;
    for (int len = 1; len <= kMaxBits; ++len) {
      uint32_t bit = 0;
      if (!need(1, bit)) return -1;
      value |= static_cast<int>(bit);
      const int count = code.count[len];
      if (value - first < count) return code.symbol[index + value - first];
      index += count;
      first = (first + count) << 1;
      value <<= 1;
    }
    return -2;
  }

  InflateStatus codes(const Code& lit, const Code& dist) {
    static constexpr uint16_t kLenBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                              31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static constexpr uint8_t kLenExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                              2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static constexpr uint16_t kDistBase[30] = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                               33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                               1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
    static constexpr uint8_t kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                               6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
    for (;;) {
      const int sym = decode(lit);
      if (sym == -1) return InflateStatus::kCut;
      if (sym < 0) return InflateStatus::kCorrupt;
      if (sym < 256) {
        if (pos_ >= cap_) return InflateStatus::kOverflow;
        if (!put(static_cast<uint8_t>(sym))) return InflateStatus::kOverrun;
        continue;
      }
      if (sym == 256) return InflateStatus::kDone;
      const int li = sym - 257;
      if (li >= 29) return InflateStatus::kCorrupt;
      uint32_t extra = 0;
      if (!need(kLenExtra[li], extra)) return InflateStatus::kCut;
      const size_t len = kLenBase[li] + extra;
      const int ds = decode(dist);
      if (ds == -1) return InflateStatus::kCut;
      if (ds < 0 || ds >= 30) return InflateStatus::kCorrupt;
      if (!need(kDistExtra[ds], extra)) return InflateStatus::kCut;
      const size_t distance = kDistBase[ds] + extra;
      if (distance > pos_) return InflateStatus::kCorrupt;
      if (len > cap_ - pos_) return InflateStatus::kOverflow;
      for (size_t i = 0; i < len; ++i)
        if (!put(out_[pos_ - distance])) return InflateStatus::kOverrun;
    }
  }

  InflateStatus fixed() {
    uint8_t lengths[kLitCodes];
    int i = 0;
    for (; i < 144; ++i) lengths[i] = 8;
    for (; i < 256; ++i) lengths[i] = 9;
    for (; i < 280; ++i) lengths[i] = 7;
    for (; i < kLitCodes; ++i) lengths[i] = 8;
    build(lit_, lengths, kLitCodes);
    for (i = 0; i < kDistCodes; ++i) lengths[i] = 5;
    build(dist_, lengths, kDistCodes);
    return codes(lit_, dist_);
  }

  InflateStatus dynamic() {
    static constexpr uint8_t kOrder[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint32_t hlit = 0, hdist = 0, hclen = 0;
    if (!need(5, hlit) || !need(5, hdist) || !need(4, hclen)) return InflateStatus::kCut;
    const int nlit = static_cast<int>(hlit) + 257, ndist = static_cast<int>(hdist) + 1;
    const int nlen = static_cast<int>(hclen) + 4;
    if (nlit > 286 || ndist > 30) return InflateStatus::kCorrupt;
    uint8_t lengths[kLitCodes + kDistCodes] = {};
    for (int i = 0; i < nlen; ++i) {
      uint32_t v = 0;
      if (!need(3, v)) return InflateStatus::kCut;
      lengths[kOrder[i]] = static_cast<uint8_t>(v);
    }
    if (!build(lit_, lengths, 19)) return InflateStatus::kCorrupt;
    for (int i = 0; i < 19; ++i) lengths[i] = 0;
    int n = 0;
    while (n < nlit + ndist) {
      const int sym = decode(lit_);
      if (sym == -1) return InflateStatus::kCut;
      if (sym < 0) return InflateStatus::kCorrupt;
      if (sym < 16) {
        lengths[n++] = static_cast<uint8_t>(sym);
        continue;
      }
      uint8_t value = 0;
      uint32_t repeat = 0;
      if (sym == 16) {
        if (n == 0) return InflateStatus::kCorrupt;
        value = lengths[n - 1];
        if (!need(2, repeat)) return InflateStatus::kCut;
        repeat += 3;
      } else if (sym == 17) {
        if (!need(3, repeat)) return InflateStatus::kCut;
        repeat += 3;
      } else {
        if (!need(7, repeat)) return InflateStatus::kCut;
        repeat += 11;
      }
      if (static_cast<int>(repeat) > nlit + ndist - n) return InflateStatus::kCorrupt;
      while (repeat-- > 0) lengths[n++] = value;
    }
    if (lengths[256] == 0) return InflateStatus::kCorrupt;  // no end-of-block code
    if (!build(lit_, lengths, nlit) || !build(dist_, lengths + nlit, ndist)) return InflateStatus::kCorrupt;
    return codes(lit_, dist_);
  }

  ByteSource in_{nullptr, nullptr};
  uint8_t* out_ = nullptr;
  size_t cap_ = 0;
  size_t pos_ = 0;
  size_t consumed_ = 0;
  uint32_t bits_ = 0;
  int nbits_ = 0;
  long long lead_ = 0;
  bool guard_ = false;
  uintptr_t in_addr_ = 0;
  uintptr_t out_addr_ = 0;
  Code lit_{};
  Code dist_{};
};

}  // namespace minrt
