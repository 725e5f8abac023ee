/* Memory map of the reference RV32IMF board, shared by the firmware (runtime/),
 * its linker script (preprocessed with this header) and firmware-sim.
 * Laid out like QEMU's "virt" machine so qemu-system-riscv32 -M virt runs the
 * same ELF. Plain #defines so the linker script can use them too. */
#ifndef MINRT_MEMORY_MAP_H
#define MINRT_MEMORY_MAP_H

#define MINRT_RAM_BASE 0x80000000
#define MINRT_RAM_DEFAULT_SIZE 0x00400000 /* 4 MiB: the course machine's SRAM */

/* Program region of the course protocol's boot stage (runtime/program_loader.*):
 * a program uploaded after 0x99 is a flat binary (code and data, entry at its
 * first byte) loaded at MINRT_PROGRAM_LOAD_ADDR and started there. Its .bss,
 * heap and stack may use the RAM above its image, up to the boot-argument
 * block at the top. The resident firmware keeps its own image (code, data,
 * .bss) below the region; its render arena may overlap the region, which
 * holds a program only when the built-in renderer does not run. */
#define MINRT_PROGRAM_LOAD_ADDR 0x80100000
#define MINRT_PROGRAM_MAX_SIZE 0x00100000 /* 1 MiB of code and data */

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
#define MINRT_UART_BASE 0x10000000
#define MINRT_UART_REG_DATA 0 /* RBR on read, THR on write */
#define MINRT_UART_REG_LSR 5  /* line status */
#define MINRT_UART_LSR_DATA_READY 0x01
#define MINRT_UART_LSR_THR_EMPTY 0x20
#define MINRT_UART_SIZE 0x100

/* SiFive test finisher: write 0x5555 to stop with status 0,
 * (code << 16) | 0x3333 to stop with status `code`. */
#define MINRT_FINISHER_BASE 0x00100000
#define MINRT_FINISHER_PASS 0x5555
#define MINRT_FINISHER_FAIL 0x3333
#define MINRT_FINISHER_SIZE 0x1000

#endif
