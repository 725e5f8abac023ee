#include "serial_stream.hpp"

#include <minrt/serial_protocol.h>

namespace minrt::fw {

namespace {
int g_put_back = -1;
}  // namespace

void SerialInput::put_back(uint8_t byte) { g_put_back = byte; }

int SerialInput::read_fn(void* ctx) { return static_cast<SerialInput*>(ctx)->next(); }

int SerialInput::next() {
  if (ended_) return -1;
  if (g_put_back >= 0) {
    const int byte = g_put_back;
    g_put_back = -1;
    if (binary_ || byte != MINRT_END_OF_INPUT) return byte;
    ended_ = true;
    return -1;
  }
  for (uint32_t idle = 0;;) {
    if (uart_.rx_ready()) {
      const uint8_t byte = uart_.rx();
      if (binary_ || byte != MINRT_END_OF_INPUT) return byte;
      break;
    }
    if (idle_polls_ != 0 && ++idle >= idle_polls_) break;
  }
  ended_ = true;
  return -1;
}

void SerialOutput::write_fn(void* ctx, const uint8_t* data, size_t size) {
  auto* self = static_cast<SerialOutput*>(ctx);
  self->bytes_ += size;
  if (!self->discard_) self->uart_.write(data, size);
}

}  // namespace minrt::fw
