/* Entry point: set up the C++ environment and run main(argc, argv).
 *
 * firmware-sim passes argc/argv in a0/a1 with a3 = MINRT_BOOT_MAGIC and sp
 * already below its argument block (include/minrt/boot_args.h); anything
 * else (QEMU -M virt: a0 = hart id, a1 = device tree) gets the linker
 * script's stack and main(0, NULL), i.e. the build-time defaults. */
#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "firmware_layout.h"

  .section .text.init, "ax", @progbits
  .globl _start
  .type _start, @function
_start:
#if MINRT_BOARD_ZICSR
  la t0, minrt_trap_entry
  csrw mtvec, t0
#ifdef __riscv_flen
  li t0, 0x2000          /* mstatus.FS = Initial: QEMU traps FP otherwise */
  csrs mstatus, t0
  fscsr zero             /* round to nearest even, no flags */
#endif
#endif
  /* Without Zicsr (board file: zicsr = no) there is no trap vector to set:
   * a CPU exception goes wherever the core sends it. */

  /* Handoff from the course boot loader (memory_map.h): a5 when a4 holds
   * the magic, kept in s4 until .bss is cleared. */
  li s4, 0
  li t0, MINRT_PROGRAM_HANDOFF_MAGIC
  bne a4, t0, 0f
  mv s4, a5
0:
  li t0, MINRT_BOOT_MAGIC
  beq a3, t0, 1f
  la sp, __stack_top
  li a0, 0
  li a1, 0
1:
  mv s0, a0
  mv s1, a1

  /* .data: copy from its load address when that differs. */
  la t0, __data_load_start
  la t1, __data_start
  la t2, __data_end
  beq t0, t1, 3f
2:
  bgeu t1, t2, 3f
  lw t3, 0(t0)
  sw t3, 0(t1)
  addi t0, t0, 4
  addi t1, t1, 4
  j 2b
3:
  /* .bss: zero. */
  la t0, __bss_start
  la t1, __bss_end
4:
  bgeu t0, t1, 5f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 4b
5:
  la t0, minrt_initial_sp   /* where the stack starts, for the footprint */
  sw sp, 0(t0)
  la t0, minrt_program_handoff
  sw s4, 0(t0)
  /* Stack: fill up to sp with the pattern for the high-water report. */
  la t0, __stack_bottom
  li t1, MINRT_FW_STACK_PATTERN
  andi t2, sp, -4
6:
  bgeu t0, t2, 7f
  sw t1, 0(t0)
  addi t0, t0, 4
  j 6b
7:
  /* Static constructors, if any. */
  la s2, __init_array_start
  la s3, __init_array_end
8:
  bgeu s2, s3, 9f
  lw t0, 0(s2)
  jalr t0
  addi s2, s2, 4
  j 8b
9:
  mv a0, s0
  mv a1, s1
  call main
  tail minrt_halt        /* with main's return value in a0 */
  .size _start, . - _start

/* Any exception ends the run with MINRT_STATUS_TRAP (serial_protocol.h). */
  .text
  .balign 4
  .globl minrt_trap_entry
  .type minrt_trap_entry, @function
minrt_trap_entry:
  li a0, MINRT_STATUS_TRAP
  tail minrt_halt
  .size minrt_trap_entry, . - minrt_trap_entry
