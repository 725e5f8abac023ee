// Tokens of an (already preprocessed) EASTRAY scene: words separated by
// blanks (manual line 27), with `; [ ] { } ( ) < >` always tokens of their
// own (the manual asks for blanks around them, line 982; we do not insist).
// `/* */` comments are skipped here too, so unexpanded text still reads.
// The whole text is in memory: parts are read again at every call.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/diagnostic.hpp"

namespace minrt::eastray {

struct Token {
  const char* s = nullptr;
  int length = 0;      // 0 at the end of the text
  SourcePos pos;
  bool bad_comment = false;  // an unterminated comment starts here
  size_t offset = 0;         // where it starts in the text

  bool is(const char* w) const {
    int i = 0;
    for (; i < length; ++i)
      if (w[i] == 0 || w[i] != s[i]) return false;  // a NUL inside the token ends no word
    return w[i] == 0;
  }
  bool is(char c) const { return length == 1 && s[0] == c; }
  bool end() const { return length == 0; }
};

class Lexer {
 public:
  struct Mark {
    size_t offset;
    SourcePos pos;
  };

  Lexer(const char* text, size_t size) : text_(text), size_(size) {}

  Mark mark() const { return Mark{offset_, pos_}; }
  // Where `t` starts: seek there and next() gives `t` again.
  static Mark at(const Token& t) { return Mark{t.offset, t.pos}; }
  void seek(const Mark& m) {
    offset_ = m.offset;
    pos_ = m.pos;
  }

  Token next() {
    Token t;
    for (;;) {
      while (offset_ < size_ && blank(text_[offset_])) step();
      if (offset_ + 1 < size_ && text_[offset_] == '/' && text_[offset_ + 1] == '*') {
        const SourcePos start = pos_;
        step();
        step();
        while (offset_ + 1 < size_ && !(text_[offset_] == '*' && text_[offset_ + 1] == '/')) step();
        if (offset_ + 1 >= size_) {
          offset_ = size_;
          t.pos = start;
          t.bad_comment = true;
          t.s = text_ + size_;
          return t;
        }
        step();
        step();
        continue;
      }
      break;
    }
    t.pos = pos_;
    t.offset = offset_;
    t.s = text_ + offset_;
    if (offset_ >= size_) return t;
    if (single(text_[offset_])) {
      step();
      t.length = 1;
      return t;
    }
    while (offset_ < size_ && !blank(text_[offset_]) && !single(text_[offset_]) &&
           !(text_[offset_] == '/' && offset_ + 1 < size_ && text_[offset_ + 1] == '*'))
      step();
    t.length = static_cast<int>(text_ + offset_ - t.s);
    return t;
  }

 private:
  static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f' || c == ','; }
  static bool single(char c) {
    return c == ';' || c == '[' || c == ']' || c == '{' || c == '}' || c == '(' || c == ')' || c == '<' || c == '>';
  }
  void step() {
    if (text_[offset_] == '\n') {
      ++pos_.line;
      pos_.col = 1;
    } else {
      ++pos_.col;
    }
    ++offset_;
  }

  const char* text_;
  size_t size_;
  size_t offset_ = 0;
  SourcePos pos_;
};

}  // namespace minrt::eastray
