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

  // One more byte into the kept bytes, for a reader of the start that
  // needs more (formats/registry.hpp's text_start says when it has enough):
  // false at the end of the input or when kKeep bytes are kept. A UTF-8
  // byte-order mark at the very start is kept but not replayed by source().
  bool extend() {
    if (kept_ >= kKeep) return false;
    const int c = in_.get();
    if (c < 0) return false;
    buf_[kept_++] = static_cast<uint8_t>(c);
    if (kept_ == 3 && buf_[0] == 0xEF && buf_[1] == 0xBB && buf_[2] == 0xBF && pos_ < 3) pos_ = 3;
    return true;
  }
  int kept_count() const { return kept_; }
  const uint8_t* kept() const { return buf_; }

  ByteSource source() { return ByteSource{&read_fn, this}; }

 private:
  static constexpr int kKeep = 1024;  // room for a comment header before the first word
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
