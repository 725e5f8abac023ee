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

std::uint32_t be32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) << 24 | static_cast<std::uint32_t>(p[1]) << 16 |
         static_cast<std::uint32_t>(p[2]) << 8 | p[3];
}
}  // namespace

bool PngReceiver::fail(std::string msg) {
  state_ = State::kFailed;
  message_ = std::move(msg);
  return false;
}

std::size_t PngReceiver::feed(const std::uint8_t* data, std::size_t size) {
  std::size_t i = 0;
  while (i < size) {
    if (done() || failed() || firmware_error()) break;
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
      if (c == static_cast<std::uint8_t>(MINRT_ERROR_MARKER[0])) {
        state_ = State::kErrorLine;
        error_line_.start(c);
        return true;
      }
      if (c != kSignature[0]) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "reply does not start like a PNG or an error line (first byte 0x%02x)", c);
        return fail(buf);
      }
      state_ = State::kSignature;
      at_ = 1;
      return true;
    case State::kSignature:
      if (c != kSignature[at_]) return fail("reply is not a PNG stream (bad signature)");
      if (++at_ == sizeof kSignature) {
        state_ = State::kChunk;
        at_ = 0;
      }
      return true;
    case State::kChunk: {
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
    case State::kErrorLine: {
      bool firmware = false;
      std::string message;
      if (error_line_.step(c, firmware, message)) return true;
      if (!firmware) return fail(message);
      message_ = message;
      state_ = State::kFirmwareError;
      return false;
    }
    default:
      return false;
  }
}

void PngReceiver::finish() {
  if (done() || failed() || firmware_error()) return;
  char buf[160];
  if (state_ == State::kStart) std::snprintf(buf, sizeof buf, "no reply from the board");
  else if (state_ == State::kErrorLine) std::snprintf(buf, sizeof buf, "error line from the board is cut off: %s", error_line_.text().c_str());
  else
    std::snprintf(buf, sizeof buf, "PNG stream is truncated: %d of %d rows after %llu bytes", rows_complete(), height_,
                  static_cast<unsigned long long>(bytes_));
  fail(buf);
}

}  // namespace minrt::send
