#include "halt.hpp"

#include <minrt/memory_map.h>

#include "uart.hpp"

#if MINRT_BOARD_HALT == MINRT_HALT_KIND_LOOP
// The status of the run, for a debugger: looping shows nothing else.
extern "C" volatile int minrt_exit_status = 0;
#endif

extern "C" [[noreturn]] void minrt_halt(int status) {
  // Let the last bytes leave the UART before the machine stops.
  minrt::fw::console_uart().drain();
#if MINRT_BOARD_HALT == MINRT_HALT_KIND_FINISHER
  auto* finisher = reinterpret_cast<volatile uint32_t*>(MINRT_FINISHER_BASE);
  const auto code = static_cast<uint32_t>(status) & 0xffffu;
  *finisher = code == 0 ? MINRT_FINISHER_PASS : (code << 16) | MINRT_FINISHER_FAIL;
  for (;;) {
    asm volatile("wfi");
  }
#elif MINRT_BOARD_HALT == MINRT_HALT_KIND_ECALL
  register int a0 asm("a0") = status;
  register int a7 asm("a7") = 93;
  asm volatile("ecall" : : "r"(a0), "r"(a7) : "memory");
#elif MINRT_BOARD_HALT == MINRT_HALT_KIND_STORE
  *reinterpret_cast<volatile uint32_t*>(MINRT_BOARD_HALT_ADDR) = static_cast<uint32_t>(status);
#else
  minrt_exit_status = status;
#endif
  // Jump-to-self: the loop kind's halt, and where the others end up if the
  // machine carries on.
  for (;;) {
    asm volatile("1: j 1b");
  }
}
