// Polling driver for ARM's CMSDK APB UART (MPS2 boards, QEMU mps2-*):
// 32-bit registers, "buffer full" flags in STATE, transmitter and receiver
// enabled in CTRL, a baud divisor of at least 16.
#pragma once

#include <stdint.h>

namespace minrt::fw {

struct CmsdkUartRegisters {
  volatile uint32_t data;      // +0x00 read: received byte, write: send
  volatile uint32_t state;     // +0x04 bit 0 TX buffer full, bit 1 RX buffer full
  volatile uint32_t ctrl;      // +0x08 bit 0 TX enable, bit 1 RX enable
  volatile uint32_t intstatus; // +0x0c
  volatile uint32_t bauddiv;   // +0x10
};

class CmsdkUart {
 public:
  explicit CmsdkUart(uintptr_t base) : regs_(reinterpret_cast<CmsdkUartRegisters*>(base)) {}

  void init() {
    regs_->bauddiv = kSmallestDivisor;
    regs_->ctrl = kTxEnable | kRxEnable;
  }
  bool rx_ready() const { return (regs_->state & kRxFull) != 0; }
  uint8_t rx() { return static_cast<uint8_t>(regs_->data); }
  bool tx_ready() const { return (regs_->state & kTxFull) == 0; }
  void put(uint8_t byte) { regs_->data = byte; }
  bool tx_idle() const { return tx_ready(); }

 private:
  static constexpr uint32_t kTxFull = 0x1;
  static constexpr uint32_t kRxFull = 0x2;
  static constexpr uint32_t kTxEnable = 0x1;
  static constexpr uint32_t kRxEnable = 0x2;
  static constexpr uint32_t kSmallestDivisor = 16;
  CmsdkUartRegisters* regs_;
};

}  // namespace minrt::fw
