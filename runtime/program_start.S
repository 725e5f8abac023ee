/* minrt_start_program(argc, argv, sp, flags): enter the program the course
 * boot stage loaded at MINRT_PROGRAM_LOAD_ADDR, with the registers
 * memory_map.h describes. Never returns: the program halts the machine. */
#include <minrt/memory_map.h>

#include "firmware_layout.h"

  .text
  .balign 4
  .globl minrt_start_program
  .type minrt_start_program, @function
minrt_start_program:
#if MINRT_BOARD_ZIFENCEI
  fence.i                /* the code arrived through stores: resync fetch */
#endif
  /* Without Zifencei (board file: zifencei = no) the stores and this jump
   * are all there is: enough on a core that fetches from the same memory
   * the stores reach, with no instruction cache or prefetch buffer holding
   * old words of the program region (docs/porting.md). */
  mv sp, a2
  li a4, MINRT_PROGRAM_HANDOFF_MAGIC
  mv a5, a3
  li a3, 0
  beqz a1, 1f            /* no argv: the program takes its build defaults */
  li a3, MINRT_BOOT_MAGIC
1:
  li a2, 0
  li t0, MINRT_PROGRAM_LOAD_ADDR
  jr t0
  .size minrt_start_program, . - minrt_start_program
