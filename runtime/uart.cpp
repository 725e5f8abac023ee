#include "uart.hpp"

namespace minrt::fw {

void Uart::tx(uint8_t byte) {
  while (!driver_.tx_ready()) {
  }
  driver_.put(byte);
}

void Uart::write(const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i) tx(data[i]);
}

void Uart::write(const char* text) {
  while (*text != 0) tx(static_cast<uint8_t>(*text++));
}

void Uart::drain() const {
  while (!driver_.tx_idle()) {
  }
}

}  // namespace minrt::fw
