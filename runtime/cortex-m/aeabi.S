/* Run-time helpers the ARM EABI names and clang calls on Cortex-M, mapped
 * onto the firmware's own (runtime/memory_functions.cpp,
 * runtime/int64_division.cpp): there is no libgcc or compiler-rt for
 * arm-none-eabi on the build machine, and the port needs only these. */
  .syntax unified
  .thumb
  .text

/* __aeabi_memcpy/memmove(dest, src, n): the C functions' argument order. */
  .globl __aeabi_memcpy, __aeabi_memcpy4, __aeabi_memcpy8
  .thumb_func
__aeabi_memcpy:
  .thumb_func
__aeabi_memcpy4:
  .thumb_func
__aeabi_memcpy8:
  b memcpy

  .globl __aeabi_memmove, __aeabi_memmove4, __aeabi_memmove8
  .thumb_func
__aeabi_memmove:
  .thumb_func
__aeabi_memmove4:
  .thumb_func
__aeabi_memmove8:
  b memmove

/* __aeabi_memset(dest, n, c) = memset(dest, c, n); memclr(dest, n) with 0. */
  .globl __aeabi_memset, __aeabi_memset4, __aeabi_memset8
  .thumb_func
__aeabi_memset:
  .thumb_func
__aeabi_memset4:
  .thumb_func
__aeabi_memset8:
  mov r3, r1
  mov r1, r2
  mov r2, r3
  b memset

  .globl __aeabi_memclr, __aeabi_memclr4, __aeabi_memclr8
  .thumb_func
__aeabi_memclr:
  .thumb_func
__aeabi_memclr4:
  .thumb_func
__aeabi_memclr8:
  mov r2, r1
  movs r1, #0
  b memset

/* __aeabi_uldivmod(n, d): quotient in r0:r1, remainder in r2:r3. */
  .globl __aeabi_uldivmod
  .thumb_func
  .type __aeabi_uldivmod, %function
__aeabi_uldivmod:
  push {r4-r8, lr}
  mov r4, r0
  mov r5, r1
  mov r6, r2
  mov r7, r3
  bl __udivdi3
  push {r0, r1}
  mov r0, r4
  mov r1, r5
  mov r2, r6
  mov r3, r7
  bl __umoddi3
  mov r2, r0
  mov r3, r1
  pop {r0, r1}
  pop {r4-r8, pc}
  .size __aeabi_uldivmod, . - __aeabi_uldivmod
