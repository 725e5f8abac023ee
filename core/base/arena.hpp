// The one init-time arena: a bump allocator over a buffer the platform hands
// in. The renderer takes everything it needs from it before the first pixel
// and nothing afterwards.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace minrt {

class Arena {
 public:
  Arena(void* base, size_t size) : base_(static_cast<uint8_t*>(base)), size_(size), top_(size) {}

  // Zero-filled storage for n objects of T, or nullptr when it does not fit.
  template <class T>
  T* alloc_zeroed(size_t n) {
    T* p = alloc_uninit<T>(n);
    if (p != nullptr) {
      uint8_t* b = reinterpret_cast<uint8_t*>(p);
      for (size_t i = 0; i < n * sizeof(T); ++i) b[i] = 0;
    }
    return p;
  }

  // Storage for n objects of T left as the buffer held it, or nullptr when
  // it does not fit: for arrays sized for the worst case whose items are
  // each written whole before anything reads them, so the unused rest is
  // never touched (on the host, never even paged in).
  template <class T>
  T* alloc_uninit(size_t n) {
    const size_t align = alignof(T);
    size_t start = (used_ + align - 1) & ~(align - 1);
    const size_t bytes = n * sizeof(T);
    if (start > top_ || bytes > top_ - start) return nullptr;
    used_ = start + bytes;
    return reinterpret_cast<T*>(base_ + start);
  }

  // Scratch storage taken from the top end, for what a reader collects
  // before it knows the counts: it is released as a whole once the final
  // arrays (allocated from the bottom) have been filled from it.
  template <class T>
  T* alloc_top(size_t n) {
    const size_t bytes = n * sizeof(T);
    if (bytes > top_ - used_) return nullptr;
    size_t start = (top_ - bytes) & ~(alignof(T) - 1);
    if (start < used_) return nullptr;
    top_ = start;
    return reinterpret_cast<T*>(base_ + start);
  }
  size_t top_mark() const { return top_; }
  void release_top(size_t mark) { top_ = mark; }

  size_t used() const { return used_; }
  size_t capacity() const { return size_; }

  // Bytes `n` objects of T take, with worst-case alignment padding.
  template <class T>
  static constexpr size_t footprint(size_t n) {
    return n * sizeof(T) + alignof(T);
  }

 private:
  uint8_t* base_;
  size_t size_;
  size_t used_ = 0;
  size_t top_;  // start of the top-end scratch; size_ when there is none
};

}  // namespace minrt
