// Integrity of what the host uploads over the raw and course protocols:
// the scene (with its texture preamble) travels behind its byte count and
// CRC-32, and the board holds it whole and checks it before anything reads
// it, so a damaged upload is refused with one error line instead of being
// rendered. Both ends: the host encodes the header, the board's
// CheckedUpload receives and checks. Freestanding.
//
//   raw     MINRT_SCENE_CHECK_REQUEST, count (u32 LE), CRC-32 (u32 LE), the
//           bytes raw would send before its end-of-input byte. The request
//           also asks for the reply's trailer (raw_check.hpp).
//   course  after 0xaa: kCheckedSceneMarker, count, CRC-32 (words in the
//           chosen byte order), then the scene words as without the check;
//           the reply then carries raw's announce byte and trailer.
//           Program: the length word's top byte is course::kCheckedProgramTag,
//           its low 24 bits the length; the program's CRC-32 follows it
//           (protocol_course_board.hpp checks it).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"
#include "core/base/diagnostic.hpp"
#include "protocol/protocol_course_board.hpp"
#include "protocol/raw_check.hpp"
#include "protocol/text_scene_upload.hpp"
#include "protocol/texture_blobs.hpp"

namespace minrt::send::scene_check {

inline constexpr size_t kRawHeaderSize = 9;       // request byte, count, CRC
// After a checked upload the host sends this many MINRT_END_OF_INPUT bytes,
// which the board does not read when the count arrived whole: when the
// line dropped up to this many bytes, they complete the count and the CRC
// refuses the upload at once instead of after the idle timeout.
inline constexpr size_t kPaddingBytes = 16;
inline constexpr size_t kCourseHeaderSize = 12;   // marker, count, CRC
inline constexpr uint32_t kCheckedSceneMarker = 0x7FF4434B;  // a NaN, like the text-scene marker
static_assert(MINRT_PROGRAM_MAX_SIZE <= course::kProgramLengthMask, "a checked program's length has 24 bits");

inline void put_le32(uint8_t* p, uint32_t v) { course::put_u32(p, v, course::Endian::kLittle); }

// Host: the raw upload's header for `size` bytes with CRC-32 `crc`.
inline void encode_raw_header(uint32_t size, uint32_t crc, uint8_t out[kRawHeaderSize]) {
  out[0] = MINRT_SCENE_CHECK_REQUEST;
  put_le32(out + 1, size);
  put_le32(out + 5, crc);
}

// Host: the course scene header (the words that follow are `size` bytes).
inline void encode_course_header(uint32_t size, uint32_t crc, course::Endian endian,
                                 uint8_t out[kCourseHeaderSize]) {
  course::put_u32(out, kCheckedSceneMarker, endian);
  course::put_u32(out + 4, size, endian);
  course::put_u32(out + 8, crc, endian);
}

enum class Result { kOk, kCut, kTooLarge, kDamaged };

// Board: an upload of known size and CRC-32, held whole at the arena's top
// (it lives as long as the render) and checked before it is handed on.
class CheckedUpload {
 public:
  // After the raw request byte: count and CRC little-endian, then the bytes.
  Result receive_raw(ByteSource in, Arena& arena, Diagnostic& error) {
    uint32_t size = 0, crc = 0;
    if (!word(in, course::Endian::kLittle, size) || !word(in, course::Endian::kLittle, crc)) {
      error.text("scene upload: header cut short");
      return Result::kCut;
    }
    return receive_body(in, size, crc, arena, error);
  }

  // After the course marker word: count and CRC in `endian`, then the bytes.
  Result receive_course(ByteSource in, course::Endian endian, Arena& arena, Diagnostic& error) {
    uint32_t size = 0, crc = 0;
    if (!word(in, endian, size) || !word(in, endian, crc)) {
      error.text("course: scene header cut short");
      return Result::kCut;
    }
    return receive_body(in, size, crc, arena, error);
  }

  bool received() const { return received_; }
  const uint8_t* data() const { return data_; }
  size_t size() const { return size_; }

  // Whether the upload starts with a texture preamble.
  bool has_textures() const { return size_ > 0 && textures::is_marker(data_[0]); }

  // Raw: a texture preamble at the start is read in place (`table` points
  // into the upload, or below it for compressed textures,
  // texture_blobs.hpp); text() then starts after it. False with the reason
  // for a preamble that does not parse or decode.
  bool view_textures(Arena& arena, textures::Table& table, Diagnostic& error) {
    if (!has_textures()) return true;
    size_t used = 0;
    if (!textures::unpack(data_, size_, arena, table, used, error)) return false;
    text_at_ = used;
    return true;
  }

  // The scene text (after any texture preamble viewed above).
  ByteSource text() {
    text_ = MemorySource{data_ + text_at_, size_ - text_at_};
    return text_.source();
  }

