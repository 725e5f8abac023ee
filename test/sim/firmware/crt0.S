/* Minimal crt0 following include/minrt/boot_args.h: keep sp and take
 * argc/argv from a0/a1 when a3 holds the boot magic (firmware-sim), else set
 * sp from the linker script and call main(0, 0) (QEMU -M virt). */
  .section .text.start, "ax"
  .globl _start
  .type _start, @function
_start:
  li t0, 0x6000          /* mstatus.FS = dirty: QEMU starts with the FPU off */
  csrs mstatus, t0
  csrwi fcsr, 0
  li t0, 0x41524756      /* MINRT_BOOT_MAGIC */
  beq a3, t0, 1f
  la sp, __stack_top
  li a0, 0
  li a1, 0
1:
  la t0, __bss_start
  la t1, __bss_end
2:
  bgeu t0, t1, 3f
  sw zero, 0(t0)
  addi t0, t0, 4
  j 2b
3:
  call main
  call fw_exit
  .size _start, . - _start
