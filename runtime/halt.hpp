// Stopping the machine through the SiFive test finisher (memory_map.h):
// firmware-sim and QEMU -M virt exit with the given status.
#pragma once

#include <stdint.h>

extern "C" [[noreturn]] void minrt_halt(int status);
