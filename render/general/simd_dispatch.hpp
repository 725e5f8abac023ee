// The vector width of the wide BVH walk (wide_traversal.hpp). Every x86-64
// has SSE2, so the walk's 16-byte vectors need nothing; on an x86-64 whose
// CPU has AVX2 the tracer runs a second copy of the walk compiled for AVX2
// (the GCC target attribute on that one function) with a node's eight
// float boxes in one register, chosen once at set-up. Other targets (the RV32
// board, which walks the binary tree) compile none of this.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__)
#define MINRT_AVX2_DISPATCH 1
#define MINRT_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define MINRT_AVX2_DISPATCH 0
#endif

namespace minrt::general {

// Whether this CPU runs the AVX2 copy.
inline bool cpu_has_avx2() {
#if MINRT_AVX2_DISPATCH
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

// A leaf's spheres as one vector of the AVX2 copy: four doubles (32 bytes)
// or four floats (16); a node's eight float boxes: one 32-byte vector.
template <class R>
inline constexpr int kAvx2Bytes = 4 * static_cast<int>(sizeof(R));
inline constexpr int kAvx2BoxBytes = 32;

}  // namespace minrt::general
