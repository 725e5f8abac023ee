#include "ppm_receiver.hpp"

#include <cstdio>

namespace minrt::send {

namespace {
bool is_space(std::uint8_t c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f'; }
bool is_digit(std::uint8_t c) { return c >= '0' && c <= '9'; }
const char* kind_name(PpmKind k) { return k == PpmKind::kP3 ? "P3" : "P6"; }
}  // namespace

std::string ppm_header(const ImageSpec& spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s\n%d %d 255\n", kind_name(spec.kind), spec.width, spec.height);
  return buf;
}

std::uint64_t expected_image_bytes(const ImageSpec& spec) {
  const std::uint64_t px = static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height);
  const std::uint64_t header = ppm_header(spec).size();
  if (spec.kind == PpmKind::kP6) return header + 3 * px;
  return header + px * 10;  // "RRR GGG BBB\n" is at most 12, typical images ~8-10
}

PpmReceiver::PpmReceiver(const ImageSpec& expected) : expected_(expected) {
  pixels_.resize(static_cast<std::size_t>(expected.width) * static_cast<std::size_t>(expected.height) * 3);
}

int PpmReceiver::rows_complete() const {
  const std::size_t row = static_cast<std::size_t>(expected_.width) * 3;
  return row == 0 ? 0 : static_cast<int>(pixel_bytes_ / row);
}

std::size_t PpmReceiver::feed(const std::uint8_t* data, std::size_t size) {
  std::size_t i = 0;
  if (state_ == State::kBody && kind_ == PpmKind::kP6) {
    // Fast path: copy the binary payload in one go.
    const std::size_t want = pixels_.size() - pixel_bytes_;
    const std::size_t take = size < want ? size : want;
    for (std::size_t k = 0; k < take; ++k) pixels_[pixel_bytes_ + k] = data[k];
    pixel_bytes_ += take;
    bytes_ += take;
    i = take;
    if (pixel_bytes_ == pixels_.size()) state_ = State::kDone;
  }
  for (; i < size; ++i) {
    if (ended()) break;
    ++bytes_;
    if (!step(data[i])) {
      // The byte that ended the reply (or broke it) counts as consumed.
      ++i;
      break;
    }
  }
  return i;
}

// Returns false when the reply has ended (done, failed or firmware error).
bool PpmReceiver::step(std::uint8_t c) {
  switch (state_) {
    case State::kStart:
      if (!start(c, 'P', "PPM")) return false;
      if (state_ == State::kHeader) token_ = "P";
      return true;
    case State::kErrorLine:
      return error_line_step(c);
    case State::kHeader:
      if (in_comment_) {
        if (c == '\n' || c == '\r') in_comment_ = false;
        return true;
      }
      if (c == '#' && token_.empty()) {
        in_comment_ = true;
        return true;
      }
      if (is_space(c)) {
        if (token_.empty()) return true;
        if (!header_token_done()) return false;
        if (header_field_ == 4) {
          state_ = State::kBody;
          if (pixels_.empty()) state_ = State::kDone;
          return state_ != State::kDone;
        }
        return true;
      }
      if (token_.size() > 16) return fail("PPM header field too long");
      token_.push_back(static_cast<char>(c));
      return true;
    case State::kBody:
      // Only P3 gets here (P6 takes the fast path in feed, except its first byte).
      if (kind_ == PpmKind::kP6) {
        pixels_[pixel_bytes_++] = c;
        if (pixel_bytes_ == pixels_.size()) {
          state_ = State::kDone;
          return false;
        }
        return true;
      }
      // The layout the firmware writes (core/image/ppm_writer.hpp): one
      // line "R G B\n" per pixel, decimal without leading zeros. Anything
      // else is damage: a lost or doubled separator, a doubled 0.
      if (is_digit(c)) {
        if (p3_digits_ == 1 && p3_value_ == 0) return fail_p3("a value with a leading zero");
        if (p3_value_ < 0) p3_value_ = 0;
        p3_value_ = p3_value_ * 10 + (c - '0');
        if (++p3_digits_ > 3 || p3_value_ > 255) return fail_p3("a value above 255");
        return true;
      }
      if (c != ' ' && c != '\n') {
        char buf[48];
        std::snprintf(buf, sizeof buf, "unexpected byte 0x%02x", c);
        return fail_p3(buf);
      }
      if (p3_value_ < 0) return fail_p3(c == ' ' ? "a space where a value should start" : "an empty line");
      if (c != (pixel_bytes_ % 3 == 2 ? '\n' : ' '))
        return fail_p3(c == ' ' ? "more than 3 values on a line" : "fewer than 3 values on a line");
      pixels_[pixel_bytes_++] = static_cast<std::uint8_t>(p3_value_);
      p3_value_ = -1;
      p3_digits_ = 0;
      if (pixel_bytes_ == pixels_.size()) {
        state_ = State::kDone;
        return false;
      }
      return true;
    default:
      return false;
  }
}

bool PpmReceiver::fail_p3(const char* what) {
  const std::size_t pixel = pixel_bytes_ / 3;
  const std::size_t width = static_cast<std::size_t>(expected_.width);
  char buf[192];
  std::snprintf(buf, sizeof buf, "P3 pixel data damaged: %s at row %zu, pixel %zu (one \"R G B\" line per pixel expected)",
                what, pixel / width, pixel % width);
  return fail(buf);
}

bool PpmReceiver::header_token_done() {
  if (header_field_ == 0) {
    if (token_ == "P6") kind_ = PpmKind::kP6;
    else if (token_ == "P3") kind_ = PpmKind::kP3;
    else return fail("bad PPM magic '" + token_ + "'");
    if (kind_ != expected_.kind)
      return fail(std::string("image is ") + kind_name(kind_) + ", expected " + kind_name(expected_.kind));
  } else {
    long v = 0;
    for (char ch : token_) {
      if (!is_digit(static_cast<std::uint8_t>(ch))) return fail("bad PPM header field '" + token_ + "'");
      v = v * 10 + (ch - '0');
    }
    values_[header_field_] = v;
    if (header_field_ == 2 && (values_[1] != expected_.width || values_[2] != expected_.height)) {
      char buf[128];
      std::snprintf(buf, sizeof buf, "image is %ldx%ld, expected %dx%d", values_[1], values_[2], expected_.width,
                    expected_.height);
      return fail(buf);
    }
    if (header_field_ == 3 && v != 255) return fail("PPM maxval is " + token_ + ", expected 255");
  }
  token_.clear();
  ++header_field_;
  return true;
}

void PpmReceiver::finish() {
  if (ended()) return;
  if (state_ == State::kBody && kind_ == PpmKind::kP3 && p3_value_ >= 0 &&
      pixel_bytes_ + 1 == pixels_.size()) {
    pixels_[pixel_bytes_++] = static_cast<std::uint8_t>(p3_value_);
    state_ = State::kDone;
    return;
  }
  if (fail_if_no_image()) return;
  char buf[160];
  if (state_ == State::kHeader) std::snprintf(buf, sizeof buf, "PPM header is cut off after %llu bytes", static_cast<unsigned long long>(bytes_));
  else
    std::snprintf(buf, sizeof buf, "image is truncated: %zu of %zu channel values (%d of %d rows) after %llu bytes",
                  pixel_bytes_, pixels_.size(), rows_complete(), expected_.height,
                  static_cast<unsigned long long>(bytes_));
  fail(buf);
}

}  // namespace minrt::send
