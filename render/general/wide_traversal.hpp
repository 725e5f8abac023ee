// Walks the eight-wide hierarchy (wide_node.hpp): the nearest hit, nearest
// children first, and any hit for shadow rays. The caller tests the leaves'
// primitives; nothing here allocates or calls through a pointer.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/math/float_step.hpp"
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

// Every lane x: a broadcast. x - 0 is x for every x (-0 included), so the
// subtraction is dropped; `V{} + x` would turn -0 into +0 and is kept.
template <class V, class T>
[[gnu::always_inline]] inline void splat(V& out, T x) {
  out = x - V{};
}

// `v` read through an address the optimiser cannot follow, taken anew at
// each call: what is read through it is read from memory there (as the
// memory operand of the instruction that uses it) instead of being loaded
// once and held in registers. The walks' ray vectors (12 for the boxes, 6
// for the spheres) do not all fit in the vector registers; held there
// they would be stored and reloaded around every leaf.
template <class T>
[[gnu::always_inline]] inline T& from_memory(T& v) {
  T* p = &v;
  asm volatile("" : "+r"(p));
  return *p;
}

// The box test's floats for lanes of origins `o` and directions `d` in the
// tracer's precision (the three axes of one ray, or one axis of a packet's
// rays): the origin rounded toward each lane's near bound for entries and
// away from it for exits, 1/d (kTinyDirection for 0, as inverse_dir in
// bvh.hpp) scaled by the margins, and which lanes point down their axis.
template <class F, class I, class Reals>
[[gnu::always_inline]] inline void slab_lanes(const Reals& o, const Reals& d, F& near_origin, F& far_origin,
                                              F& near_inv, F& far_inv, I& negative) {
  using R = __typeof__(o[0] + 0);
  const Reals i = R(1) / (d == R(0) ? kTinyDirection<R> - Reals{} : d);
  const F f = __builtin_convertvector(o, F);
  F step;
  if constexpr (sizeof(F) > 16) {
    // (a 32-byte vector may not pass through a call)
    for (int k = 0; k < static_cast<int>(sizeof(F) / sizeof(WideBox)); ++k) step[k] = float_step_bound(f[k]);
  } else {
    step = float_step_bound(f);
  }
  negative = __builtin_convertvector(i < R(0), I);
  // Entry: (bound - origin) * inv as small as may be, so the origin is
  // taken above it for a positive direction and below for a negative.
  const F above = f + step, below = f - step;
  near_origin = negative != 0 ? below : above;
  far_origin = negative != 0 ? above : below;
  const F inv = __builtin_convertvector(i, F);
  near_inv = inv * kEntryShrink;
  far_inv = inv * kExitGrow;
}

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
  V limit;  // the distance the walk looks up to, in every lane
  // Byte offsets in a node of each axis's near and far bounds (lo or hi,
  // by the sign of the direction): loads without a branch.
  uint32_t near_at[3];
  uint32_t far_at[3];

  // The three axes side by side in the lanes of one vector (a fourth,
  // unused, to fill it): the same operations as one axis at a time.
  template <class R>
  [[gnu::always_inline]] WideRay(const Ray<R>& ray, WideBox up_to) {
    using Axes = Lanes<R, 4 * static_cast<int>(sizeof(R))>;
    using FloatAxes = Lanes<WideBox, 16>;
    using Signs = Lanes<int32_t, 16>;
    const Axes o = {ray.origin.x, ray.origin.y, ray.origin.z, R(0)};
    const Axes d = {ray.dir.x, ray.dir.y, ray.dir.z, R(1)};
    // inverse_dir (bvh.hpp), lane by lane.
    FloatAxes near, far, near_i, far_i;
    Signs negative;
    slab_lanes(o, d, near, far, near_i, far_i, negative);
    const uint32_t signs = true_lanes<WideBox, 16>(negative);
    for (int a = 0; a < 3; ++a) {
      splat(near_origin[a], near[a]);
      splat(far_origin[a], far[a]);
      splat(near_inv[a], near_i[a]);
      splat(far_inv[a], far_i[a]);
      const uint32_t lo = wide_bound_at(a, false), hi = wide_bound_at(a, true);
      const bool neg = (signs >> a & 1u) != 0;
      near_at[a] = neg ? hi : lo;
      far_at[a] = neg ? lo : hi;
    }
    splat(limit, up_to);
  }
};

