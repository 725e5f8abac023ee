#include "halt.hpp"

#include <minrt/memory_map.h>

#include "ns16550.hpp"

extern "C" [[noreturn]] void minrt_halt(int status) {
  // Let the last bytes leave the UART before the machine stops.
  minrt::fw::console_uart().drain();
  auto* finisher = reinterpret_cast<volatile uint32_t*>(MINRT_FINISHER_BASE);
  const auto code = static_cast<uint32_t>(status) & 0xffffu;
  *finisher = code == 0 ? MINRT_FINISHER_PASS : (code << 16) | MINRT_FINISHER_FAIL;
  for (;;) {
    asm volatile("wfi");
  }
}
