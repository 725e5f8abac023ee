// The board's UART as seen by the firmware, in one of four register
// layouts (memory_map.hpp UartKind): NS16550A (data at +0, line status at +5,
// divisor latch behind LCR.DLAB so a real init sequence works), LiteX CSR
// UART, SiFive UART, or a generic data/status pair with masks. Registers not
// described read 0 and ignore writes. The host side is a pair of file
// descriptors (stdin/stdout, files, or a pty master).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "memory_map.hpp"

namespace fwsim {

class Uart {
 public:
  struct Config {
    int in_fd = 0;
    int out_fd = 1;
    bool interactive = false;        // pty: flush output eagerly
    uint64_t cycles_per_byte = 0;    // 0 = no pacing
    uint64_t stall_polls = 2000000;  // status polls after input EOF before giving up
    uint64_t max_output = UINT64_MAX;  // bytes sent before the run stops (--max-output)
    UartLayout layout;               // register interface
    // --real-board: output the host does not take within a moment is lost
    // (a serial line keeps nothing for a host that is not there), and a
    // long wait for the host is reported on stderr, in seconds and in
    // cycles at clock_hz (the board waits in real time).
    bool real_board = false;
    uint64_t clock_hz = 0;
  };

  explicit Uart(const Config& cfg) : cfg_(cfg) {}
  ~Uart() { flush(); }
  Uart(const Uart&) = delete;
  Uart& operator=(const Uart&) = delete;

  // `now` is the current simulated cycle, used only for baud pacing.
  uint32_t read(uint32_t offset, uint64_t now);
  void write(uint32_t offset, uint32_t value, uint64_t now);

  bool stalled() const { return eof_polls_ >= cfg_.stall_polls; }
  // The run must stop: a write failed, or --max-output was reached.
  bool io_error() const { return io_error_; }
  bool output_limited() const { return output_limited_; }
  int write_errno() const { return write_errno_; }  // of the failed write, 0 if none
  void flush();

  uint64_t bytes_out() const { return bytes_out_; }
  uint64_t bytes_in() const { return bytes_in_; }
  // Bytes lost because the firmware had not switched the UART on.
  uint64_t bytes_dropped() const { return dropped_; }

 private:
  bool fill_input();  // true when at least one byte is buffered
  bool data_ready(uint64_t now);
  // Kind-independent halves of the register behaviour.
  bool poll_rx(uint64_t now);  // a status read: is a byte available?
  int take_rx(uint64_t now);   // a data read: the byte, or -1 (none)
  bool tx_ready(uint64_t now) const { return now >= tx_free_at_; }
  void send(uint8_t value, uint64_t now);
  uint8_t read_ns16550(uint32_t offset, uint64_t now);
  void write_ns16550(uint32_t offset, uint8_t value, uint64_t now);

  Config cfg_;
  std::vector<uint8_t> in_buf_;
  size_t in_pos_ = 0;
  bool eof_ = false;
  bool holding_ = false;        // a byte sits in the receive register
  uint64_t rx_ready_at_ = 0;    // cycle at which the held byte becomes readable
  uint64_t tx_free_at_ = 0;     // cycle at which the transmitter is empty again
  uint64_t eof_polls_ = 0;
  uint64_t idle_polls_ = 0;     // LSR reads without data since the last data access
  std::vector<uint8_t> out_buf_;
  uint8_t lcr_ = 0, dll_ = 0, dlm_ = 0, scr_ = 0;
  uint32_t sifive_txctrl_ = 0, sifive_rxctrl_ = 0, sifive_div_ = 0;
  // Generic kind: what the firmware wrote to registers other than data
  // (their first 0x100 bytes), for the enable condition and read-back.
  bool generic_enabled() const;
  uint32_t generic_regs_[64] = {};
  uint64_t dropped_ = 0;  // bytes sent or received while the UART was off
  uint64_t bytes_out_ = 0, bytes_in_ = 0;
  bool io_error_ = false;
  bool output_limited_ = false;
  int write_errno_ = 0;
  uint64_t unread_ = 0;          // real board: output bytes no host took
  long long wait_since_ns_ = 0;  // real board: when the firmware began to poll an empty line
};

}  // namespace fwsim
