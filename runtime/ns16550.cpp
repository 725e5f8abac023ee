#include "ns16550.hpp"

namespace minrt::fw {
namespace {
constexpr uint8_t kLcr8N1 = 0x03;
constexpr uint8_t kLsrTransmitterEmpty = 0x40;  // THR and shift register empty
}  // namespace

void Ns16550::init() {
  regs_->ier = 0;
  regs_->lcr = kLcr8N1;
}

void Ns16550::tx(uint8_t byte) {
  while ((regs_->lsr & MINRT_UART_LSR_THR_EMPTY) == 0) {
  }
  regs_->data = byte;
}

void Ns16550::write(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) tx(data[i]);
}

void Ns16550::write(const char* text) {
  while (*text != 0) tx(static_cast<uint8_t>(*text++));
}

void Ns16550::drain() const {
  while ((regs_->lsr & kLsrTransmitterEmpty) == 0) {
  }
}

}  // namespace minrt::fw
