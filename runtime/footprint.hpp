// Memory footprint of the running firmware: section sizes from the linker
// script's symbols, the arena, and the stack high-water mark (crt0 fills the
// stack with MINRT_FW_STACK_PATTERN; the deepest overwritten word marks it).
#pragma once

#include <stddef.h>

#include "uart.hpp"

namespace minrt::fw {

struct ArenaRegion {
  void* base;
  size_t size;
};

// Free RAM between .bss and the stack.
ArenaRegion arena_region();

// Prints "name bytes" lines: text, rodata, data, bss, arena, arena_used,
// stack, stack_high_water, image_bytes.
void print_footprint(Uart uart, size_t arena_used, size_t image_bytes);

}  // namespace minrt::fw
