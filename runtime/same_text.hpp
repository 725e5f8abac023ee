// Byte-for-byte equality of two NUL-terminated strings: the board has no
// libc strcmp, and its format detection and argument parser need one.
#pragma once

namespace minrt::fw {

inline bool same_text(const char* a, const char* b) {
  while (*a != 0 && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

}  // namespace minrt::fw
