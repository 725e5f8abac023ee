// Polling driver for an NS16550A-compatible UART (uart = ns16550). The
// registers are one byte wide and one byte apart; the driver never uses
// interrupts and never changes the FIFO setup (which on QEMU would discard
// bytes already received).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/memory_map.h>

namespace minrt::fw {

// The register block as the CPU sees it.
struct Ns16550Registers {
  volatile uint8_t data;  // +0 RBR (read) / THR (write); DLL when LCR.DLAB
  volatile uint8_t ier;   // +1 interrupt enable; DLM when LCR.DLAB
  volatile uint8_t fcr;   // +2 IIR (read) / FCR (write)
  volatile uint8_t lcr;   // +3 line control
  volatile uint8_t mcr;   // +4 modem control
  volatile uint8_t lsr;   // +5 line status
  volatile uint8_t msr;   // +6 modem status
  volatile uint8_t scr;   // +7 scratch
};
static_assert(offsetof(Ns16550Registers, data) == MINRT_UART_REG_DATA);
static_assert(offsetof(Ns16550Registers, lsr) == MINRT_UART_REG_LSR);
static_assert(sizeof(Ns16550Registers) <= MINRT_UART_SIZE);

class Ns16550 {
 public:
  explicit Ns16550(uintptr_t base) : regs_(reinterpret_cast<Ns16550Registers*>(base)) {}

  // 8 data bits, no parity, 1 stop bit, interrupts off; the baud divisor
  // when the board file gives one (emulators ignore it).
  void init();
  bool rx_ready() const { return (regs_->lsr & MINRT_UART_LSR_DATA_READY) != 0; }
  uint8_t rx() { return regs_->data; }
  bool tx_ready() const { return (regs_->lsr & MINRT_UART_LSR_THR_EMPTY) != 0; }
  void put(uint8_t byte) { regs_->data = byte; }
  bool tx_idle() const { return (regs_->lsr & kLsrTransmitterEmpty) != 0; }

 private:
  static constexpr uint8_t kLsrTransmitterEmpty = 0x40;  // THR and shift register empty
  Ns16550Registers* regs_;
};

}  // namespace minrt::fw
