/* Board test program: echoes UART input up to and including the first
 * newline, then halts with the number of bytes echoed as its status.
 * Assembled per board with -D: UART_KIND (1 ns16550, 2 litex, 3 sifive,
 * 4 generic; generic also GEN_DATA, GEN_STATUS, GEN_TX, GEN_RX, GEN_WIDTH,
 * and optionally GEN_INIT_OFF/GEN_INIT_VAL: one register write first),
 * UART_BASE, HALT_KIND (1 finisher, 2 ecall, 3 store, 4 loop), HALT_ADDR. */
#if GEN_WIDTH == 1
#define GEN_LOAD lbu
#define GEN_STORE sb
#else
#define GEN_LOAD lw
#define GEN_STORE sw
#endif

  .section .text.start, "ax"
  .globl _start
_start:
  li s0, UART_BASE
  li s1, 0
#ifdef GEN_INIT_OFF
  li t0, GEN_INIT_VAL
  GEN_STORE t0, GEN_INIT_OFF(s0)
#endif
#if UART_KIND == 3
  li t0, 1
  sw t0, 8(s0)           /* txctrl.txen */
  sw t0, 12(s0)          /* rxctrl.rxen */
#endif
next:
  /* a0 = next input byte, waiting for it */
#if UART_KIND == 1
1: lbu t0, 5(s0)
  andi t0, t0, 1
  beqz t0, 1b
  lbu a0, 0(s0)
#elif UART_KIND == 2
1: lw t0, 8(s0)          /* rxempty */
  bnez t0, 1b
  lw a0, 0(s0)
#elif UART_KIND == 3
1: lw a0, 4(s0)          /* rxdata, bit 31 = empty */
  bltz a0, 1b
#else
1: GEN_LOAD t0, GEN_STATUS(s0)
  li t1, GEN_RX
  and t0, t0, t1
  beqz t0, 1b
  GEN_LOAD a0, GEN_DATA(s0)
#endif
  andi a0, a0, 0xff
  /* send a0, waiting until the transmitter takes it */
#if UART_KIND == 1
2: lbu t0, 5(s0)
  andi t0, t0, 0x20
  beqz t0, 2b
  sb a0, 0(s0)
#elif UART_KIND == 2
2: lw t0, 4(s0)          /* txfull */
  bnez t0, 2b
  sw a0, 0(s0)
#elif UART_KIND == 3
2: lw t0, 0(s0)          /* txdata, bit 31 = full */
  bltz t0, 2b
  sw a0, 0(s0)
#else
2: GEN_LOAD t0, GEN_STATUS(s0)
  li t1, GEN_TX
  and t0, t0, t1
  beqz t0, 2b
  GEN_STORE a0, GEN_DATA(s0)
#endif
  addi s1, s1, 1
  li t0, 10
  bne a0, t0, next
  mv a0, s1
#if HALT_KIND == 1
  slli a0, a0, 16
  li t0, 0x3333
  or a0, a0, t0
  li t0, HALT_ADDR
  sw a0, 0(t0)
#elif HALT_KIND == 2
  li a7, 93
  ecall
#elif HALT_KIND == 3
  li t0, HALT_ADDR
  sw a0, 0(t0)
#else
  j .
#endif
  /* not reached: an unhalted run stops at the next, illegal, word */
  .word 0
