/* qemu-riscv32 (Linux user mode) side of the fuzz test: run the body, write
 * the dump to stdout, exit 0. */
  .text
  .globl _start
_start:
  call fuzz_body
  li a0, 1
  la a1, fuzz_dump
  li a2, 240
  li a7, 64          /* write */
  ecall
  li a0, 0
  li a7, 93          /* exit */
  ecall
