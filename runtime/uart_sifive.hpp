// Polling driver for the SiFive UART (uart = sifive), as in the FE310 and
// QEMU's sifive_e/sifive_u machines: 32-bit registers, a full/empty flag in
// bit 31 of the data registers.
#pragma once

#include <stdint.h>

#include <minrt/memory_map.h>

namespace minrt::fw {

struct SifiveUartRegisters {
  volatile uint32_t txdata;  // +0x00 write: send; read: bit 31 = FIFO full
  volatile uint32_t rxdata;  // +0x04 read: bit 31 = empty, else byte in 7:0 (popped)
  volatile uint32_t txctrl;  // +0x08 bit 0 txen
  volatile uint32_t rxctrl;  // +0x0c bit 0 rxen
  volatile uint32_t ie;      // +0x10
  volatile uint32_t ip;      // +0x14 bit 0: TX FIFO below its watermark
  volatile uint32_t div;     // +0x18 baud divisor
};

class SifiveUart {
 public:
  explicit SifiveUart(uintptr_t base) : regs_(reinterpret_cast<SifiveUartRegisters*>(base)) {}

  void init() {
#ifdef MINRT_BOARD_UART_DIVISOR
    regs_->div = MINRT_BOARD_UART_DIVISOR;
#endif
    regs_->ie = 0;
    regs_->txctrl = kEnable;
    regs_->rxctrl = kEnable;
  }
  // Reading rxdata pops the byte, so a poll that finds one keeps it for rx().
  bool rx_ready() {
    if (pending_ < 0) {
      const uint32_t word = regs_->rxdata;
      if ((word & kFlag) == 0) pending_ = static_cast<int32_t>(word & 0xff);
    }
    return pending_ >= 0;
  }
  uint8_t rx() {
    const auto byte = static_cast<uint8_t>(pending_);
    pending_ = -1;
    return byte;
  }
  bool tx_ready() const { return (regs_->txdata & kFlag) == 0; }
  void put(uint8_t byte) { regs_->txdata = byte; }
  // No "transmitter empty" flag; a FIFO with room is as far as it shows.
  bool tx_idle() const { return tx_ready(); }

 private:
  static constexpr uint32_t kFlag = 0x80000000u;
  static constexpr uint32_t kEnable = 0x1;
  SifiveUartRegisters* regs_;
  int32_t pending_ = -1;
};

}  // namespace minrt::fw
