// Walks the eight-wide hierarchy (wide_node.hpp): the nearest hit, nearest
// children first, and any hit for shadow rays. The caller tests the leaves'
// primitives; nothing here allocates or calls through a pointer.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "render/general/bvh.hpp"
#include "render/general/ray.hpp"
#include "render/general/simd_dispatch.hpp"
#include "render/general/wide_node.hpp"

namespace minrt::general {

// kBytes of values side by side (16: four floats or two doubles; 32: eight
// floats or four doubles): a GCC/Clang vector, which the compiler maps to
// the target's vector registers (16 bytes: one SSE2 register on any x86-64;
// 32: one AVX register, in code compiled for AVX2, simd_dispatch.hpp) or to
// scalar code where there are none. A node's eight boxes are tested in
// groups of kLanes. Only passed by reference: a vector by value would
// depend on the target's ABI.
template <class T, int kBytes>
struct LanesOf {
  typedef T type __attribute__((vector_size(kBytes)));
};
template <class T, int kBytes>
using Lanes = typename LanesOf<T, kBytes>::type;
template <class T, int kBytes>
inline constexpr int kLanes = kBytes / static_cast<int>(sizeof(T));
static_assert(kWideArity % kLanes<WideBox, 16> == 0 && kWideArity % kLanes<WideBox, 32> == 0, "whole groups per node");

#if MINRT_AVX2_DISPATCH
// movmsk on a whole 32-byte vector, for the AVX2 copy only. Not
// always_inline: GCC refuses that across the target change, and inlines it
// anyway once its caller sits in an AVX2 function.
MINRT_TARGET_AVX2 inline uint32_t sign_bits_avx(const Lanes<float, 32>& v) {
  return static_cast<uint32_t>(__builtin_ia32_movmskps256(v));
}
MINRT_TARGET_AVX2 inline uint32_t sign_bits_avx(const Lanes<double, 32>& v) {
  return static_cast<uint32_t>(__builtin_ia32_movmskpd256(v));
}
#endif

// Bit k set where lane k of a comparison result `met` (lanes the size of
// T: all ones or zero) is true: one movmsk on x86-64, a loop elsewhere.
template <class T, int kBytes, class Mask>
[[gnu::always_inline]] inline uint32_t true_lanes(const Mask& met) {
  static_assert(sizeof(Mask) == kBytes, "one vector");
#if MINRT_AVX2_DISPATCH
  Lanes<T, kBytes> v;
  __builtin_memcpy(&v, &met, sizeof v);
  if constexpr (kBytes == 32) {
    return sign_bits_avx(v);
  } else if constexpr (sizeof(T) == 8) {
    return static_cast<uint32_t>(__builtin_ia32_movmskpd(v));
  } else {
    return static_cast<uint32_t>(__builtin_ia32_movmskps(v));
  }
#else
  uint32_t bits = 0;
  for (int k = 0; k < kLanes<T, kBytes>; ++k) bits |= static_cast<uint32_t>(met[k] != 0) << k;
  return bits;
#endif
}

// The box test's margins: the float distances below carry at most four
// roundings of 2^-24 each (1/d to float, its product with the margin, the
// subtraction, the multiplication; the origin's is taken care of apart), so
// entries taken with 1/d scaled down and exits with 1/d scaled up by 2^-20
// are never later (or earlier) than the exact ones.
inline constexpr WideBox kEntryShrink = 1.0f - 1.0f / 1048576.0f;
inline constexpr WideBox kExitGrow = 1.0f + 1.0f / 1048576.0f;

// A ray as the box test wants it, in floats: for each axis, which bound it
// meets first (by the sign of the direction), 1/d in every lane scaled by
// the entry and exit margins, and the origin rounded toward the near bound
// for entries and away from it for exits, so that the rounding of the
// origin only widens the boxes.
template <int kBytes>
struct WideRay {
  using V = Lanes<WideBox, kBytes>;
  V near_origin[3];
  V far_origin[3];
  V near_inv[3];
  V far_inv[3];
  // Byte offsets in a node of each axis's near and far bounds (lo or hi,
  // by the sign of the direction): loads without a branch.
  uint32_t near_at[3];
  uint32_t far_at[3];

