// The course protocol's boot stage: where an uploaded program goes and how
// it is started (MINRT_PROGRAM_* in include/minrt/memory_map.h).
#pragma once

#include <stdint.h>

namespace minrt::fw {

// What the boot loader handed this image (MINRT_PROGRAM_LOADED,
// MINRT_PROGRAM_BIG_ENDIAN); 0 when it was started directly.
uint32_t program_handoff();

struct ProgramRegion {
  uint8_t* base;
  uint32_t capacity;  // 0 when this image itself lies in the region
};
ProgramRegion program_region();

// Jumps to the program at MINRT_PROGRAM_LOAD_ADDR with this image's
// arguments and stack, telling it the course words' byte order.
[[noreturn]] void start_program(int argc, char** argv, bool big_endian);

}  // namespace minrt::fw
