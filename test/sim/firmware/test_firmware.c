/* Test firmware for firmware-sim. Without arguments (as under QEMU) it runs
 * the integer/float workload whose UART output the QEMU comparison checks;
 * with argv[1] it runs one behaviour the CLI tests need. */
#include "board.h"

void fw_exit(int code) {
  volatile unsigned *fin = (volatile unsigned *)MINRT_FINISHER_BASE;
  *fin = code == 0 ? MINRT_FINISHER_PASS : ((unsigned)code << 16) | MINRT_FINISHER_FAIL;
  for (;;) {}
}

static void puts_(const char *s) { while (*s) uart_putc(*s++); }
static void put_u(unsigned v) {
  char b[12];
  int n = 0;
  do { b[n++] = (char)('0' + v % 10); v /= 10; } while (v);
  while (n) uart_putc(b[--n]);
}
static void put_i(int v) {
  if (v < 0) { uart_putc('-'); put_u(0u - (unsigned)v); } else put_u((unsigned)v);
}
static void put_hex(unsigned v) {
  for (int i = 28; i >= 0; i -= 4) uart_putc("0123456789abcdef"[(v >> i) & 15]);
}
static unsigned bits(float f) { union { float f; unsigned u; } c = {f}; return c.u; }
static int streq(const char *a, const char *b) {
  while (*a && *a == *b) { ++a; ++b; }
  return *a == *b;
}
static int atoi_(const char *s) {
  int v = 0, neg = *s == '-';
  if (neg) ++s;
  while (*s >= '0' && *s <= '9') v = v * 10 + (*s++ - '0');
  return neg ? -v : v;
}

/* Recursive and mutually calling functions give the profiler a real tree. */
/* Two real calls per level: `3a - b` keeps the compiler from turning one of
 * them into a loop, so the profile's call count equals recur_calls. */
static unsigned recur_calls;
__attribute__((noinline)) static unsigned recur(unsigned n) {
  ++recur_calls;
  return n < 2 ? n : 3 * recur(n - 1) - recur(n - 2);
}
__attribute__((noinline)) static float dot(const float *a, const float *b, int n) {
  float s = 0.0f;
  for (int i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}
__attribute__((noinline)) static float newton_sqrt(float x) {
  float g = x > 1.0f ? x : 1.0f;
  for (int i = 0; i < 20; ++i) g = 0.5f * (g + x / g);
  return g;
}

static volatile float vol_zero = 0.0f;

static void workload(void) {
  puts_("fwsim test workload\n");
  unsigned h = 2166136261u;
  for (unsigned i = 0; i < 1000; ++i) { h ^= i * 2654435761u; h *= 16777619u; h += h >> 13; }
  puts_("hash "); put_hex(h); uart_putc('\n');
  int q = -7, d = 2;
  puts_("div "); put_i(q / d); uart_putc(' '); put_i(q % d); uart_putc(' ');
  put_u(0xfffffff0u / 3u); uart_putc('\n');
  puts_("recur "); put_u(recur(18)); uart_putc('\n');
  float a[16], b[16];
  for (int i = 0; i < 16; ++i) { a[i] = 1.0f / (float)(i + 1); b[i] = (float)i * 0.37f - 2.0f; }
  puts_("dot "); put_hex(bits(dot(a, b, 16))); uart_putc('\n');
  for (int i = 1; i < 8; ++i) {
    float x = (float)i * 1.7f;
    puts_("sqrt "); put_hex(bits(newton_sqrt(x))); uart_putc(' ');
    put_hex(bits(__builtin_sqrtf(x))); uart_putc(' ');
    put_i((int)(x * 1000.0f)); uart_putc('\n');
  }
  float inf = 1.0f / vol_zero, nan = vol_zero / vol_zero;
  puts_("special "); put_hex(bits(inf)); uart_putc(' '); put_hex(bits(nan)); uart_putc(' ');
  put_i((int)inf); uart_putc(' '); put_i((int)nan); uart_putc('\n');
  unsigned flags;
  __asm__ volatile("frflags %0" : "=r"(flags));
  puts_("fflags "); put_hex(flags); uart_putc('\n');
  /* A tiny Mandelbrot: many dependent float ops and branches. */
  for (int y = -6; y <= 6; ++y) {
    for (int x = -20; x <= 8; ++x) {
      float cr = (float)x / 10.0f, ci = (float)y / 6.0f, zr = 0.0f, zi = 0.0f;
      int k = 0;
      while (k < 50 && zr * zr + zi * zi < 4.0f) { float t = zr * zr - zi * zi + cr; zi = 2.0f * zr * zi + ci; zr = t; ++k; }
      uart_putc(" .:-=+*#%@"[k % 10]);
    }
    uart_putc('\n');
  }
}

int main(int argc, char **argv) {
  uart_init();
  if (argc < 2) { workload(); return 0; }
  const char *mode = argv[1];
  if (streq(mode, "args")) {
    put_i(argc);
    for (int i = 1; i < argc; ++i) { uart_putc(' '); puts_(argv[i]); }
    uart_putc('\n');
    return 0;
  }
  if (streq(mode, "exit")) return atoi_(argv[2]);
  if (streq(mode, "echo")) {  /* uppercase echo until 'q' */
    for (;;) {
      int c = uart_getc();
      if (c == 'q') return 0;
      uart_putc((char)(c >= 'a' && c <= 'z' ? c - 32 : c));
    }
  }
  if (streq(mode, "spin")) for (;;) { __asm__ volatile(""); }
  if (streq(mode, "illegal")) __asm__ volatile(".word 0xffffffff");
  if (streq(mode, "ebreak")) __asm__ volatile("ebreak");
  if (streq(mode, "ecall")) __asm__ volatile("ecall");
  if (streq(mode, "load-fault")) return *(volatile int *)0x40000000;
  if (streq(mode, "misaligned")) {
    /* An aligned word plus one: argv strings have no fixed alignment (they
       follow argv[0], the ELF's path), so they cannot serve as the base. */
    static volatile int words[2];
    return *(volatile int *)((volatile char *)words + 1);
  }
  if (streq(mode, "counters")) {
    unsigned c0, i0, c1, i1, t;
    __asm__ volatile("rdcycle %0\n rdinstret %1" : "=r"(c0), "=r"(i0));
    for (volatile int k = 0; k < 1000; ++k) {}
    __asm__ volatile("rdcycle %0\n rdinstret %1\n rdtime %2" : "=r"(c1), "=r"(i1), "=r"(t));
    puts_(i1 - i0 > 1000 && c1 - c0 >= i1 - i0 ? "counters ok\n" : "counters bad\n");
    return 0;
  }
  if (streq(mode, "recur")) {
    put_u(recur((unsigned)atoi_(argv[2])));
    uart_putc(' ');
    put_u(recur_calls);
    uart_putc('\n');
    return 0;
  }
  puts_("unknown mode\n");
  return 1;
}
