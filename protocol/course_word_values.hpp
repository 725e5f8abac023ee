// Board side of the course protocol's scene: the SLD reader's value source
// over the 4-byte words the host sends (formats/sld/sld_values.hpp). The
// reader says whether it wants an integer or a real, so the word layout
// needs no table of its own: the host encodes exactly the values the same
// reader consumed from the text (host/send/course_words.cpp).
#pragma once

#include <stdint.h>

#include "core/base/bit_cast.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"  // SourcePos
#include "core/base/value_status.hpp"
#include "protocol/protocol_course.hpp"

namespace minrt::send::course {

template <class R>
class CourseWordValues {
 public:
  CourseWordValues(ByteSource words, Endian endian) : words_(words), endian_(endian) {}

  ValueStatus next_int(int64_t& out) {
    uint32_t w = 0;
    if (!word(w)) return ValueStatus::kEnd;
    out = static_cast<int32_t>(w);  // every word is a valid integer
    return ValueStatus::kOk;
  }
  ValueStatus next_real(R& out) {
    uint32_t w = 0;
    if (!word(w)) return ValueStatus::kEnd;
    const float f = bit_cast<float>(w);
    if (f - f != f - f) {  // inf or nan: what the text reader calls non-finite
      set_text(f != f ? "nan" : (w >> 31 ? "-inf" : "inf"));
      return ValueStatus::kNonFinite;
    }
    out = static_cast<R>(f);
    set_text("");
    return ValueStatus::kOk;
  }
  // Words have no lines: line 1, column = the word's number (from 1).
  SourcePos pos() const { return SourcePos{1, count_}; }
  const char* text() const { return text_; }
  int length() const { return length_; }

 private:
  bool word(uint32_t& w) {
    uint8_t b[4];
    for (uint8_t& x : b) {
      const int c = words_.get();
      if (c < 0) return false;
      x = static_cast<uint8_t>(c);
    }
    ++count_;
    w = get_u32(b, endian_);
    return true;
  }
  void set_text(const char* s) {
    length_ = 0;
    while (s[length_] != 0) text_[length_] = s[length_], ++length_;
    text_[length_] = 0;
  }

  ByteSource words_;
  Endian endian_;
  int count_ = 0;
  char text_[16] = {};
  int length_ = 0;
};

}  // namespace minrt::send::course
