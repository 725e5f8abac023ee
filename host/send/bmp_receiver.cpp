#include "bmp_receiver.hpp"

#include <cstdio>

namespace minrt::send {

namespace {
constexpr int kMaxSide = 16384;
std::uint32_t le32(const std::uint8_t* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}
}  // namespace

int BmpReceiver::rows_complete() const {
  return width_ > 0 ? static_cast<int>(pixels_seen_ / (4u * static_cast<std::uint64_t>(width_))) : 0;
}

std::size_t BmpReceiver::feed(const std::uint8_t* data, std::size_t size) {
  std::size_t i = 0;
  while (i < size && !ended()) {
    if (state_ == State::kBody) {  // the bulk of the image: take what is there
      const std::uint64_t want = pixel_bytes_ - pixels_seen_;
      const std::size_t n = static_cast<std::size_t>(want < size - i ? want : size - i);
      // Every pixel the firmware writes is opaque: a lost or doubled byte
      // moves a colour byte into an alpha slot.
      for (std::size_t k = 0; k < n; ++k)
        if ((pixels_seen_ + k) % 4 == 3 && data[i + k] != 0xFF) {
          char buf[128];
          const std::uint64_t px = (pixels_seen_ + k) / 4;
          std::snprintf(buf, sizeof buf, "BMP pixel %llu (row %llu from the bottom) is not opaque: the line damaged it",
                        static_cast<unsigned long long>(px % static_cast<std::uint64_t>(width_)),
                        static_cast<unsigned long long>(px / static_cast<std::uint64_t>(width_)));
          bytes_ += k + 1;
          fail(buf);
          return i + k + 1;
        }
      pixels_seen_ += n;
      bytes_ += n;
      i += n;
      if (pixels_seen_ == pixel_bytes_) state_ = State::kDone;
      continue;
    }
    const bool more = step(data[i]);
    ++i;
    ++bytes_;
    if (!more) break;
  }
  return i;
}

bool BmpReceiver::header_done() {
  const std::uint8_t* h = header_;
  width_ = static_cast<int>(le32(h + 18));
  height_ = static_cast<int>(le32(h + 22));
  if (h[0] != 'B' || h[1] != 'M' || le32(h + 10) != 54 || le32(h + 14) != 40 || h[28] != 32 || width_ < 1 ||
      height_ < 1 || width_ > kMaxSide || height_ > kMaxSide)
    return fail("the board's BMP header is not the one the firmware writes: the line damaged it");
  pixel_bytes_ = 4u * static_cast<std::uint64_t>(width_) * static_cast<std::uint64_t>(height_);
  if (le32(h + 2) != 54 + pixel_bytes_) return fail("the board's BMP header gives a wrong file size");
  state_ = State::kBody;
  return true;
}

bool BmpReceiver::step(std::uint8_t c) {
  switch (state_) {
    case State::kStart:
      if (!start(c, 'B', "BMP")) return false;
      if (state_ == State::kHeader) header_[at_++] = c;
      return true;
    case State::kHeader:
      header_[at_++] = c;
      if (at_ == sizeof header_) return header_done();
      return true;
    case State::kErrorLine:
      return error_line_step(c);
    default:
      return false;
  }
}

void BmpReceiver::finish() {
  if (ended() || fail_if_no_image()) return;
  char buf[160];
  std::snprintf(buf, sizeof buf, "BMP is truncated: %d of %d rows after %llu bytes", rows_complete(), height_,
                  static_cast<unsigned long long>(bytes_));
  fail(buf);
}

}  // namespace minrt::send
