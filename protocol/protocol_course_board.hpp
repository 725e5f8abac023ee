// Course protocol, board side: the two stages as the firmware (runtime/)
// and the stand-in board (test/host_send) both run them. Freestanding like
// protocol_course.hpp: no heap, no exceptions, <stdint.h>/<stddef.h> only.
//
//   stage 1  send 0x99, read the program (u32 length + bytes)
//   stage 2  send 0xaa, render the scene words; an error goes out as one
//            MINRT_ERROR_MARKER line
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"
#include "core/base/diagnostic.hpp"
#include "protocol/course_word_values.hpp"
#include "protocol/protocol_course.hpp"

namespace minrt::send::course {

// MINRT_ERROR_MARKER, "LINE:COL: " when the error has a position, the
// message, '\n' (the raw protocol's error line).
inline void write_error_line(ByteSink out, const Diagnostic& error) {
  Diagnostic where;
  if (error.has_pos) where.number(error.pos.line).text(":").number(error.pos.col).text(": ");
  const char marker[] = MINRT_ERROR_MARKER;
  out.put(reinterpret_cast<const uint8_t*>(marker), sizeof marker - 1);
  out.put(reinterpret_cast<const uint8_t*>(where.message), static_cast<size_t>(where.length));
  out.put(reinterpret_cast<const uint8_t*>(error.message), static_cast<size_t>(error.length));
  out.put(reinterpret_cast<const uint8_t*>("\n"), 1);
}

enum class ProgramResult { kReceived, kNoLength, kTooLarge, kCut, kDamaged };

// A checked program's length word: this tag in the top byte, the length in
// the low 24 bits, and the program's CRC-32 (a word) after its bytes
// (protocol/scene_check.hpp). The course's own length word never has it:
// no program region comes near 2^24 bytes.
inline constexpr uint32_t kCheckedProgramTag = 0xC5;
inline constexpr uint32_t kProgramLengthMask = 0x00FFFFFF;

// Stage 1: sends 0x99 and reads the program length, then the bytes into
// `dest` (nullptr: read and dropped). A length above `capacity` is refused
// before any program byte is read; a checked program whose CRC-32 differs
// is refused after it (the caller must not start it). On failure the error
// line has been sent and `error` holds its text.
inline ProgramResult receive_program(ByteSource in, ByteSink out, Endian endian, uint8_t* dest, uint32_t capacity,
                                     uint32_t& length, Diagnostic& error) {
  out.put(&kProgramRequest, 1);
  uint8_t len[4];
  auto read_word = [&](uint8_t* w) {
    for (int k = 0; k < 4; ++k) {
      const int c = in.get();
      if (c < 0) return false;
      w[k] = static_cast<uint8_t>(c);
    }
    return true;
  };
  if (!read_word(len)) {
    error.text("course: no program size from the host");
    write_error_line(out, error);
    return ProgramResult::kNoLength;
  }
  length = get_u32(len, endian);
  const bool checked = (length >> 24) == kCheckedProgramTag;
  if (checked) length &= kProgramLengthMask;
  if (length > capacity) {
    error.text("course: program of ")
        .number(length)
        .text(" bytes does not fit the board's ")
        .number(capacity)
        .text("-byte program region");
    write_error_line(out, error);
    return ProgramResult::kTooLarge;
  }
  uint32_t state = crc32_begin();
  for (uint32_t i = 0; i < length; ++i) {
    const int c = in.get();
    if (c < 0) {
      error.text("course: program ended early, ").number(length - i).text(" of ").number(length).text(" bytes missing");
      write_error_line(out, error);
      return ProgramResult::kCut;
    }
    const uint8_t b = static_cast<uint8_t>(c);
    if (checked) state = crc32_update(state, &b, 1);
    if (dest != nullptr) dest[i] = b;
  }
  if (checked) {
    uint8_t sum[4];
    if (!read_word(sum)) {
      error.text("course: program's CRC-32 cut short");
      write_error_line(out, error);
      return ProgramResult::kCut;
    }
    if (get_u32(sum, endian) != crc32_end(state)) {
      error.text("course: program damaged on the line: CRC-32 mismatch over ").number(length).text(
          " bytes; not started");
      write_error_line(out, error);
      return ProgramResult::kDamaged;
    }
  }
  return ProgramResult::kReceived;
}

// Stage 2: sends 0xaa and hands `render` the line the scene words arrive on
// (read them with CourseWordValues). `render(ByteSource words)` returns false
// with the reason in `error`, which then goes out as the error line.
template <class Render>
bool serve_scene(ByteSource in, ByteSink out, Render&& render, Diagnostic& error) {
  out.put(&kSceneRequest, 1);
  if (render(in)) return true;
  write_error_line(out, error);
  return false;
}

}  // namespace minrt::send::course