 private:
  static bool word(ByteSource in, course::Endian endian, uint32_t& v) {
    uint8_t b[4];
    for (uint8_t& x : b) {
      const int c = in.get();
      if (c < 0) return false;
      x = static_cast<uint8_t>(c);
    }
    v = course::get_u32(b, endian);
    return true;
  }

  Result receive_body(ByteSource in, uint32_t size, uint32_t crc, Arena& arena, Diagnostic& error) {
    uint8_t* dest = size == 0 ? nullptr : arena.alloc_top<uint8_t>(size);
    if (size != 0 && dest == nullptr) {
      error.text("scene upload of ").number(static_cast<int64_t>(size)).text(
          " bytes does not fit in the board's memory (").number(static_cast<int64_t>(arena.top_mark() - arena.used()))
          .text(" bytes free)");
      return Result::kTooLarge;
    }
    uint32_t state = crc32_begin();
    for (uint32_t i = 0; i < size; ++i) {
      const int c = in.get();
      if (c < 0) {
        error.text("scene upload cut short: ").number(static_cast<int64_t>(size - i)).text(" of ").number(
            static_cast<int64_t>(size)).text(" bytes missing");
        return Result::kCut;
      }
      dest[i] = static_cast<uint8_t>(c);
      state = crc32_update(state, dest + i, 1);
    }
    if (crc32_end(state) != crc) {
      error.text("scene upload damaged on the line: CRC-32 mismatch over ").number(static_cast<int64_t>(size))
          .text(" bytes; nothing rendered");
      return Result::kDamaged;
    }
    data_ = dest;
    size_ = size;
    received_ = true;
    return Result::kOk;
  }

  const uint8_t* data_ = nullptr;
  size_t size_ = 0;
  size_t text_at_ = 0;
  bool received_ = false;
  MemorySource text_{nullptr, 0, 0};
};


// Board, course stage 2: the scene's first word tells a checked upload
// (kCheckedSceneMarker: received whole and checked, then read from memory,
// and the reply gets raw's trailer), a text-format upload
// (text_scene_upload.hpp) and SLD words apart.
class CourseScene {
 public:
  // Reads the first word(s) from `in`. False with the reason when a checked
  // upload is cut, too large (too_large()) or damaged: nothing is rendered.
  bool begin(ByteSource in, course::Endian endian, Arena& arena, raw_check::CheckedSink& reply, Diagnostic& error) {
    endian_ = endian;
    in_ = in;
    got_ = first_word(in_, first_);
    if (got_ == 4 && course::get_u32(first_, endian) == kCheckedSceneMarker) {
      const Result r = upload_.receive_course(in, endian, arena, error);
      too_large_ = r == Result::kTooLarge;
      if (r != Result::kOk) return false;
      reply.request();
      in_ = upload_.text();
      got_ = first_word(in_, first_);
    }
    return true;
  }

  bool too_large() const { return too_large_; }
  bool is_text() const { return got_ == 4 && text::is_marker(first_, endian_); }

  // SLD words from the first one on.
  ByteSource words() {
    replay_ = text::PrefixSource(first_, got_, in_);
    return replay_.source();
  }

  // A text-format upload: viewed in place when it came checked, otherwise
  // read into the arena (text::read_course).
  bool text_scene(Arena& arena, text::TextScene& scene, bool& too_large, Diagnostic& error) {
    too_large = false;
    if (!upload_.received()) return text::read_course(in_, endian_, arena, scene, too_large, error);
    const uint8_t* p = upload_.data() + 4;
    const size_t size = upload_.size() - 4;
    if (size < 8) {
      error.text("course: scene header cut short");
      return false;
    }
    scene.format = course::get_u32(p, endian_);
    const uint32_t n = course::get_u32(p + 4, endian_);
    if (!text::is_text_format(scene.format)) {
      error.text("course: unknown scene format ").number(static_cast<int64_t>(scene.format));
      return false;
    }
    if (n > size - 8) {
      error.text("course: scene header says ").number(static_cast<int64_t>(n)).text(" bytes, ").number(
          static_cast<int64_t>(size - 8)).text(" arrived");
      return false;
    }
    scene.bytes = p + 8;
    scene.size = n;
    return true;
  }

 private:
  static int first_word(ByteSource in, uint8_t* out) {
    int got = 0;
    for (int c; got < 4 && (c = in.get()) >= 0;) out[got++] = static_cast<uint8_t>(c);
    return got;
  }

  CheckedUpload upload_;
  course::Endian endian_ = course::Endian::kLittle;
  ByteSource in_{nullptr, nullptr};
  uint8_t first_[4] = {};
  int got_ = 0;
  bool too_large_ = false;
  text::PrefixSource replay_{nullptr, 0, ByteSource{nullptr, nullptr}};
};

}  // namespace minrt::send::scene_check
