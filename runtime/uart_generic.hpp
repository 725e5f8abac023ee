// Polling driver for a UART described entirely by the board file
// (uart = generic): one data register (read = receive, write = send) and
// one status register at the given offsets, "can send" and "byte
// available" as masks over the status, registers 1 or 4 bytes wide. Covers
// most student and soft-core UARTs that have a status word. A UART that
// must be switched on (NEORV32's, whose control register resets to 0) gets
// the board file's uart_init writes at start-up; uart_tx_idle is the status
// mask that says everything sent has left, for the drain before a halt.
#pragma once

#include <stdint.h>

#include <minrt/memory_map.h>

namespace minrt::fw {

class GenericUart {
 public:
#if MINRT_BOARD_UART_WIDTH == 1
  using Register = volatile uint8_t;
#else
  using Register = volatile uint32_t;
#endif

  explicit GenericUart(uintptr_t base)
      : base_(base),
        data_(reinterpret_cast<Register*>(base + MINRT_BOARD_UART_DATA)),
        status_(reinterpret_cast<Register*>(base + MINRT_BOARD_UART_STATUS)) {}

  // The board file's register writes, in order; without any, the board's
  // reset state or boot loader configured the UART.
  void init() {
#ifdef MINRT_BOARD_UART_INIT
    static constexpr uint32_t kWrites[] = {MINRT_BOARD_UART_INIT};  // offset, value, ...
    for (unsigned i = 0; i + 1 < sizeof kWrites / sizeof kWrites[0]; i += 2)
      *reinterpret_cast<Register*>(base_ + kWrites[i]) = kWrites[i + 1];
#endif
  }
  bool rx_ready() const { return (*status_ & MINRT_BOARD_UART_RX_READY) != 0; }
  uint8_t rx() { return static_cast<uint8_t>(*data_); }
  bool tx_ready() const { return (*status_ & MINRT_BOARD_UART_TX_READY) != 0; }
  void put(uint8_t byte) { *data_ = byte; }
  bool tx_idle() const { return (*status_ & MINRT_BOARD_UART_TX_IDLE) != 0; }

 private:
  uintptr_t base_;
  Register* data_;
  Register* status_;
};

}  // namespace minrt::fw
