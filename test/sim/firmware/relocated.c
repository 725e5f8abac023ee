/* A bare-metal program for a memory map other than the board's: linked at
 * address 0 (link_at_zero.ld), UART and finisher where RELOC_UART and
 * RELOC_FINISHER say (relocated.machine gives firmware-sim the same map).
 * Prints where its code runs and its arguments, then exits with 7. */
#define UART(off) (*(volatile unsigned char *)(RELOC_UART + (off)))

static void putc_(char c) {
  while (!(UART(5) & 0x20)) {}
  UART(0) = (unsigned char)c;
}
static void puts_(const char *s) { while (*s) putc_(*s++); }
static void put_hex(unsigned v) {
  for (int i = 28; i >= 0; i -= 4) putc_("0123456789abcdef"[(v >> i) & 15]);
}

void fw_exit(int code) {
  *(volatile unsigned *)RELOC_FINISHER = code == 0 ? 0x5555u : ((unsigned)code << 16) | 0x3333u;
  for (;;) {}
}

int main(int argc, char **argv) {
  unsigned pc;
  __asm__ volatile("auipc %0, 0" : "=r"(pc));
  puts_("relocated: main at 0x");
  put_hex((unsigned)(unsigned long)&main);
  puts_(", pc 0x");
  put_hex(pc & ~0xfffu);
  puts_(", args");
  for (int i = 1; i < argc; ++i) { putc_(' '); puts_(argv[i]); }
  putc_('\n');
  return 7;
}
