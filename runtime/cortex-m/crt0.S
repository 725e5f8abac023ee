/* Cortex-M start-up of the port: the vector table (initial stack pointer,
 * reset, every fault to minrt_trap_entry), then what runtime/crt0.S does on
 * RISC-V: FPU on, .data copied from ROM, .bss cleared, the stack filled
 * with the footprint pattern, constructors, main(0, NULL), halt. */
#include <minrt/memory_map.h>
#include <minrt/serial_protocol.h>

#include "firmware_layout.h"

  .syntax unified
  .thumb

  .section .text.init, "ax", %progbits
  .globl minrt_vectors
minrt_vectors:
  .word __stack_top
  .word minrt_reset
  .rept 14
  .word minrt_trap_entry          /* NMI, HardFault ... SysTick; Thumb bit set by the linker */
  .endr

  .text
  .thumb_func
  .globl minrt_reset
  .type minrt_reset, %function
minrt_reset:
  /* CPACR: full access to CP10/CP11, the single-precision FPU. */
  ldr r0, =0xe000ed88
  ldr r1, [r0]
  orr r1, r1, #(0xf << 20)
  str r1, [r0]
  dsb
  isb

  ldr r0, =__data_load_start
  ldr r1, =__data_start
  ldr r2, =__data_end
1:
  cmp r1, r2
  bhs 2f
  ldr r3, [r0], #4
  str r3, [r1], #4
  b 1b
2:
  ldr r1, =__bss_start
  ldr r2, =__bss_end
  movs r3, #0
3:
  cmp r1, r2
  bhs 4f
  str r3, [r1], #4
  b 3b
4:
  ldr r0, =minrt_initial_sp
  mov r1, sp
  str r1, [r0]
  ldr r0, =__stack_bottom
  ldr r1, =MINRT_FW_STACK_PATTERN
  mov r2, sp
  bic r2, r2, #3
5:
  cmp r0, r2
  bhs 6f
  str r1, [r0], #4
  b 5b
6:
  ldr r4, =__init_array_start
  ldr r5, =__init_array_end
7:
  cmp r4, r5
  bhs 8f
  ldr r0, [r4], #4
  blx r0
  b 7b
8:
  movs r0, #0
  movs r1, #0
  bl main
  b minrt_halt
  .size minrt_reset, . - minrt_reset

  .thumb_func
  .globl minrt_trap_entry
  .type minrt_trap_entry, %function
minrt_trap_entry:
  movs r0, #MINRT_STATUS_TRAP
  b minrt_halt
  .size minrt_trap_entry, . - minrt_trap_entry

/* The course boot stage's jump into an uploaded program (runtime/program_start.S
 * on RISC-V): r0/r1 argc/argv, sp as given, r4 the handoff magic, r5 the
 * flags; Thumb code at MINRT_PROGRAM_LOAD_ADDR. */
  .thumb_func
  .globl minrt_start_program
  .type minrt_start_program, %function
minrt_start_program:
  dsb
  isb
  mov sp, r2
  ldr r4, =MINRT_PROGRAM_HANDOFF_MAGIC
  mov r5, r3
  ldr r2, =(MINRT_PROGRAM_LOAD_ADDR + 1)
  bx r2
  .size minrt_start_program, . - minrt_start_program
