// minrt_halt on the Cortex-M port: ARM semihosting's SYS_EXIT_EXTENDED
// (QEMU with -semihosting-config enable=on exits with the status).
#include "halt.hpp"

#include "uart.hpp"

namespace {
constexpr uint32_t kSysExitExtended = 0x20;
constexpr uint32_t kApplicationExit = 0x20026;  // ADP_Stopped_ApplicationExit
constexpr uint32_t kFlushPolls = 1000000;
}  // namespace

extern "C" [[noreturn]] void minrt_halt(int status) {
  // The UART shows only "buffer full", not "line idle": give the last
  // byte time to leave before the machine stops (QEMU drops it otherwise).
  minrt::fw::console_uart().drain();
  for (volatile uint32_t i = 0; i < kFlushPolls; i = i + 1) {
  }
  const uint32_t block[2] = {kApplicationExit, static_cast<uint32_t>(status)};
  register uint32_t r0 asm("r0") = kSysExitExtended;
  register const uint32_t* r1 asm("r1") = block;
  asm volatile("bkpt 0xab" : : "r"(r0), "r"(r1) : "memory");
  for (;;) {
    asm volatile("b .");
  }
}
