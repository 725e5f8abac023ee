// Small decimal conversions for command lines and reports, the same on the
// host and the board: unsigned decimal digits in, decimal digits out.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/limits.hpp>

namespace minrt {

// Decimal digits of `s` up to `stop` (or the end of the string), advancing
// `s` to the stop; false when there are none, on any other byte, or when the
// value exceeds `max`.
inline bool parse_decimal(const char*& s, char stop, uint32_t max, uint32_t& value) {
  const char* start = s;
  uint32_t v = 0;
  for (; *s != 0 && *s != stop; ++s) {
    if (*s < '0' || *s > '9') return false;
    const uint32_t digit = static_cast<uint32_t>(*s - '0');
    if (v > (max - digit) / 10) return false;
    v = v * 10 + digit;
  }
  value = v;
  return s != start;
}

// "WxH" (or "WXH") within the image limits; the one size syntax of minrt,
// host-send and the firmware.
inline bool parse_size(const char* s, int& width, int& height) {
  uint32_t w = 0, h = 0;
  const char* p = s;
  const char* q = s;
  while (*q != 0 && *q != 'x' && *q != 'X') ++q;
  if (*q == 0) return false;
  const char sep = *q;
  if (!parse_decimal(p, sep, limits::kMaxImageWidth, w) || *p++ != sep) return false;
  if (!parse_decimal(p, 0, limits::kMaxImageHeight, h) || w == 0 || h == 0) return false;
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

// Writes the decimal digits of `x` to `out` (10 bytes suffice); returns the
// count, no terminator. 32-bit division by 10 is one instruction with RV32M.
inline size_t format_decimal_u32(uint32_t x, char* out) {
  char digits[10];
  size_t k = 0;
  do {
    digits[k++] = static_cast<char>('0' + x % 10);
    x /= 10;
  } while (x != 0);
  size_t n = 0;
  while (k > 0) out[n++] = digits[--k];
  return n;
}

// Writes the decimal digits of `v` (with '-' when negative) to `out`, which
// needs 20 bytes; returns the count, no terminator. With format_decimal_u32
// the one integer formatter of the project (PPM pixels, diagnostics,
// reports). Values beyond 32 bits subtract powers of ten, so a 32-bit
// target never calls a 64-bit division routine.
inline size_t format_decimal(int64_t v, char* out) {
  uint64_t u = v < 0 ? 0 - static_cast<uint64_t>(v) : static_cast<uint64_t>(v);
  size_t n = 0;
  if (v < 0) out[n++] = '-';
  if (u <= 0xFFFFFFFFu) return n + format_decimal_u32(static_cast<uint32_t>(u), out + n);
  uint64_t power[20];  // 10^0 .. 10^19, by multiplication only
  power[0] = 1;
  for (int i = 1; i < 20; ++i) power[i] = power[i - 1] * 10;
  bool started = false;
  for (int i = 19; i >= 0; --i) {
    char d = '0';
    while (u >= power[i]) {
      u -= power[i];
      ++d;
    }
    if (d != '0' || started) {
      out[n++] = d;
      started = true;
    }
  }
  return n;  // u > 0xFFFFFFFF here, so some digit was written
}

}  // namespace minrt
