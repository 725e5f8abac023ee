/* The board header of the Cortex-M port (runtime/cortex-m/, docs/porting.md
 * "A CPU that is not RISC-V"): QEMU's mps2-an386 (ARM MPS2 with the AN386
 * Cortex-M4 image). Written by hand, in the form cmake/minrt_board.cmake
 * generates for RISC-V boards, since a board file describes RV32 CPUs.
 *   0x00000000  SSRAM1, 4 MiB: vector table, code and read-only data
 *   0x20000000  SSRAM2/3, 4 MiB: .data, .bss, arena, stack
 *   0x40004000  UART0, a CMSDK APB UART */
#ifndef MINRT_BOARD_H
#define MINRT_BOARD_H

#define MINRT_BOARD_NAME "mps2-an386"
#define MINRT_BOARD_ZICSR 0
#define MINRT_BOARD_ISA "armv7e-m+fp"
/* QEMU runs it once per scene (its test): halt after the image. */
#define MINRT_BOARD_AFTER_IMAGE MINRT_AFTER_IMAGE_HALT
#define MINRT_BOARD_RESET 0x00000000
#define MINRT_RAM_BASE 0x20000000
#define MINRT_RAM_DEFAULT_SIZE 0x00400000
#define MINRT_BOARD_ROM_BASE 0x00000000
#define MINRT_BOARD_ROM_SIZE 0x00400000
#define MINRT_BOARD_UART MINRT_UART_KIND_CMSDK
#define MINRT_UART_BASE 0x40004000
#define MINRT_BOARD_HALT MINRT_HALT_KIND_SEMIHOSTING

#endif