  template <class R>
  [[gnu::always_inline]] explicit WideRay(const Ray<R>& ray) {
    const Vec3<R> d = inverse_dir(ray.dir);
    const R o[3] = {ray.origin.x, ray.origin.y, ray.origin.z}, i[3] = {d.x, d.y, d.z};
    for (int a = 0; a < 3; ++a) {
      const WideBox f = static_cast<WideBox>(o[a]);
      // |f| / 2^23 is at least one step of f; f is within half a step of o.
      const WideBox step = (f < WideBox(0) ? -f : f) * WideBox(1.0f / 8388608.0f) + WideBox(1e-30f);
      const bool negative = i[a] < R(0);
      // Entry: (bound - origin) * inv as small as may be, so the origin is
      // taken above it for a positive direction and below for a negative.
      const WideBox near = negative ? f - step : f + step, far = negative ? f + step : f - step;
      near_origin[a] = V{} + near;
      far_origin[a] = V{} + far;
      const WideBox inv = static_cast<WideBox>(i[a]);
      near_inv[a] = V{} + inv * kEntryShrink;
      far_inv[a] = V{} + inv * kExitGrow;
      const uint32_t lo = static_cast<uint32_t>(offsetof(WideNode, lo) + sizeof(WideBox) * kWideArity * a);
      const uint32_t hi = static_cast<uint32_t>(offsetof(WideNode, hi) + sizeof(WideBox) * kWideArity * a);
      near_at[a] = negative ? hi : lo;
      far_at[a] = negative ? lo : hi;
    }
  }
};

// Slab test of the ray against the node's eight boxes at once: entry[k] is
// no later than where it enters box k (0 when it starts inside); bit k of
// the result is set when it may meet box k at or before `limit` (never
// clear where the exact test in the tracer's precision would meet it).
// For a positive 1/d the low bound gives the smaller distance, so picking
// the bound by the sign replaces the min/max of the two, and starting from
// [0, limit] replaces the clamp and the limit test.
template <int kBytes>
[[gnu::always_inline]] inline uint32_t wide_entry(const WideNode& n, const WideRay<kBytes>& r, WideBox limit,
                                                  WideBox (&entry)[kWideArity]) {
  using V = Lanes<WideBox, kBytes>;
  constexpr int kL = kLanes<WideBox, kBytes>;
  const char* base = reinterpret_cast<const char*>(&n);
  uint32_t mask = 0;
  for (int g = 0; g < kWideArity; g += kL) {
    V tmin{}, tmax = V{} + limit;
    for (int a = 0; a < 3; ++a) {
      V near, far;
      __builtin_memcpy(&near, base + r.near_at[a] + sizeof(WideBox) * g, sizeof near);
      __builtin_memcpy(&far, base + r.far_at[a] + sizeof(WideBox) * g, sizeof far);
      const V lo = (near - r.near_origin[a]) * r.near_inv[a];
      const V hi = (far - r.far_origin[a]) * r.far_inv[a];
      tmin = lo > tmin ? lo : tmin;
      tmax = hi < tmax ? hi : tmax;
    }
    __builtin_memcpy(entry + g, &tmin, sizeof tmin);
    mask |= true_lanes<WideBox, kBytes>(tmax >= tmin) << g;
  }
  return mask & n.used_mask;
}

// Nearest-hit walk. `limit()` is the distance of the best hit so far;
// `leaf(first, count)` tests references first .. first+count-1 and may
// lower it. A single child met is entered at once; several are pushed
// farthest first, so the nearest is taken next and the others are dropped
// when a closer hit has turned up by the time they come off the stack.
template <int kBytes, class R, class Limit, class Leaf>
[[gnu::always_inline]] inline void wide_nearest(const WideBvh<R>& tree, const Ray<R>& ray, Limit limit, Leaf leaf) {
  const WideRay<kBytes> r(ray);
  // A waiting child: its node (or a leaf's first reference), its count
  // (0 for a node) and its entry distance.
  struct Entry {
    uint32_t child;
    uint32_t count;
    WideBox t;
  };
  Entry stack[kWideStack];
  int top = 0;
  uint32_t current = 0;
  // limit() rounded to the nearest float, read again only after a leaf. An
  // entry distance (a float) beyond it is beyond limit() too: no float lies
  // between a value and its nearest float.
  WideBox bound = static_cast<WideBox>(limit());
  for (;;) {
    const WideNode& node = tree.nodes[current];
    WideBox entry[kWideArity];
    uint32_t mask = wide_entry(node, r, bound, entry);
    if (mask != 0 && (mask & (mask - 1)) == 0) {
      const int k = __builtin_ctz(mask);
      if (node.count[k] == 0) {
        current = node.child[k];
        continue;
      }
      leaf(node.child[k], node.count[k]);
      bound = static_cast<WideBox>(limit());
    } else {
      // Insert the met children in order of decreasing entry distance.
      const int base = top;
      while (mask != 0) {
        const int k = __builtin_ctz(mask);
        mask &= mask - 1;
        const Entry e{node.child[k], node.count[k], entry[k]};
        int i = top++;
        while (i > base && stack[i - 1].t < e.t) {
          stack[i] = stack[i - 1];
          --i;
        }
        stack[i] = e;
      }
    }
    bool descend = false;
    while (top > 0) {
      const Entry e = stack[--top];
      if (e.t > bound) continue;
      if (e.count == 0) {
        current = e.child;
        descend = true;
        break;
      }
      leaf(e.child, e.count);
      bound = static_cast<WideBox>(limit());
    }
    if (!descend) return;
  }
}

// Any-hit walk for shadow rays: `leaf(first, count)` says whether one of
// those references blocks the ray before `limit`. Leaves are tested as
// soon as their box is met; inner children wait on the stack.
template <int kBytes, class R, class Leaf>
[[gnu::always_inline]] inline bool wide_any(const WideBvh<R>& tree, const Ray<R>& ray, R limit, Leaf leaf) {
  const WideRay<kBytes> r(ray);
  const WideBox wide_limit = static_cast<WideBox>(limit);
  uint32_t stack[kWideStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const WideNode& node = tree.nodes[stack[--top]];
    WideBox entry[kWideArity];
    const uint32_t mask = wide_entry(node, r, wide_limit, entry);
    for (uint32_t inner = mask & ~node.leaf_mask; inner != 0; inner &= inner - 1)
      stack[top++] = node.child[__builtin_ctz(inner)];
    for (uint32_t leaves = mask & node.leaf_mask; leaves != 0; leaves &= leaves - 1) {
      const int k = __builtin_ctz(leaves);
      if (leaf(node.child[k], node.count[k])) return true;
    }
  }
  return false;
}

}  // namespace minrt::general
