/* Board ISA test program: runs one instruction from an extension, then
 * exits through the finisher at 0x100000 with the result as status.
 * -DPROBE=1 mul (M), 2 x16 (not in rv32e), 3 csrr (Zicsr), 4 a compressed
 * c.addi (C), 5 fadd.s (F), 6 fence.i (Zifencei). */
  .section .text.start, "ax"
  .globl _start
_start:
  li a0, 6
  li a1, 7
#if PROBE == 1
  mul a0, a0, a1         /* 42 */
#elif PROBE == 2
  mv x16, a1
  add a0, a0, x16        /* 13 */
#elif PROBE == 3
  csrr t0, mscratch
  addi a0, t0, 20        /* 20: mscratch starts at 0 */
#elif PROBE == 4
  .2byte 0x0511          /* c.addi a0, 4: 10 */
  .2byte 0x0001          /* c.nop, keeps the next word aligned */
#elif PROBE == 5
  fcvt.s.w ft0, a0
  fadd.s ft0, ft0, ft0
  fcvt.w.s a0, ft0       /* 12 */
#elif PROBE == 6
  .word 0x0000100f       /* fence.i, spelled out: assemblers differ on Zifencei */
  add a0, a0, a1         /* 13 */
#endif
  slli a0, a0, 16
  li t0, 0x3333
  or a0, a0, t0
  li t0, 0x100000
  sw a0, 0(t0)
  .word 0
