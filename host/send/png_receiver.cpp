#include "png_receiver.hpp"

#include <cstdio>
#include <cstring>

#include <minrt/serial_protocol.h>

#include "core/base/crc32.hpp"

namespace minrt::send {

namespace {
constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
// The writer's chunks are one row (4W + 6 bytes per 64 KiB block) at most.
constexpr std::uint32_t kMaxChunk = 1u << 24;
static_assert(static_cast<std::uint32_t>(MINRT_ERROR_MARKER[0]) << 24 > kMaxChunk,
              "an error line between chunks cannot start a chunk's length");

std::uint32_t be32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
         static_cast<std::uint32_t>(p[2]) << 8 | p[3];
}
}  // namespace

std::size_t PngReceiver::feed(const std::uint8_t* data, std::size_t size) {
  std::size_t i = 0;
  while (i < size) {
    if (ended()) break;
    const bool more = step(data[i]);
    ++i;
    ++bytes_;
    if (!more) break;
  }
  return i;
}

bool PngReceiver::chunk_done() {
  const std::uint32_t want = be32(crc_bytes_);
  if (crc32_end(crc_) != want) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "PNG chunk %.4s after %llu bytes has a bad CRC-32: the line damaged it",
                  reinterpret_cast<const char*>(head_ + 4), static_cast<unsigned long long>(bytes_));
    return fail(buf);
  }
  const char* type = reinterpret_cast<const char*>(head_ + 4);
  if (std::memcmp(type, "IHDR", 4) == 0) {
    const int w = static_cast<int>(be32(ihdr_)), h = static_cast<int>(be32(ihdr_ + 4));
    if (w != width_ || h != height_) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "the board sent a %dx%d image, the scene asks for %dx%d", w, h, width_, height_);
      return fail(buf);
    }
    seen_ihdr_ = true;
  } else if (!seen_ihdr_) {
    return fail("PNG stream does not start with IHDR");
  } else if (std::memcmp(type, "IDAT", 4) == 0) {
    ++rows_;
  } else if (std::memcmp(type, "IEND", 4) == 0) {
    state_ = State::kDone;
    return false;
  }
  at_ = 0;
  return true;
}

bool PngReceiver::step(std::uint8_t c) {
  switch (state_) {
    case State::kStart:
      if (!start(c, kSignature[0], "PNG")) return false;
      if (state_ == State::kHeader) at_ = 1;
      return true;
    case State::kHeader:
      if (c != kSignature[at_]) return fail("reply is not a PNG stream (bad signature)");
      if (++at_ == sizeof kSignature) {
        state_ = State::kBody;
        at_ = 0;
      }
      return true;
    case State::kBody: {
      // A board that stops between rows (a texel of a sparse texture not
      // sent, MINRT_UNSENT_TEXEL_ERROR) sends its error line there; no
      // chunk's length starts with that byte (they are below kMaxChunk).
      if (at_ == 0 && c == static_cast<std::uint8_t>(MINRT_ERROR_MARKER[0]) && seen_ihdr_) {
        state_ = State::kStart;
        return start(c, kSignature[0], "PNG");
      }
      if (at_ < 8) {
        head_[at_++] = c;
        if (at_ == 8) {
          length_ = be32(head_);
          if (length_ > kMaxChunk) return fail("PNG chunk longer than the board can send: the line damaged it");
          crc_ = crc32_update(crc32_begin(), head_ + 4, 4);
        }
        return true;
      }
      const std::size_t in_data = at_ - 8;
      if (in_data < length_) {
        crc_ = crc32_update(crc_, &c, 1);
        if (std::memcmp(head_ + 4, "IHDR", 4) == 0 && in_data < sizeof ihdr_) ihdr_[in_data] = c;
        ++at_;
        return true;
      }
      crc_bytes_[in_data - length_] = c;
      ++at_;
      if (in_data - length_ == 3) return chunk_done();
      return true;
    }
    case State::kErrorLine:
      return error_line_step(c);
    default:
      return false;
  }
}

void PngReceiver::finish() {
  if (ended() || fail_if_no_image()) return;
  char buf[160];
  std::snprintf(buf, sizeof buf, "PNG stream is truncated: %d of %d rows after %llu bytes", rows_complete(), height_,
                  static_cast<unsigned long long>(bytes_));
  fail(buf);
}

}  // namespace minrt::send
