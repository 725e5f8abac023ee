// A ByteSource that lets its reader look at the start of the input and then
// read it again from the first byte: the board decides a scene's format from
// its first word (a letter starts a CS418 file, a digit or sign an SLD one)
// without losing the bytes, and so without shifting line numbers.
#pragma once

#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt {

class PeekSource {
 public:
  explicit PeekSource(ByteSource in) : in_(in) {}

  // The first byte that is not blank, or -1 at the end of the input (or
  // when more than kKeep blanks come first). The bytes read so far are
  // replayed by source().
  int first_nonblank() {
    if (first_ != kUnknown) return first_;
    first_ = -1;
    while (kept_ < kKeep) {
      const int c = in_.get();
      if (c < 0) break;
      buf_[kept_++] = static_cast<uint8_t>(c);
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
        first_ = c;
        break;
      }
    }
    return first_;
  }

  // The first word: the letters from the first non-blank byte on, lower
  // case, at most `cap - 1` of them, into `out` (empty when the input does
  // not start with a letter). Replayed by source() like the rest.
  void first_word(char* out, int cap) {
    int n = 0;
    int c = first_nonblank();
    while (((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) && n + 1 < cap) {
      out[n++] = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
      if (kept_ >= kKeep) break;
      c = in_.get();
      if (c < 0) break;
      buf_[kept_++] = static_cast<uint8_t>(c);
    }
    out[n] = 0;
  }

  // Reads as far as recognising a format needs (formats/registry.hpp's
  // text_start): a UTF-8 byte-order mark, blanks, the first word (up to a
  // blank, at most `word_cap` bytes), blanks and one more byte; returns how
  // many bytes are kept, at kept(). Never reads past that byte, so a short
  // scene is not waited for. The mark is not replayed by source().
  int peek_start(int word_cap) {
    int i = 0;
    auto at = [&](int k) -> int {  // byte k of the input, read when needed
      while (kept_ <= k && kept_ < kKeep) {
        const int c = in_.get();
        if (c < 0) return -1;
        buf_[kept_++] = static_cast<uint8_t>(c);
      }
      return k < kept_ ? buf_[k] : -1;
    };
    if (at(0) == 0xEF && at(1) == 0xBB && at(2) == 0xBF) {
      i = 3;
      if (pos_ < 3) pos_ = 3;
    }
    auto blank = [](int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (blank(at(i))) ++i;
    for (int n = 0; n < word_cap && at(i) >= 0 && !blank(at(i)); ++n) ++i;
    while (blank(at(i))) ++i;
    at(i);
    return kept_;
  }
  const uint8_t* kept() const { return buf_; }

  ByteSource source() { return ByteSource{&read_fn, this}; }

 private:
  static constexpr int kKeep = 256;
  static constexpr int kUnknown = -2;
  static int read_fn(void* ctx) {
    auto* self = static_cast<PeekSource*>(ctx);
    if (self->pos_ < self->kept_) return self->buf_[self->pos_++];
    return self->in_.get();
  }

  ByteSource in_;
  uint8_t buf_[kKeep];
  int kept_ = 0;
  int pos_ = 0;
  int first_ = kUnknown;
};

}  // namespace minrt
