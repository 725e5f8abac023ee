// The core's ByteSource and ByteSink on the UART.
//
// Input ends (read returns -1) at MINRT_END_OF_INPUT or after `idle_polls`
// consecutive status polls without a byte (0: wait forever); see
// include/minrt/serial_protocol.h. A valid scene never gets there: the SLD
// reader stops after the final terminator.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "uart.hpp"

namespace minrt::fw {

class SerialInput {
 public:
  // `binary`: MINRT_END_OF_INPUT is an ordinary byte (course words, framed
  // frames); only the idle count ends the input.
  SerialInput(Uart uart, uint32_t idle_polls, bool binary = false)
      : uart_(uart), idle_polls_(idle_polls), binary_(binary) {}

  ByteSource source() { return ByteSource{&read_fn, this}; }
  bool ended() const { return ended_; }

  // A byte taken off the line before the protocol that owns it was chosen
  // (the session's wait for a host): the next read of any SerialInput
  // returns it first.
  static void put_back(uint8_t byte);

 private:
  static int read_fn(void* ctx);
  int next();

  Uart uart_;
  uint32_t idle_polls_;
  bool binary_;
  bool ended_ = false;
};

// Sends everything to the UART, or with `discard` only counts it.
class SerialOutput {
 public:
  SerialOutput(Uart uart, bool discard) : uart_(uart), discard_(discard) {}

  ByteSink sink() { return ByteSink{&write_fn, this}; }
  size_t bytes() const { return bytes_; }

 private:
  static void write_fn(void* ctx, const uint8_t* data, size_t size);

  Uart uart_;
  bool discard_;
  size_t bytes_ = 0;
};

}  // namespace minrt::fw
