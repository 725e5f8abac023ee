// Where the SLD reader's numbers come from. The reader asks for the next
// integer or real in the original's order and a value source answers: from
// SLD text (SldTextValues: the lexer and the correctly rounded number
// parser) or, on the board, from the course protocol's binary words
// (protocol/course_word_values.hpp), so the same reader, checks and messages
// serve every protocol and the board never turns words back into text.
//
// A source provides:
//   ValueStatus next_int(int64_t& out);
//   ValueStatus next_real(R& out);
//   SourcePos pos() const;                  // of the value just read, or of the end
//   const char* text() const; int length() const;  // its spelling, for messages
#pragma once

#include <stdint.h>

#include "core/base/number_parse.hpp"
#include "core/base/value_status.hpp"
#include "formats/sld/sld_lexer.hpp"

namespace minrt {

template <class R>
class SldTextValues {
 public:
  explicit SldTextValues(ByteSource in) : lex_(in) {}

  ValueStatus next_int(int64_t& out) {
    const ValueStatus st = token();
    if (st != ValueStatus::kOk) return st;
    return from(parse_int(tok_.text, tok_.length, out));
  }
  ValueStatus next_real(R& out) {
    const ValueStatus st = token();
    if (st != ValueStatus::kOk) return st;
    return from(parse_real(tok_.text, tok_.length, out));
  }
  SourcePos pos() const { return at_end_ ? lex_.position() : tok_.pos; }
  const char* text() const { return tok_.text; }
  int length() const { return tok_.length; }

 private:
  ValueStatus token() {
    switch (lex_.next(tok_)) {
      case SldLexer::Result::kToken: return ValueStatus::kOk;
      case SldLexer::Result::kTooLong: return ValueStatus::kTooLong;
      case SldLexer::Result::kEnd: break;
    }
    at_end_ = true;
    return ValueStatus::kEnd;
  }
  static ValueStatus from(NumberStatus st) {
    switch (st) {
      case NumberStatus::kOk: return ValueStatus::kOk;
      case NumberStatus::kOutOfRange: return ValueStatus::kOutOfRange;
      case NumberStatus::kNonFinite: return ValueStatus::kNonFinite;
      default: return ValueStatus::kInvalid;
    }
  }

  SldLexer lex_;
  Token tok_;
  bool at_end_ = false;
};

}  // namespace minrt
