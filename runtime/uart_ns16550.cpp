#include "uart_ns16550.hpp"

namespace minrt::fw {
namespace {
constexpr uint8_t kLcr8N1 = 0x03;
}  // namespace

void Ns16550::init() {
  regs_->ier = 0;
#ifdef MINRT_BOARD_UART_DIVISOR
  constexpr uint8_t kLcrDivisorLatch = 0x80;
  regs_->lcr = kLcrDivisorLatch | kLcr8N1;
  regs_->data = static_cast<uint8_t>(MINRT_BOARD_UART_DIVISOR & 0xff);  // DLL
  regs_->ier = static_cast<uint8_t>((MINRT_BOARD_UART_DIVISOR >> 8) & 0xff);  // DLM
#endif
  regs_->lcr = kLcr8N1;
}

}  // namespace minrt::fw
