// The raw protocol's reply with its optional CRC-32 trailer
// (include/minrt/serial_protocol.h, protocol/raw_check.hpp): wraps the
// format's receiver (PPM, PNG, BMP), takes the announce byte in front of the
// image, hands the image to the receiver, keeps the image bytes, and checks
// the trailer after it. Same interface as the receivers, so the exchange
// loop in protocol_raw.cpp serves it unchanged; the image bytes come from
// image() instead of the caller's copy.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>

#include <minrt/serial_protocol.h>

#include "core/base/crc32.hpp"
#include "core/base/byte_io.hpp"
#include "protocol/raw_check.hpp"

namespace minrt::send {

// host-send --check / --no-check: whether to ask for the trailer, and
// whether a reply without it is acceptable.
enum class RawCheck {
  kOff,      // --no-check: do not ask; the reply is the plain image
  kAuto,     // default: ask, check it when the board announces it
  kRequire,  // --check: ask, and refuse an image that comes without it
};

template <class Receiver>
class CheckedReply {
 public:
  CheckedReply(Receiver& inner, RawCheck mode) : inner_(inner), mode_(mode) {}
  // --show: the image bytes also go here (the window's decoder) as they arrive.
  void follow(ByteSink live) { live_ = live; }

  std::size_t feed(const std::uint8_t* data, std::size_t size) {
    std::size_t i = 0;
    if (phase_ == Phase::kFirst && size > 0) {
      if (mode_ != RawCheck::kOff && data[0] == MINRT_CHECK_ANNOUNCE) {
        announced_ = true;
        i = 1;
        ++bytes_;
      } else if (mode_ == RawCheck::kRequire && data[0] != MINRT_ERROR_MARKER[0]) {
        ++bytes_;
        fail("the board did not announce the CRC-32 trailer (--check); --no-check takes the image without it");
        return 1;
      }
      phase_ = Phase::kImage;
    }
    if (phase_ == Phase::kImage && i < size) {
      const std::size_t used = inner_.feed(data + i, size - i);
      if (inner_.image_bytes()) {
        image_.append(reinterpret_cast<const char*>(data + i), used);
        crc_ = crc32_update(crc_, data + i, used);
        if (live_.write != nullptr) live_.put(data + i, used);
      }
      i += used;
      if (inner_.done()) phase_ = announced_ ? Phase::kTrailer : Phase::kDone;
    }
    while (phase_ == Phase::kTrailer && i < size) {
      trailer_[trailer_at_++] = data[i++];
      ++bytes_;
      if (trailer_at_ == raw_check::kTrailerSize) check_trailer();
    }
    return i;
  }

  void finish() {
    if (phase_ == Phase::kTrailer) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "the CRC-32 trailer is cut off (%zu of %zu bytes)", trailer_at_,
                    raw_check::kTrailerSize);
      fail(buf);
      return;
    }
    if (phase_ == Phase::kImage || phase_ == Phase::kFirst) {
      inner_.finish();
      if (inner_.done()) {
        if (announced_) fail("the CRC-32 trailer is missing after the image");
        else phase_ = Phase::kDone;
      }
    }
  }

  bool done() const { return phase_ == Phase::kDone; }
  bool failed() const { return phase_ == Phase::kFailed || (phase_ == Phase::kImage && inner_.failed()); }
  bool firmware_error() const { return phase_ == Phase::kImage && inner_.firmware_error(); }
  bool started() const { return announced_ || inner_.started(); }
  // The exchange loop must not copy fed bytes: image() has the image alone.
  bool image_bytes() const { return false; }
  const std::string& image() const { return image_; }
  const std::string& message() const { return phase_ == Phase::kFailed ? message_ : inner_.message(); }
  std::uint64_t bytes() const { return bytes_ + inner_.bytes(); }
  int rows_complete() const { return inner_.rows_complete(); }
  // Whether the image came with a trailer that matched.
  bool checked() const { return checked_; }
  bool announced() const { return announced_; }

 private:
  enum class Phase { kFirst, kImage, kTrailer, kDone, kFailed };

  void fail(std::string msg) {
    phase_ = Phase::kFailed;
    message_ = std::move(msg);
  }

  void check_trailer() {
    std::uint32_t bytes = 0, crc = 0;
    const std::uint32_t got = crc32_end(crc_);
    char buf[160];
    if (!raw_check::decode_trailer(trailer_, bytes, crc)) {
      fail("no CRC-32 trailer after the image: the line damaged the image or its end");
    } else if (bytes != image_.size()) {
      std::snprintf(buf, sizeof buf, "the board sent a %u-byte image, %zu bytes arrived: the line damaged it", bytes,
                    image_.size());
      fail(buf);
    } else if (crc != got) {
      std::snprintf(buf, sizeof buf,
                    "CRC-32 mismatch: the board sent %08x, the image received has %08x: the line damaged it", crc,
                    got);
      fail(buf);
    } else {
      checked_ = true;
      phase_ = Phase::kDone;
    }
  }

  Receiver& inner_;
  RawCheck mode_;
  ByteSink live_{nullptr, nullptr};
  Phase phase_ = Phase::kFirst;
  bool announced_ = false;
  bool checked_ = false;
  std::string message_;
  std::string image_;
  std::uint32_t crc_ = crc32_begin();
  std::uint8_t trailer_[raw_check::kTrailerSize] = {};
  std::size_t trailer_at_ = 0;
  std::uint64_t bytes_ = 0;  // announce and trailer bytes (the receiver counts the image)
};

}  // namespace minrt::send
