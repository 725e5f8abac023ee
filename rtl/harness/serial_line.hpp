// The host's end of an 8N1 serial line, bit by bit in simulated clock
// cycles: bytes from the UART's input file go out on the CPU's receive pin
// (start bit, 8 data bits LSB first, stop bit, each `cycles_per_bit`
// clocks), and the CPU's transmit pin is sampled in the middle of each bit
// and decoded back to bytes for the output file. A frame with a bad stop
// bit is counted, not passed on.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

class SerialLine {
 public:
  SerialLine(int in_fd, int out_fd, unsigned cycles_per_bit)
      : in_fd_(in_fd), out_fd_(out_fd), cpb_(cycles_per_bit) {}
  ~SerialLine() { flush(); }
  unsigned cycles_per_bit() const { return cpb_; }

  // The level of the CPU's receive pin during `cycle`. Nothing is sent
  // before open() (the firmware has not looked at its UART yet).
  bool rx_bit(uint64_t cycle);
  void open() { open_ = true; }
  bool is_open() const { return open_; }
  // The CPU's transmit pin during `cycle`.
  void tx_sample(bool level, uint64_t cycle);
  void flush();
  uint64_t framing_errors() const { return framing_errors_; }

 private:
  bool next_input(uint8_t& byte, uint64_t cycle);

  int in_fd_, out_fd_;
  unsigned cpb_;
  // receive pin (host -> CPU)
  bool open_ = false;
  bool sending_ = false;
  uint64_t frame_start_ = 0;
  uint16_t frame_ = 0;  // start, data, stop: bit 0 first
  std::vector<uint8_t> in_buf_;
  size_t in_pos_ = 0;
  bool eof_ = false;
  uint64_t next_poll_ = 0;
  // transmit pin (CPU -> host)
  bool receiving_ = false;
  uint64_t rx_start_ = 0;
  unsigned rx_bits_ = 0;
  uint8_t rx_byte_ = 0;
  std::vector<uint8_t> out_buf_;
  uint64_t last_byte_ = 0;
  uint64_t framing_errors_ = 0;
};
