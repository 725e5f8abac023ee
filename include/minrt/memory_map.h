/* Memory map of the board the firmware is built for, shared by the firmware
 * (runtime/), its linker script (preprocessed with this header), firmware-sim
 * and the host tools. The board's own values (RAM, UART, halt device) come
 * from <minrt/board.h>, generated from a boards/NAME.board file by
 * cmake/minrt_board.cmake: the firmware build puts its board's header ahead
 * of include/ on the include path; everything else gets include/minrt/board.h,
 * the reference board's (boards/qemu-virt.board, laid out like QEMU's "virt"
 * machine so qemu-system-riscv32 -M virt runs the same ELF). This file holds
 * what is the same on every board. Plain #defines so the linker script can
 * use them too. */
#ifndef MINRT_MEMORY_MAP_H
#define MINRT_MEMORY_MAP_H

/* Kinds of UART and of halt device a board file names (MINRT_BOARD_UART,
 * MINRT_BOARD_HALT in board.h). */
#define MINRT_UART_KIND_NS16550 1
#define MINRT_UART_KIND_LITEX 2
#define MINRT_UART_KIND_SIFIVE 3
#define MINRT_UART_KIND_GENERIC 4
#define MINRT_HALT_KIND_FINISHER 1
#define MINRT_HALT_KIND_ECALL 2
#define MINRT_HALT_KIND_STORE 3
#define MINRT_HALT_KIND_LOOP 4
/* The Cortex-M port's (runtime/cortex-m/minrt/board.h), no board-file kinds. */
#define MINRT_UART_KIND_CMSDK 5
#define MINRT_HALT_KIND_SEMIHOSTING 5

/* What the firmware does after an image (MINRT_BOARD_AFTER_IMAGE, board
 * file key after_image): wait for the next scene, or halt. */
#define MINRT_AFTER_IMAGE_SERVE 0
#define MINRT_AFTER_IMAGE_HALT 1

#include <minrt/board.h>

/* A board header written by hand (the Cortex-M port's) may leave these out. */
#ifndef MINRT_BOARD_ZIFENCEI
#define MINRT_BOARD_ZIFENCEI 0
#endif
#ifndef MINRT_BOARD_ISA
#define MINRT_BOARD_ISA "unknown"
#endif
#ifndef MINRT_BOARD_CLOCK_HZ
#define MINRT_BOARD_CLOCK_HZ 0u
#endif
#ifndef MINRT_BOARD_AFTER_IMAGE
#define MINRT_BOARD_AFTER_IMAGE MINRT_AFTER_IMAGE_SERVE
#endif
#ifndef MINRT_BOARD_WAIT_POLLS
#define MINRT_BOARD_WAIT_POLLS 0u
#endif

/* Program region of the course protocol's boot stage (runtime/program_loader.*):
 * a program uploaded after 0x99 is a flat binary (code and data, entry at its
 * first byte) loaded at MINRT_PROGRAM_LOAD_ADDR and started there. Its .bss,
 * heap and stack may use the RAM above its image, up to the boot-argument
 * block at the top. The resident firmware keeps its own image (code, data,
 * .bss) below the region; its render arena may overlap the region, which
 * holds a program only when the built-in renderer does not run. */
#if MINRT_RAM_DEFAULT_SIZE >= 0x00400000
#define MINRT_PROGRAM_LOAD_ADDR (MINRT_RAM_BASE + 0x00100000)
#define MINRT_PROGRAM_MAX_SIZE 0x00100000 /* 1 MiB of code and data */
#else
/* Less than 4 MiB of RAM: no room for a second image, every upload is
 * refused as too large. */
#define MINRT_PROGRAM_LOAD_ADDR MINRT_RAM_BASE
#define MINRT_PROGRAM_MAX_SIZE 0
#endif

/* Registers at the program's entry (runtime/program_start.S):
 *   a0, a1, a3, sp   argc, argv, MINRT_BOOT_MAGIC and the stack as the boot
 *                    loader got them from firmware-sim (a3 = 0 without them)
 *   a4               MINRT_PROGRAM_HANDOFF_MAGIC: a5 is valid
 *   a5               MINRT_PROGRAM_LOADED | MINRT_PROGRAM_BIG_ENDIAN if the
 *                    host sends big-endian words
 * A program that finds the magic has had its 0x99 stage done by the boot
 * loader and goes straight on with 0xaa. */
#define MINRT_PROGRAM_HANDOFF_MAGIC 0x4c4f4144 /* "DAOL" */
#define MINRT_PROGRAM_LOADED 0x1
#define MINRT_PROGRAM_BIG_ENDIAN 0x2

/* NS16550A-compatible UART, byte-wide registers. */
#define MINRT_UART_REG_DATA 0 /* RBR on read, THR on write */
#define MINRT_UART_REG_LSR 5  /* line status */
#define MINRT_UART_LSR_DATA_READY 0x01
#define MINRT_UART_LSR_THR_EMPTY 0x20
#define MINRT_UART_SIZE 0x100

/* SiFive test finisher: write 0x5555 to stop with status 0,
 * (code << 16) | 0x3333 to stop with status `code`. */
#if MINRT_BOARD_HALT == MINRT_HALT_KIND_FINISHER
#define MINRT_FINISHER_BASE MINRT_BOARD_HALT_ADDR
#endif
#define MINRT_FINISHER_PASS 0x5555
#define MINRT_FINISHER_FAIL 0x3333
#define MINRT_FINISHER_SIZE 0x1000

#endif
