// The raw protocol's CRC-32 trailer (include/minrt/serial_protocol.h), both
// ends of its byte layout: the board's sink that announces the trailer and
// appends it, and the encoding the host decodes. Freestanding, so the
// firmware and the stand-in board run the same code.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"

namespace minrt::send::raw_check {

inline constexpr size_t kTrailerSize = MINRT_CHECK_TRAILER_SIZE;
inline constexpr size_t kMagicSize = 4;
static_assert(sizeof(MINRT_CHECK_TRAILER_MAGIC) - 1 == kMagicSize, "trailer magic is 4 bytes");
static_assert(kTrailerSize == kMagicSize + 8, "trailer: magic, byte count, CRC-32");

// The trailer of an image of `bytes` bytes with CRC-32 `crc`.
inline void encode_trailer(uint32_t bytes, uint32_t crc, uint8_t out[kTrailerSize]) {
  for (size_t i = 0; i < kMagicSize; ++i) out[i] = static_cast<uint8_t>(MINRT_CHECK_TRAILER_MAGIC[i]);
  for (int i = 0; i < 4; ++i) {
    out[kMagicSize + i] = static_cast<uint8_t>(bytes >> (8 * i));
    out[kMagicSize + 4 + i] = static_cast<uint8_t>(crc >> (8 * i));
  }
}

// Decodes a trailer; false when the magic is wrong.
inline bool decode_trailer(const uint8_t in[kTrailerSize], uint32_t& bytes, uint32_t& crc) {
  for (size_t i = 0; i < kMagicSize; ++i)
    if (in[i] != static_cast<uint8_t>(MINRT_CHECK_TRAILER_MAGIC[i])) return false;
  bytes = 0;
  crc = 0;
  for (int i = 0; i < 4; ++i) {
    bytes |= static_cast<uint32_t>(in[kMagicSize + i]) << (8 * i);
    crc |= static_cast<uint32_t>(in[kMagicSize + 4 + i]) << (8 * i);
  }
  return true;
}

// Board side: a sink in front of the image's sink. When the host asked for
// the trailer, the first image byte goes out after MINRT_CHECK_ANNOUNCE and
// end() appends the trailer; otherwise it passes bytes through untouched.
class CheckedSink {
 public:
  CheckedSink(ByteSink out, bool requested) : out_(out), requested_(requested) {}

  ByteSink sink() { return requested_ ? ByteSink{&write_fn, this} : out_; }

  // The host asked after construction (the course protocol's checked scene,
  // scene_check.hpp); before the first image byte.
  void request() { requested_ = true; }

  // After a complete image: the trailer (nothing when not requested or when
  // no image byte was written, as for an error line sent elsewhere).
  void end() {
    if (!requested_ || !started_) return;
    uint8_t trailer[kTrailerSize];
    encode_trailer(bytes_, crc32_end(state_), trailer);
    out_.put(trailer, kTrailerSize);
  }

 private:
  static void write_fn(void* ctx, const uint8_t* data, size_t size) {
    auto* self = static_cast<CheckedSink*>(ctx);
    if (size == 0) return;
    if (!self->started_) {
      const uint8_t announce = MINRT_CHECK_ANNOUNCE;
      self->out_.put(&announce, 1);
      self->started_ = true;
    }
    self->state_ = crc32_update(self->state_, data, size);
    self->bytes_ += static_cast<uint32_t>(size);
    self->out_.put(data, size);
  }

  ByteSink out_;
  bool requested_;
  bool started_ = false;
  uint32_t bytes_ = 0;
  uint32_t state_ = crc32_begin();
};

}  // namespace minrt::send::raw_check
