// The console UART every part of the firmware uses, whatever the board's
// kind (MINRT_BOARD_UART in <minrt/board.h>, from the board file): one
// driver per kind (uart_ns16550, uart_litex, uart_sifive, uart_generic),
// each with the same small polling interface
//   init(), rx_ready(), rx(), tx_ready(), put(byte), tx_idle()
// chosen at compile time, and the waiting and string writes here on top.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/memory_map.h>

#if MINRT_BOARD_UART == MINRT_UART_KIND_NS16550
#include "uart_ns16550.hpp"
#elif MINRT_BOARD_UART == MINRT_UART_KIND_LITEX
#include "uart_litex.hpp"
#elif MINRT_BOARD_UART == MINRT_UART_KIND_SIFIVE
#include "uart_sifive.hpp"
#elif MINRT_BOARD_UART == MINRT_UART_KIND_GENERIC
#include "uart_generic.hpp"
#elif MINRT_BOARD_UART == MINRT_UART_KIND_CMSDK
#include "cortex-m/uart_cmsdk.hpp"
#else
#error "minrt/board.h names no known UART kind"
#endif

namespace minrt::fw {

#if MINRT_BOARD_UART == MINRT_UART_KIND_NS16550
using UartDriver = Ns16550;
#elif MINRT_BOARD_UART == MINRT_UART_KIND_LITEX
using UartDriver = LitexUart;
#elif MINRT_BOARD_UART == MINRT_UART_KIND_SIFIVE
using UartDriver = SifiveUart;
#elif MINRT_BOARD_UART == MINRT_UART_KIND_CMSDK
using UartDriver = CmsdkUart;
#else
using UartDriver = GenericUart;
#endif

class Uart {
 public:
  explicit Uart(UartDriver driver) : driver_(driver) {}

  void init() { driver_.init(); }
  bool rx_ready() { return driver_.rx_ready(); }
  // The received byte; only valid when rx_ready().
  uint8_t rx() { return driver_.rx(); }

  // Waits until the transmitter takes the byte.
  void tx(uint8_t byte);
  void write(const uint8_t* data, size_t size);
  void write(const char* text);
  // Waits until every written byte has left (as far as the UART shows).
  void drain() const;

 private:
  UartDriver driver_;
};

// The board's UART at MINRT_UART_BASE (the drivers hold no other state
// that must outlive a call).
inline Uart console_uart() { return Uart(UartDriver(MINRT_UART_BASE)); }

}  // namespace minrt::fw
