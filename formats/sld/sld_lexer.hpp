// Splits SLD input into tokens exactly where the original reader does: only
// space, tab, CR and LF separate tokens; every other byte belongs to one.
// Tracks the line and column of each token for error messages.
#pragma once

#include "formats/sld/sld_limits.hpp"

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"

namespace minrt {

struct Token {
  char text[limits::kMaxTokenLength + 1];
  int length = 0;
  SourcePos pos;
};

class SldLexer {
 public:
  enum class Result { kToken, kEnd, kTooLong };

  explicit SldLexer(ByteSource in) : in_(in) {}

  Result next(Token& tok) {
    int c = in_.get();
    advance(c);
    while (is_separator(c)) {
      c = in_.get();
      advance(c);
    }
    tok.length = 0;
    tok.pos = token_start_;
    if (c < 0) return Result::kEnd;
    while (c >= 0 && !is_separator(c)) {
      if (tok.length == limits::kMaxTokenLength) return Result::kTooLong;
      tok.text[tok.length++] = static_cast<char>(c);
      c = in_.get();
      advance(c);
    }
    tok.text[tok.length] = 0;
    return Result::kToken;
  }

  // Where the reader stands: the end-of-input position after kEnd.
  SourcePos position() const { return here_; }

 private:
  static bool is_separator(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

  // Called for each byte read; token_start_ is the position of byte `c`.
  void advance(int c) {
    token_start_ = here_;
    if (c == '\n') {
      ++here_.line;
      here_.col = 1;
    } else if (c >= 0) {
      ++here_.col;
    }
  }

  ByteSource in_;
  SourcePos here_;
  SourcePos token_start_;
};

}  // namespace minrt
