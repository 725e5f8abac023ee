// Polling driver for LiteX's CSR UART (uart = litex): 32-bit CSRs, one byte
// of data each. A received byte stays at the head of the RX FIFO until the
// RX event is acknowledged in ev_pending, which is what advances it.
#pragma once

#include <stdint.h>

namespace minrt::fw {

struct LitexUartRegisters {
  volatile uint32_t rxtx;        // +0x00 read: head of RX FIFO, write: send
  volatile uint32_t txfull;      // +0x04 1 while the TX FIFO is full
  volatile uint32_t rxempty;     // +0x08 1 while the RX FIFO is empty
  volatile uint32_t ev_status;   // +0x0c
  volatile uint32_t ev_pending;  // +0x10 write 1 to a bit to acknowledge it
  volatile uint32_t ev_enable;   // +0x14 interrupt enables
};

class LitexUart {
 public:
  explicit LitexUart(uintptr_t base) : regs_(reinterpret_cast<LitexUartRegisters*>(base)) {}

  // Interrupts off; the baud rate is the SoC's (a gateware parameter).
  void init() { regs_->ev_enable = 0; }
  bool rx_ready() const { return regs_->rxempty == 0; }
  uint8_t rx() {
    const auto byte = static_cast<uint8_t>(regs_->rxtx);
    regs_->ev_pending = kEventRx;
    return byte;
  }
  bool tx_ready() const { return regs_->txfull == 0; }
  void put(uint8_t byte) { regs_->rxtx = byte; }
  // The CSR block has no "shift register empty" flag on every LiteX
  // version; an accepted byte is as far as the driver can see.
  bool tx_idle() const { return regs_->txfull == 0; }

 private:
  static constexpr uint32_t kEventRx = 0x2;
  LitexUartRegisters* regs_;
};

}  // namespace minrt::fw
