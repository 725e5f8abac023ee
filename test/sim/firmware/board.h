/* UART and finisher access for the test firmware (memory map shared with
 * firmware-sim through minrt/memory_map.h). */
#ifndef FWSIM_TEST_BOARD_H
#define FWSIM_TEST_BOARD_H
#include <minrt/memory_map.h>

#define UART_REG(off) (*(volatile unsigned char *)(MINRT_UART_BASE + (off)))

static inline void uart_init(void) {
  UART_REG(3) = 0x80; /* DLAB: divisor follows */
  UART_REG(0) = 0x01;
  UART_REG(1) = 0x00;
  UART_REG(3) = 0x03; /* 8N1 */
  UART_REG(2) = 0x07; /* FIFOs on */
  UART_REG(1) = 0x00; /* no interrupts */
}
static inline void uart_putc(char c) {
  while (!(UART_REG(MINRT_UART_REG_LSR) & MINRT_UART_LSR_THR_EMPTY)) {}
  UART_REG(MINRT_UART_REG_DATA) = (unsigned char)c;
}
static inline int uart_getc(void) {
  while (!(UART_REG(MINRT_UART_REG_LSR) & MINRT_UART_LSR_DATA_READY)) {}
  return UART_REG(MINRT_UART_REG_DATA);
}
void fw_exit(int code) __attribute__((noreturn));
#endif
