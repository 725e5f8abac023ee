// Line-oriented text scenes (CS418, miniRT): a line at a time from a
// ByteSource into the reader's fixed buffer, then split into words. The
// checks every such format needs live here once: a NUL byte (a binary file
// given by mistake) and a line longer than the buffer, which is refused,
// never cut. Each reader words its own messages.
#pragma once

#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt::text {

enum class LineRead : uint8_t {
  kLine,     // a line, possibly empty, in buf[0, length)
  kEnd,      // no byte was left
  kNulByte,  // a NUL byte at column length + 1
  kTooLong,  // more than `capacity` bytes before the newline; reading stopped at the first one over
};

// Reads up to and without the '\n' (the last line may lack it). `at_end`
// becomes true once the input has run out.
inline LineRead read_line(ByteSource& in, char* buf, int capacity, int& length, bool& at_end) {
  length = 0;
  bool got_any = false;
  for (;;) {
    const int c = in.get();
    if (c < 0) {
      at_end = true;
      return got_any ? LineRead::kLine : LineRead::kEnd;
    }
    got_any = true;
    if (c == '\n') return LineRead::kLine;
    if (c == 0) return LineRead::kNulByte;
    if (length == capacity) return LineRead::kTooLong;
    buf[length++] = static_cast<char>(c);
  }
}

// Words are separated by spaces or tabs; a CR before the newline (a file
// saved on Windows) is white space too, and so are VT and FF.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

struct Word {
  int start;   // 0-based column of its first byte
  int length;
};

// Splits buf[0, length) into words, storing the first `max_words`. Returns
// how many the line has (more than max_words when some were not stored);
// `first_unstored` is then where the first of those starts.
inline int split_words(const char* buf, int length, Word* words, int max_words, int& first_unstored) {
  int total = 0;
  int i = 0;
  for (;;) {
    while (i < length && is_blank(buf[i])) ++i;
    if (i == length) return total;
    const int start = i;
    while (i < length && !is_blank(buf[i])) ++i;
    if (total < max_words) words[total] = Word{start, i - start};
    else if (total == max_words) first_unstored = start;
    ++total;
  }
}

// Whether word `w` of `buf` is exactly the NUL-terminated `s`.
inline bool word_is(const char* buf, const Word& w, const char* s) {
  int k = 0;
  for (; k < w.length; ++k)
    if (s[k] == 0 || s[k] != buf[w.start + k]) return false;
  return s[k] == 0;
}

}  // namespace minrt::text
