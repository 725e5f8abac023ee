// One error or warning about the input, with where it happened, built
// without printf so the core stays freestanding.
#pragma once

#include "core/base/text_numbers.hpp"

#include <stdint.h>

namespace minrt {

struct SourcePos {
  int line = 1;
  int col = 1;
};

struct Diagnostic {
  SourcePos pos;
  bool has_pos = false;
  char message[200] = {};
  int length = 0;
  // The input did not fit the memory it was given: the same input may be
  // read with a larger arena (the host grows it and tries again).
  bool out_of_memory = false;

  Diagnostic& text(const char* s) {
    while (*s != 0 && length + 1 < static_cast<int>(sizeof message)) message[length++] = *s++;
    message[length] = 0;
    return *this;
  }
  Diagnostic& number(int64_t v) {
    char out[21];
    out[format_decimal(v, out)] = 0;
    return text(out);
  }
  // Quotes a token, escaping bytes that would garble a terminal and
  // shortening long ones.
  Diagnostic& quoted(const char* s, int n) {
    static constexpr char kHex[] = "0123456789abcdef";
    constexpr int kShown = 24;
    text("'");
    for (int i = 0; i < n && i < kShown; ++i) {
      const auto c = static_cast<unsigned char>(s[i]);
      if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
        const char one[2] = {static_cast<char>(c), 0};
        text(one);
      } else {
        const char esc[5] = {'\\', 'x', kHex[c >> 4], kHex[c & 15], 0};
        text(esc);
      }
    }
    if (n > kShown) text("...");
    return text("'");
  }
};

// Receives warnings (the input is accepted but odd); errors are returned.
struct WarningSink {
  void (*warn)(void* ctx, const Diagnostic& d) = nullptr;
  void* ctx = nullptr;

  void emit(const Diagnostic& d) const {
    if (warn != nullptr) warn(ctx, d);
  }
};

}  // namespace minrt
