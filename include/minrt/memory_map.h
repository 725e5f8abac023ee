/* Memory map of the reference RV32IMF board, shared by the firmware (runtime/),
 * its linker script (preprocessed with this header) and firmware-sim.
 * Laid out like QEMU's "virt" machine so qemu-system-riscv32 -M virt runs the
 * same ELF. Plain #defines so the linker script can use them too. */
#ifndef MINRT_MEMORY_MAP_H
#define MINRT_MEMORY_MAP_H

#define MINRT_RAM_BASE 0x80000000
#define MINRT_RAM_DEFAULT_SIZE 0x00400000 /* 4 MiB: the course machine's SRAM */

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
