// How a scene in one of the text formats (CS418, Jaworski, miniRT, EASTRAY)
// travels over the course and framed protocols, shared by host and board.
// Freestanding: <stdint.h>/<stddef.h> and the core's base only.
//
//   word 0  kTextSceneMarker, a NaN bit pattern
//   word 1  the format's tag (formats/registry.hpp, Format::wire_tag)
//   word 2  N, the number of bytes that follow
//   N bytes exactly what the raw protocol sends before its 0x04: for CS418
//           and miniRT the texture preamble when the scene names textures
//           (include/minrt/serial_protocol.h), then the scene text (EASTRAY:
//           as host-send's preprocessor expanded it)
//
// Course: after 0xaa, in place of the SLD words; words in the chosen byte
// order, the N bytes zero-padded to a multiple of 4 so that everything after
// 0xaa stays whole words. The marker cannot begin an SLD scene: min-rt's
// first value is a real and the reader refuses a non-finite one, so the SLD
// word layout is untouched. Framed: the same 12-byte header, little-endian,
// then the N bytes, is the payload the S frames carry (an SLD text never
// starts with the marker's bytes 54 58 F4 7F). The length is explicit, so
// the text may hold any byte, 0x04 included.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "protocol/protocol_course.hpp"

namespace minrt::send::text {

inline constexpr uint32_t kTextSceneMarker = 0x7FF45854;  // exponent all ones, mantissa non-zero: NaN
inline constexpr size_t kHeaderBytes = 12;

// A tag a text format may have (which format it names is the registry's
// business, formats/registry.hpp; the board refuses one it does not know).
inline bool is_text_format(uint32_t tag) { return tag != MINRT_SCENE_FORMAT_SLD && tag < MINRT_SCENE_FORMAT_TAG_LIMIT; }

// The scene bytes as they arrived (texture preamble and text), in memory.
struct TextScene {
  uint32_t format = 0;
  const uint8_t* bytes = nullptr;
  size_t size = 0;
};

inline void put_header(uint8_t* p, uint32_t format, uint32_t size, course::Endian endian) {
  course::put_u32(p, kTextSceneMarker, endian);
  course::put_u32(p + 4, format, endian);
  course::put_u32(p + 8, size, endian);
}

inline bool is_marker(const uint8_t* p, course::Endian endian) {
  return course::get_u32(p, endian) == kTextSceneMarker;
}

// Framed: `data` is the whole collected upload. False when it does not
// start with the marker (an SLD text); otherwise `ok` says whether the
// header is sound (false with the reason in `error`).
inline bool view_framed(const uint8_t* data, size_t size, TextScene& scene, bool& ok, Diagnostic& error) {
  if (size < 4 || !is_marker(data, course::Endian::kLittle)) return false;
  ok = false;
  if (size < kHeaderBytes) {
    error.text("scene upload: header cut short");
    return true;
  }
  scene.format = course::get_u32(data + 4, course::Endian::kLittle);
  const uint32_t n = course::get_u32(data + 8, course::Endian::kLittle);
  if (!is_text_format(scene.format)) {
    error.text("scene upload: unknown scene format ").number(static_cast<int64_t>(scene.format));
    return true;
  }
  if (n != size - kHeaderBytes) {
    error.text("scene upload: header says ").number(static_cast<int64_t>(n)).text(" bytes, ").number(
        static_cast<int64_t>(size - kHeaderBytes)).text(" arrived");
    return true;
  }
  scene.bytes = data + kHeaderBytes;
  scene.size = n;
  ok = true;
  return true;
}

// Course: the rest of the header after the marker word, then the bytes,
// which go to the arena's top end (released by nobody: they live as long
// as the render). False with the reason in `error`; `too_large` tells a
// scene that does not fit from one that was cut short.
inline bool read_course(ByteSource in, course::Endian endian, Arena& arena, TextScene& scene, bool& too_large,
                        Diagnostic& error) {
  too_large = false;
  uint8_t w[8];
  for (uint8_t& b : w) {
    const int c = in.get();
    if (c < 0) {
      error.text("course: scene header cut short");
      return false;
    }
    b = static_cast<uint8_t>(c);
  }
  scene.format = course::get_u32(w, endian);
  const uint32_t n = course::get_u32(w + 4, endian);
  if (!is_text_format(scene.format)) {
    error.text("course: unknown scene format ").number(static_cast<int64_t>(scene.format));
    return false;
  }
  uint8_t* dest = n == 0 ? nullptr : arena.alloc_top<uint8_t>(n);
  if (n != 0 && dest == nullptr) {
    too_large = true;
    error.text("scene of ").number(static_cast<int64_t>(n)).text(" bytes does not fit in the board's memory (")
        .number(static_cast<int64_t>(arena.top_mark() - arena.used())).text(" bytes free)");
    return false;
  }
  const uint32_t padded = (n + 3u) & ~3u;
  for (uint32_t i = 0; i < padded; ++i) {
    const int c = in.get();
    if (c < 0) {
      error.text("course: scene ended early, ").number(static_cast<int64_t>(padded - i)).text(" of ").number(
          static_cast<int64_t>(padded)).text(" bytes missing");
      return false;
    }
    if (i < n) dest[i] = static_cast<uint8_t>(c);
  }
  scene.bytes = dest;
  scene.size = n;
  return true;
}

// A source that gives back the bytes already taken from `rest` (at most 4:
// the word the board looked at to tell text from SLD), then `rest`.
class PrefixSource {
 public:
  PrefixSource(const uint8_t* prefix, int count, ByteSource rest) : rest_(rest), count_(count) {
    for (int i = 0; i < count && i < 4; ++i) prefix_[i] = prefix[i];
  }
  ByteSource source() { return ByteSource{&read_fn, this}; }

 private:
  static int read_fn(void* ctx) {
    auto* self = static_cast<PrefixSource*>(ctx);
    if (self->at_ < self->count_) return self->prefix_[self->at_++];
    return self->rest_.get();
  }
  ByteSource rest_;
  uint8_t prefix_[4] = {};
  int count_;
  int at_ = 0;
};

}  // namespace minrt::send::text
