#include "footprint.hpp"

#include <stdint.h>

#include "core/base/diagnostic.hpp"
#include "firmware_layout.h"

extern "C" {
// Linker script symbols: only their addresses mean anything.
extern uint8_t __text_start[], __text_end[];
extern uint8_t __rodata_start[], __rodata_end[];
extern uint8_t __data_start[], __data_end[];
extern uint8_t __bss_start[], __bss_end[];
extern uint8_t __arena_start[], __arena_end[];
extern uint32_t __stack_bottom[];

// sp at entry to crt0, stored by crt0 (firmware-sim starts it at RAM end -
// MINRT_BOOT_ARGS_MAX, right below the argument block: __stack_top with the
// board's 4 MiB).
uintptr_t minrt_initial_sp;
}

namespace minrt::fw {
namespace {

size_t span(const void* begin, const void* end) {
  return static_cast<size_t>(reinterpret_cast<uintptr_t>(end) -
                             reinterpret_cast<uintptr_t>(begin));
}

// Bytes between the deepest word crt0's pattern no longer holds and the
// initial stack pointer.
size_t stack_high_water() {
  const auto* top = reinterpret_cast<const uint32_t*>(minrt_initial_sp);
  const uint32_t* p = __stack_bottom;
  while (p < top && *p == MINRT_FW_STACK_PATTERN) ++p;
  return span(p, top);
}

void line(Uart uart, const char* name, size_t bytes) {
  Diagnostic text;
  text.text(name).text(" ").number(static_cast<int64_t>(bytes)).text("\n");
  uart.write(text.message);
}

}  // namespace

ArenaRegion arena_region() { return {__arena_start, span(__arena_start, __arena_end)}; }

void print_footprint(Uart uart, size_t arena_used, size_t image_bytes) {
  // Measured first, before the printing below uses stack of its own.
  const size_t high_water = stack_high_water();
  line(uart, "text", span(__text_start, __text_end));
  line(uart, "rodata", span(__rodata_start, __rodata_end));
  line(uart, "data", span(__data_start, __data_end));
  line(uart, "bss", span(__bss_start, __bss_end));
  line(uart, "arena", arena_region().size);
  line(uart, "arena_used", arena_used);
  line(uart, "stack", MINRT_FW_STACK_SIZE);
  line(uart, "stack_high_water", high_water);
  line(uart, "image_bytes", image_bytes);
}

}  // namespace minrt::fw
