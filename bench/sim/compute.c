/* Compute-bound RV32IMF benchmark for firmware-sim: a float-heavy loop
 * (vector normalise, dot products, a Mandelbrot-style recurrence, one divide
 * and one square root per element) plus integer hashing and calls, about
 * 300 million instructions. Prints a checksum so the work cannot be elided. */
#include "board.h"

void fw_exit(int code) {
  volatile unsigned *fin = (volatile unsigned *)MINRT_FINISHER_BASE;
  *fin = code == 0 ? MINRT_FINISHER_PASS : ((unsigned)code << 16) | MINRT_FINISHER_FAIL;
  for (;;) {}
}

#define N 1024
static float vx[N], vy[N], vz[N];

__attribute__((noinline)) static float shade(float x, float y, float z) {
  float len = __builtin_sqrtf(x * x + y * y + z * z);
  float inv = 1.0f / (len + 1e-6f);
  float d = x * inv * 0.3f + y * inv * 0.5f + z * inv * 0.8f;
  return d > 0.0f ? d : 0.0f;
}

__attribute__((noinline)) static unsigned mix(unsigned h, unsigned v) {
  h ^= v * 2654435761u;
  return (h << 7 | h >> 25) * 16777619u;
}

__attribute__((noinline)) static float orbit(float cr, float ci) {
  float zr = 0.0f, zi = 0.0f;
  int k = 0;
  while (k < 24 && zr * zr + zi * zi < 4.0f) {
    float t = zr * zr - zi * zi + cr;
    zi = 2.0f * zr * zi + ci;
    zr = t;
    ++k;
  }
  return (float)k;
}

int main(int argc, char **argv) {
  (void)argc; (void)argv;
  for (int i = 0; i < N; ++i) {
    vx[i] = (float)(i % 37) * 0.1f - 1.5f;
    vy[i] = (float)(i % 23) * 0.13f - 1.2f;
    vz[i] = (float)(i % 11) * 0.2f + 0.1f;
  }
  float acc = 0.0f;
  unsigned h = 1;
  for (int rep = 0; rep < 600; ++rep) {
    for (int i = 0; i < N; ++i) {
      acc += shade(vx[i], vy[i], vz[i]);
      acc += orbit(vx[i] * 0.5f, vy[i] * 0.5f) * 0.001f;
      h = mix(h, (unsigned)i + (unsigned)rep);
    }
  }
  union { float f; unsigned u; } c = {acc};
  static const char hex[] = "0123456789abcdef";
  const char *msg = "checksum ";
  while (*msg) uart_putc(*msg++);
  for (int s = 28; s >= 0; s -= 4) uart_putc(hex[(c.u >> s) & 15]);
  uart_putc(' ');
  for (int s = 28; s >= 0; s -= 4) uart_putc(hex[(h >> s) & 15]);
  uart_putc('\n');
  return 0;
}
