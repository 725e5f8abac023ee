// memset, memcpy, memmove and memcmp: the compiler emits calls to them (struct
// copies, zeroing) even in freestanding code, and there is no C library.
// Word-at-a-time when both pointers allow it, bytes otherwise. The
// no_builtin attribute keeps the compiler from turning these loops back into
// calls to themselves.
#include <stddef.h>
#include <stdint.h>

namespace {

constexpr uintptr_t kWord = sizeof(uint32_t);

bool word_aligned(const void* p) { return (reinterpret_cast<uintptr_t>(p) & (kWord - 1)) == 0; }

}  // namespace

extern "C" {

__attribute__((no_builtin)) void* memset(void* dest, int value, size_t n) {
  auto* d = static_cast<uint8_t*>(dest);
  const auto byte = static_cast<uint8_t>(value);
  while (n != 0 && !word_aligned(d)) {
    *d++ = byte;
    --n;
  }
  const uint32_t word = 0x01010101u * byte;
  for (; n >= kWord; n -= kWord, d += kWord) *reinterpret_cast<uint32_t*>(d) = word;
  while (n-- != 0) *d++ = byte;
  return dest;
}

__attribute__((no_builtin)) void* memcpy(void* __restrict dest, const void* __restrict src,
                                         size_t n) {
  auto* d = static_cast<uint8_t*>(dest);
  const auto* s = static_cast<const uint8_t*>(src);
  if (((reinterpret_cast<uintptr_t>(d) ^ reinterpret_cast<uintptr_t>(s)) & (kWord - 1)) == 0) {
    while (n != 0 && !word_aligned(d)) {
      *d++ = *s++;
      --n;
    }
    for (; n >= kWord; n -= kWord, d += kWord, s += kWord)
      *reinterpret_cast<uint32_t*>(d) = *reinterpret_cast<const uint32_t*>(s);
  }
  while (n-- != 0) *d++ = *s++;
  return dest;
}

__attribute__((no_builtin)) void* memmove(void* dest, const void* src, size_t n) {
  auto* d = static_cast<uint8_t*>(dest);
  const auto* s = static_cast<const uint8_t*>(src);
  if (d == s || n == 0) return dest;
  // Forward copy is safe unless dest starts inside [src, src + n).
  if (reinterpret_cast<uintptr_t>(d) - reinterpret_cast<uintptr_t>(s) >= n)
    return memcpy(dest, src, n);
  d += n;
  s += n;
  while (n-- != 0) *--d = *--s;
  return dest;
}

__attribute__((no_builtin)) int memcmp(const void* a, const void* b, size_t n) {
  const auto* x = static_cast<const uint8_t*>(a);
  const auto* y = static_cast<const uint8_t*>(b);
  for (size_t i = 0; i < n; ++i)
    if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
  return 0;
}

}  // extern "C"
