/* firmware-sim side of the fuzz test: run the body, send the dump over the
 * UART, stop through the finisher. */
  .section .text.start, "ax"
  .globl _start
_start:
  la sp, __stack_top
  call fuzz_body
  la t0, fuzz_dump
  addi t1, t0, 240
  li t2, 0x10000000  /* MINRT_UART_BASE */
1:
  lbu t3, 5(t2)
  andi t3, t3, 0x20
  beqz t3, 1b
  lbu t3, 0(t0)
  sb t3, 0(t2)
  addi t0, t0, 1
  bne t0, t1, 1b
  li t0, 0x100000    /* MINRT_FINISHER_BASE */
  li t1, 0x5555
  sw t1, 0(t0)
2:
  j 2b