// Slab test of the ray against the node's eight boxes at once: entry[k] is
// no later than where it enters box k (0 when it starts inside); bit k of
// the result is set when it may meet box k at or before r.limit (never
// clear where the exact test in the tracer's precision would meet it).
// For a positive 1/d the low bound gives the smaller distance, so picking
// the bound by the sign replaces the min/max of the two, and starting from
// [0, limit] replaces the clamp and the limit test. kOctant (bit a set:
// the direction is negative along axis a), when known at compile time,
// makes the bounds' offsets constants instead of loads from r.
template <int kBytes, int kOctant = -1>
[[gnu::always_inline]] inline uint32_t wide_entry(const WideNode& n, const WideRay<kBytes>& r,
                                                  WideBox (&entry)[kWideArity]) {
  using V = Lanes<WideBox, kBytes>;
  constexpr int kL = kLanes<WideBox, kBytes>;
  const char* base = reinterpret_cast<const char*>(&n);
  uint32_t mask = 0;
  for (int g = 0; g < kWideArity; g += kL) {
    V tmin{}, tmax = r.limit;
    for (int a = 0; a < 3; ++a) {
      V near, far;
      uint32_t near_at = 0, far_at = 0;
      if constexpr (kOctant < 0) {
        near_at = r.near_at[a];
        far_at = r.far_at[a];
      } else {
        near_at = wide_bound_at(a, (kOctant >> a & 1) != 0);
        far_at = wide_bound_at(a, (kOctant >> a & 1) == 0);
      }
      __builtin_memcpy(&near, base + near_at + sizeof(WideBox) * g, sizeof near);
      __builtin_memcpy(&far, base + far_at + sizeof(WideBox) * g, sizeof far);
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

// A waiting child of the nearest-hit walk as one 64-bit key: its entry
// distance's bits above (distances are never negative, and non-negative
// floats order as their bits), its parent node and lane below, so keys
// order by distance and a key past `wide_key(bound, ~0u)` is beyond bound.
static_assert(kWideArity == 8, "a key's lane is its low three bits");
inline uint64_t wide_key(WideBox t, uint32_t lane) {
  uint32_t bits;
  __builtin_memcpy(&bits, &t, sizeof bits);
  return static_cast<uint64_t>(bits) << 32 | lane;
}

// Nearest-hit walk. `limit()` is the distance of the best hit so far;
// `leaf(first, count)` tests references first .. first+count-1 and may
// lower it. The nearest child met is taken at once; the others wait on the
// stack, pushed farthest first, and are dropped when a closer hit has
// turned up by the time they come off it.
template <int kBytes, int kOctant, class R, class Limit, class Leaf>
[[gnu::always_inline]] inline void wide_nearest_in(const WideBvh<R>& tree, const Ray<R>& ray, Limit limit,
                                                   Leaf leaf) {
  const WideNode* const nodes = tree.nodes;
  uint64_t stack[kWideStack];
  int top = 0;
  // limit() rounded to the nearest float, read again only after a leaf. An
  // entry distance (a float) beyond it is beyond limit() too: no float lies
  // between a value and its nearest float.
  WideBox bound = static_cast<WideBox>(limit());
  WideRay<kBytes> lanes(ray, bound);
  uint64_t beyond = wide_key(bound, ~0u);
  // The next waiting child that may still hold something closer: its
  // parent and lane.
  const WideNode* from = nullptr;
  uint32_t lane = 0;
  auto pop = [&]() __attribute__((always_inline)) {
    uint64_t e;
    do {
      if (top == 0) return false;
      e = stack[--top];
    } while (e > beyond);
    const uint32_t at = static_cast<uint32_t>(e);
    from = nodes + (at >> 3);
    lane = at & 7u;
    return true;
  };
  uint32_t current = 0;
  for (;;) {
    const WideNode* node = nodes + current;
    WideBox entry[kWideArity];
    uint32_t mask = wide_entry<kBytes, kOctant>(*node, from_memory(lanes), entry);
    if (mask != 0) {
      lane = static_cast<uint32_t>(__builtin_ctz(mask));
      mask &= mask - 1;
      if (mask != 0) {
        // Several met: keep the nearest key, push the others in order of
        // decreasing distance (two met, the commonest case: one compare).
        const uint32_t here = current << 3;
        const uint32_t second = static_cast<uint32_t>(__builtin_ctz(mask));
        mask &= mask - 1;
        const uint64_t a = wide_key(entry[lane], here | lane), b = wide_key(entry[second], here | second);
        uint64_t best = a < b ? a : b;
        stack[top++] = a < b ? b : a;
        const int base = top - 1;
        while (mask != 0) {
          const uint32_t k = static_cast<uint32_t>(__builtin_ctz(mask));
          mask &= mask - 1;
          uint64_t e = wide_key(entry[k], here | k);
          if (e < best) {
            const uint64_t nearer = e;
            e = best;
            best = nearer;
          }
          int i = top++;
          while (i > base && stack[i - 1] < e) {
            stack[i] = stack[i - 1];
            --i;
          }
          stack[i] = e;
        }
        lane = static_cast<uint32_t>(best) & 7u;
      }
      from = node;
    } else if (!pop()) {
      return;
    }
    // Test leaves until an inner child comes next.
    for (;;) {
      const uint32_t count = from->count[lane];
      current = from->child[lane];
      if (count == 0) break;
      leaf(current, count);
      bound = static_cast<WideBox>(limit());
      splat(lanes.limit, bound);
      beyond = wide_key(bound, ~0u);
      if (!pop()) return;
    }
  }
}

// The nearest-hit walk (wide_nearest_in). The AVX2 copy has one for each
// octant of directions, so that the box test's loads take constant
// offsets: fewer instructions a node, and registers left for the rest.
// (A direction component of -0 counts as positive, as in inverse_dir.)
template <int kBytes, class R, class Limit, class Leaf>
[[gnu::always_inline]] inline void wide_nearest(const WideBvh<R>& tree, const Ray<R>& ray, Limit limit, Leaf leaf) {
  if constexpr (kBytes == 32) {
    const int octant = (ray.dir.x < R(0) ? 1 : 0) | (ray.dir.y < R(0) ? 2 : 0) | (ray.dir.z < R(0) ? 4 : 0);
    switch (octant) {
      case 0: return wide_nearest_in<kBytes, 0>(tree, ray, limit, leaf);
      case 1: return wide_nearest_in<kBytes, 1>(tree, ray, limit, leaf);
      case 2: return wide_nearest_in<kBytes, 2>(tree, ray, limit, leaf);
      case 3: return wide_nearest_in<kBytes, 3>(tree, ray, limit, leaf);
      case 4: return wide_nearest_in<kBytes, 4>(tree, ray, limit, leaf);
      case 5: return wide_nearest_in<kBytes, 5>(tree, ray, limit, leaf);
      case 6: return wide_nearest_in<kBytes, 6>(tree, ray, limit, leaf);
      default: return wide_nearest_in<kBytes, 7>(tree, ray, limit, leaf);
    }
  } else {
    wide_nearest_in<kBytes, -1>(tree, ray, limit, leaf);
  }
}

// Any-hit walk for shadow rays: `leaf(first, count)` says whether one of
// those references blocks the ray before `limit`. Leaves are tested as
// soon as their box is met; inner children wait on the stack.
template <int kBytes, class R, class Leaf>
[[gnu::always_inline]] inline bool wide_any(const WideBvh<R>& tree, const Ray<R>& ray, R limit, Leaf leaf) {
  const WideRay<kBytes> r(ray, static_cast<WideBox>(limit));
  uint32_t stack[kWideStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const WideNode& node = tree.nodes[stack[--top]];
    WideBox entry[kWideArity];
    const uint32_t mask = wide_entry(node, r, entry);
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
