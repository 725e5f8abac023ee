// Course protocol, shared by the host and the board. Freestanding: no heap,
// no exceptions, only <stdint.h>/<stddef.h> and the core's ByteSource.
//
//   board 0x99            host: program size (u32) + program bytes
//   board 0xaa            host: the scene as 4-byte words (ints and IEEE
//                         floats) in the order min-rt reads its tokens
//   board PPM image, or one MINRT_ERROR_MARKER line (as in the raw protocol)
//
// The scene words are the values min-rt reads, in its order, each an int32
// or an IEEE single as the reader expects it: the host encodes what the SLD
// reader consumes from the text (host/send/course_words.cpp) and the board
// feeds the same reader from the words (course_word_values.hpp).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"

namespace minrt::send::course {

inline constexpr uint8_t kProgramRequest = 0x99;
inline constexpr uint8_t kSceneRequest = 0xaa;

enum class Endian { kLittle, kBig };

inline void put_u32(uint8_t* p, uint32_t v, Endian e) {
  for (int i = 0; i < 4; ++i) p[e == Endian::kLittle ? i : 3 - i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint32_t get_u32(const uint8_t* p, Endian e) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(p[e == Endian::kLittle ? i : 3 - i]) << (8 * i);
  return v;
}

}  // namespace minrt::send::course
