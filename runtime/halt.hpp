// Stopping the machine the board's way (MINRT_BOARD_HALT in <minrt/board.h>):
// the SiFive test finisher (firmware-sim, QEMU -M virt), an ecall (a0 =
// status, a7 = 93, as a simulator's exit call), a store of the status word to
// an address, or an endless jump-to-self (a simulator stops there; on an
// FPGA the CPU just idles).
#pragma once

#include <stdint.h>

extern "C" [[noreturn]] void minrt_halt(int status);
