// A program for the course boot stage's tests, uploaded instead of the
// renderer: prints one line showing where it runs and what the boot loader
// handed it, then halts with kProbeStatus, so a test can tell from the
// output and the exit status that uploaded code really ran.
#include <stdint.h>

#include <minrt/memory_map.h>

#include "core/base/diagnostic.hpp"
#include "uart.hpp"
#include "program_loader.hpp"

namespace {

constexpr int kProbeStatus = 42;

void hex(minrt::Diagnostic& d, uint32_t v) {
  char digits[11] = {'0', 'x'};
  for (int i = 0; i < 8; ++i) digits[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 15];
  digits[10] = 0;
  d.text(digits);
}

}  // namespace

extern "C" int main(int argc, char** argv) {
  minrt::fw::Uart uart = minrt::fw::console_uart();
  uart.init();
  uintptr_t pc;
  asm volatile("auipc %0, 0" : "=r"(pc));  // where this code really runs
  const uint32_t handoff = minrt::fw::program_handoff();
  const bool inside = pc >= MINRT_PROGRAM_LOAD_ADDR && pc < MINRT_PROGRAM_LOAD_ADDR + MINRT_PROGRAM_MAX_SIZE;
  minrt::Diagnostic line;
  line.text("boot probe: pc ");
  hex(line, static_cast<uint32_t>(pc));
  line.text(inside ? " (in the program region), " : " (outside the program region), ");
  line.text((handoff & MINRT_PROGRAM_LOADED) != 0 ? "started by the boot loader, " : "started directly, ");
  line.text((handoff & MINRT_PROGRAM_BIG_ENDIAN) != 0 ? "big-endian words, " : "little-endian words, ");
  line.text("argc ").number(argc);
  if (argc > 0) line.text(", last argument ").text(argv[argc - 1]);
  line.text("\n");
  uart.write(line.message);
  return kProbeStatus;
}
