#include "program_loader.hpp"

#include <minrt/memory_map.h>

extern "C" {
extern uint8_t __text_start[], __bss_end[];
extern uintptr_t minrt_initial_sp;  // footprint.cpp

// Stored by crt0: the handoff flags, or 0.
uint32_t minrt_program_handoff;

[[noreturn]] void minrt_start_program(int argc, char** argv, uintptr_t sp, uint32_t flags);
}

namespace minrt::fw {

uint32_t program_handoff() { return minrt_program_handoff; }

ProgramRegion program_region() {
  const auto start = reinterpret_cast<uintptr_t>(__text_start);
  const auto end = reinterpret_cast<uintptr_t>(__bss_end);
  // An uploaded program (this image run from the region) must not load
  // another one over itself.
  if (start < MINRT_PROGRAM_LOAD_ADDR + MINRT_PROGRAM_MAX_SIZE && end > MINRT_PROGRAM_LOAD_ADDR)
    return ProgramRegion{nullptr, 0};
  return ProgramRegion{reinterpret_cast<uint8_t*>(MINRT_PROGRAM_LOAD_ADDR), MINRT_PROGRAM_MAX_SIZE};
}

void start_program(int argc, char** argv, bool big_endian) {
  const uint32_t flags = MINRT_PROGRAM_LOADED | (big_endian ? MINRT_PROGRAM_BIG_ENDIAN : 0u);
  minrt_start_program(argc, argv, minrt_initial_sp, flags);
}

}  // namespace minrt::fw
