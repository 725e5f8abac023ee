// Polling driver for a UART described entirely by the board file
// (uart = generic): one data register (read = receive, write = send) and
// one status register at the given offsets, "can send" and "byte
// available" as masks over the status, registers 1 or 4 bytes wide. Covers
// most student and soft-core UARTs that have a status word.
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
      : data_(reinterpret_cast<Register*>(base + MINRT_BOARD_UART_DATA)),
        status_(reinterpret_cast<Register*>(base + MINRT_BOARD_UART_STATUS)) {}

  // Nothing to set up: the board's reset state or boot loader configured it.
  void init() {}
  bool rx_ready() const { return (*status_ & MINRT_BOARD_UART_RX_READY) != 0; }
  uint8_t rx() { return static_cast<uint8_t>(*data_); }
  bool tx_ready() const { return (*status_ & MINRT_BOARD_UART_TX_READY) != 0; }
  void put(uint8_t byte) { *data_ = byte; }
  bool tx_idle() const { return tx_ready(); }

 private:
  Register* data_;
  Register* status_;
};

}  // namespace minrt::fw
