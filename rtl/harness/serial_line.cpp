#include "serial_line.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>

bool SerialLine::next_input(uint8_t& byte, uint64_t cycle) {
  if (in_pos_ == in_buf_.size() && !eof_ && cycle >= next_poll_) {
    // A system call only every few hundred cycles while the host is silent.
    next_poll_ = cycle + 256;
    pollfd p{in_fd_, POLLIN, 0};
    if (::poll(&p, 1, 0) > 0) {
      in_buf_.resize(4096);
      const ssize_t n = ::read(in_fd_, in_buf_.data(), in_buf_.size());
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) eof_ = true;
      in_buf_.resize(n > 0 ? static_cast<size_t>(n) : 0);
      in_pos_ = 0;
    }
  }
  if (in_pos_ == in_buf_.size()) return false;
  byte = in_buf_[in_pos_++];
  return true;
}

bool SerialLine::rx_bit(uint64_t cycle) {
  if (sending_ && cycle - frame_start_ >= 10ull * cpb_) sending_ = false;
  if (!sending_) {
    uint8_t b;
    if (!open_) return true;
    if (!next_input(b, cycle)) return true;  // idle line is high
    frame_ = static_cast<uint16_t>(1u << 9 | b << 1);  // stop 1, data, start 0
    frame_start_ = cycle;
    sending_ = true;
  }
  return (frame_ >> ((cycle - frame_start_) / cpb_)) & 1;
}

void SerialLine::tx_sample(bool level, uint64_t cycle) {
  if (!receiving_) {
    // Pass on what came once the line has been quiet for two frames.
    if (!out_buf_.empty() && cycle - last_byte_ > 20ull * cpb_) flush();
    if (!level) {
      receiving_ = true;
      rx_start_ = cycle;
      rx_bits_ = 0;
      rx_byte_ = 0;
    }
    return;
  }
  // The middle of bit k (0 = start) is at start + k * cpb + cpb / 2.
  const uint64_t mid = rx_start_ + static_cast<uint64_t>(rx_bits_) * cpb_ + cpb_ / 2;
  if (cycle != mid) return;
  if (rx_bits_ == 0 && level) {
    receiving_ = false;  // a glitch, not a start bit
    return;
  }
  if (rx_bits_ >= 1 && rx_bits_ <= 8) rx_byte_ = static_cast<uint8_t>(rx_byte_ >> 1 | (level ? 0x80 : 0));
  if (rx_bits_ == 9) {
    receiving_ = false;
    if (level) {
      out_buf_.push_back(rx_byte_);
      last_byte_ = cycle;
      if (out_buf_.size() >= 256) flush();
    } else ++framing_errors_;
    return;
  }
  ++rx_bits_;
}

void SerialLine::flush() {
  size_t done = 0;
  while (done < out_buf_.size()) {
    const ssize_t n = ::write(out_fd_, out_buf_.data() + done, out_buf_.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  out_buf_.clear();
}
