// Walks the four-wide hierarchy (wide_node.hpp): the nearest hit, nearest
// children first, and any hit for shadow rays. The caller tests the leaves'
// primitives; nothing here allocates or calls through a pointer.
#pragma once

#include <stdint.h>

#include "render/general/bvh.hpp"
#include "render/general/ray.hpp"
#include "render/general/wide_node.hpp"

namespace minrt::general {

// kBytes of values side by side (16: two doubles or four floats; 32: four
// doubles): a GCC/Clang vector, which the compiler maps to the target's
// vector registers (16 bytes: one SSE2 register on any x86-64; 32: one AVX
// register, in code compiled for AVX2, simd_dispatch.hpp) or to scalar code
// where there are none. A node's four boxes are tested in groups of
// kLanes. Only passed by reference: a vector by value would depend on the
// target's ABI.
template <class R, int kBytes>
struct LanesOf {
  typedef R type __attribute__((vector_size(kBytes)));
};
template <class R, int kBytes>
using Lanes = typename LanesOf<R, kBytes>::type;
template <class R, int kBytes>
inline constexpr int kLanes = kBytes / static_cast<int>(sizeof(R));
static_assert(kWideArity % kLanes<float, 16> == 0 && kWideArity % kLanes<double, 32> == 0, "whole groups per node");

// A ray as the box test wants it: for each axis, which bound it meets first
// (by the sign of the direction), and origin and 1/d in every lane.
template <class R, int kBytes>
struct WideRay {
  Lanes<R, kBytes> origin[3];
  Lanes<R, kBytes> inv[3];
  bool negative[3];

  [[gnu::always_inline]] explicit WideRay(const Ray<R>& ray) {
    const Vec3<R> d = inverse_dir(ray.dir);
    const R o[3] = {ray.origin.x, ray.origin.y, ray.origin.z}, i[3] = {d.x, d.y, d.z};
    for (int a = 0; a < 3; ++a) {
      origin[a] = Lanes<R, kBytes>{} + o[a];
      inv[a] = Lanes<R, kBytes>{} + i[a];
      negative[a] = i[a] < R(0);
    }
  }
};

// Slab test of the ray against the node's four boxes at once: entry[k] is
// where it enters box k (0 when it starts inside); bit k of the result is
// set when it meets box k at or before `limit`. The arithmetic of
// box_entry: for a positive 1/d the low bound gives the smaller distance, so
// picking the bound by the sign replaces the min/max of the two, and
// starting from [0, limit] replaces the clamp and the limit test.
template <class R, int kBytes>
[[gnu::always_inline]] inline uint32_t wide_entry(const WideNode<R>& n, const WideRay<R, kBytes>& r, R limit,
                                                  R (&entry)[kWideArity]) {
  using V = Lanes<R, kBytes>;
  constexpr int kL = kLanes<R, kBytes>;
  uint32_t mask = 0;
  for (int g = 0; g < kWideArity; g += kL) {
    V tmin{}, tmax = V{} + limit;
    for (int a = 0; a < 3; ++a) {
      V near, far;
      __builtin_memcpy(&near, (r.negative[a] ? n.hi[a] : n.lo[a]) + g, sizeof near);
      __builtin_memcpy(&far, (r.negative[a] ? n.lo[a] : n.hi[a]) + g, sizeof far);
      const V lo = (near - r.origin[a]) * r.inv[a];
      const V hi = (far - r.origin[a]) * r.inv[a];
      tmin = lo > tmin ? lo : tmin;
      tmax = hi < tmax ? hi : tmax;
    }
    __builtin_memcpy(entry + g, &tmin, sizeof tmin);
    const auto met = tmax >= tmin;
    for (int k = 0; k < kL; ++k) mask |= static_cast<uint32_t>(met[k] & 1) << (g + k);
  }
  return mask & ((1u << n.used) - 1u);
}

// Nearest-hit walk. `limit()` is the distance of the best hit so far;
// `leaf(first, count)` tests references first .. first+count-1 and may
// lower it. A single child met is entered at once; several are pushed
// farthest first, so the nearest is taken next and the others are dropped
// when a closer hit has turned up by the time they come off the stack.
template <int kBytes, class R, class Limit, class Leaf>
[[gnu::always_inline]] inline void wide_nearest(const WideBvh<R>& tree, const Ray<R>& ray, Limit limit, Leaf leaf) {
  const WideRay<R, kBytes> r(ray);
  struct Entry {
    uint32_t child;
    uint32_t count;
    R t;
  };
  Entry stack[kWideStack];
  int top = 0;
  uint32_t current = 0;
  for (;;) {
    const WideNode<R>& node = tree.nodes[current];
    R entry[kWideArity];
    uint32_t mask = wide_entry(node, r, limit(), entry);
    if (mask != 0 && (mask & (mask - 1)) == 0) {
      const int k = __builtin_ctz(mask);
      if (node.count[k] == 0) {
        current = node.child[k];
        continue;
      }
      leaf(node.child[k], node.count[k]);
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
      if (e.t > limit()) continue;
      if (e.count == 0) {
        current = e.child;
        descend = true;
        break;
      }
      leaf(e.child, e.count);
    }
    if (!descend) return;
  }
}

// Any-hit walk for shadow rays: `leaf(first, count)` says whether one of
// those references blocks the ray before `limit`. Leaves are tested as
// soon as their box is met; inner children wait on the stack.
template <int kBytes, class R, class Leaf>
[[gnu::always_inline]] inline bool wide_any(const WideBvh<R>& tree, const Ray<R>& ray, R limit, Leaf leaf) {
  const WideRay<R, kBytes> r(ray);
  uint32_t stack[kWideStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const WideNode<R>& node = tree.nodes[stack[--top]];
    R entry[kWideArity];
    uint32_t mask = wide_entry(node, r, limit, entry);
    while (mask != 0) {
      const int k = __builtin_ctz(mask);
      mask &= mask - 1;
      if (node.count[k] == 0) {
        stack[top++] = node.child[k];
      } else if (leaf(node.child[k], node.count[k])) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace minrt::general
