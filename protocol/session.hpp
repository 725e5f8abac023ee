// The session: host-send's handshake with a board that got no boot
// arguments (a real board), both ends' shared pieces. Freestanding: no heap,
// no exceptions, <stdint.h>/<stddef.h> only. The bytes are defined in
// include/minrt/serial_protocol.h (MINRT_SESSION_*); docs/host-send.md
// ("Session") is the reference page.
//
//   host  SYN m r t ?                     greeting (5 bytes)
//   board SYN minrt-board v=1 fw=... crc=XXXXXXXX \n      identity
//   host  SYN o size=WxH format=p3 protocol=raw endian=little crc=XXXXXXXX \n
//   board SYN ok \n                       accepted (or one MINRT_ERROR_MARKER line)
//   then the chosen protocol's exchange, byte for byte as without the
//   session (course: the board's 0x99 comes next).
//
// Identity fields, in this order (a host must ignore fields it does not
// know, so later versions may add some before crc):
//   v         session version (MINRT_SESSION_VERSION)
//   fw        firmware version (the project's)
//   build     CRC-32 of the firmware's code (.text) as 8 hex digits
//   board     the board file's name
//   isa       rv32i, rv32imf, ... (the ISA the firmware was built for)
//   clock     the board's clock in Hz (board key clock_hz), 0 when not known
//   ram       RAM bytes; arena: bytes of the render arena
//   protocols raw,course,framed
//   size      build-time default WxH; format: p3|p6; protocol: raw|course|framed
//   after     serve|halt (board key after_image); wait: polls before giving
//             up on a host (0: never)
// Options fields (each optional; the board's default otherwise):
//   size=WxH  format=p3|p6  protocol=raw|course|framed  endian=little|big
// A field the board does not know is refused with an error line naming it,
// so a host never believes an option took effect when it did not.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/crc32.hpp"

namespace minrt::session {

inline constexpr uint8_t kLead = MINRT_SESSION_LEAD;
inline constexpr size_t kLineMax = MINRT_SESSION_LINE_MAX;
inline constexpr char kCrcField[] = " crc=";

// A session line being written: the lead, the fields, then finish() adds
// the CRC field and '\n'. Text that would overflow is dropped (finish()
// then reports false).
class LineWriter {
 public:
  explicit LineWriter(const char* head) { raw(head); }
  LineWriter& raw(const char* s) {
    while (*s != 0) byte(static_cast<uint8_t>(*s++));
    return *this;
  }
  LineWriter& field(const char* key, const char* value) {
    if (size_ > 1 && buf_[size_ - 1] != ' ') byte(' ');
    return raw(key).raw("=").raw(value);
  }
  LineWriter& field(const char* key, uint32_t value) {
    char digits[11];
    int n = 0;
    do {
      digits[n++] = static_cast<char>('0' + value % 10);
      value /= 10;
    } while (value != 0);
    char text[11];
    for (int i = 0; i < n; ++i) text[i] = digits[n - 1 - i];
    text[n] = 0;
    return field(key, text);
  }
  LineWriter& hex_field(const char* key, uint32_t value) {
    char text[9];
    hex8(value, text);
    text[8] = 0;
    return field(key, text);
  }
  bool finish() {
    const uint32_t crc = crc32(buf_ + 1, size_ - 1);
    raw(kCrcField);
    char text[9];
    hex8(crc, text);
    text[8] = 0;
    raw(text).raw("\n");
    return !overflow_;
  }
  const uint8_t* data() const { return buf_; }
  size_t size() const { return size_; }

  static void hex8(uint32_t v, char* out) {
    static constexpr char kHex[] = "0123456789abcdef";
    for (int i = 7; i >= 0; --i, v >>= 4) out[i] = kHex[v & 0xf];
  }

 private:
  void byte(uint8_t b) {
    if (size_ + 1 < kLineMax) buf_[size_++] = b;
    else overflow_ = true;
  }
  uint8_t buf_[kLineMax] = {};
  size_t size_ = 0;
  bool overflow_ = false;
};

// A received line: `text` from the byte after the lead to the '\n' (not
// included). check() verifies the CRC field; next() walks the fields before
// it as key/value spans.
class LineReader {
 public:
  LineReader(const char* text, size_t size) : text_(text), size_(size) {}

  // True when the line ends in a CRC field that matches the bytes before it.
  bool check() {
    const size_t tail = sizeof kCrcField - 1 + 8;
    if (size_ < tail) return false;
    const size_t at = size_ - tail;
    for (size_t i = 0; i < sizeof kCrcField - 1; ++i)
      if (text_[at + i] != kCrcField[i]) return false;
    uint32_t want = 0;
    for (size_t i = at + sizeof kCrcField - 1; i < size_; ++i) {
      const char c = text_[i];
      const int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
      if (d < 0) return false;
      want = want << 4 | static_cast<uint32_t>(d);
    }
    if (crc32(reinterpret_cast<const uint8_t*>(text_), at) != want) return false;
    end_ = at;
    return true;
  }

  // The first word (before any '='), e.g. "minrt-board" or "o".
  bool head(const char*& word, size_t& n) {
    pos_ = 0;
    while (pos_ < end_ && text_[pos_] != ' ') ++pos_;
    word = text_;
    n = pos_;
    return n > 0;
  }

  // The next `key=value`; false at the end. A field without '=' gives an
  // empty value.
  bool next(const char*& key, size_t& key_n, const char*& value, size_t& value_n) {
    while (pos_ < end_ && text_[pos_] == ' ') ++pos_;
    if (pos_ >= end_) return false;
    const size_t start = pos_;
    while (pos_ < end_ && text_[pos_] != ' ') ++pos_;
    key = text_ + start;
    size_t eq = start;
    while (eq < pos_ && text_[eq] != '=') ++eq;
    key_n = eq - start;
    value = eq < pos_ ? text_ + eq + 1 : text_ + pos_;
    value_n = eq < pos_ ? pos_ - eq - 1 : 0;
    return true;
  }

 private:
  const char* text_;
  size_t size_;
  size_t end_ = 0;
  size_t pos_ = 0;
};

// Whether `s` (n bytes) spells `word`.
inline bool same(const char* s, size_t n, const char* word) {
  size_t i = 0;
  for (; i < n; ++i)
    if (word[i] == 0 || word[i] != s[i]) return false;
  return word[i] == 0;
}

}  // namespace minrt::session
