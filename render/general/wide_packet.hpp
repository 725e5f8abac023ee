// Walks the eight-wide hierarchy (wide_node.hpp) with a packet of up to P
// rays at once, for the nearest hit of each: one order of nodes for the
// packet, so the walk's branches are taken once for P rays instead of once
// a ray (the single walk, wide_traversal.hpp, is bound by mispredicted
// branches). Each ray keeps its own limit and hit; a node or leaf is
// visited for the rays whose own box test, the single walk's arithmetic,
// meets it at or before their limit, so every leaf that may hold a hit at
// or before a ray's best is tested for it and, hits being compared by
// (distance, file order) whatever order they are found in, the ray ends
// with the single walk's hit. The
// rays must share the octant of their directions (the bounds' offsets are
// the packet's); make_packet_ray says when they do not.
#pragma once

#include <stdint.h>

#include "render/general/bvh.hpp"
#include "render/general/ray.hpp"
#include "render/general/simd_dispatch.hpp"
#include "render/general/wide_node.hpp"
#include "render/general/wide_traversal.hpp"

namespace minrt::general {

// One float a ray: P rays side by side in one vector (16 bytes for 4, 32
// for 8).
template <int P>
using PacketLanes = Lanes<WideBox, 4 * P>;
template <int P>
using PacketMask = Lanes<int32_t, 4 * P>;

// Bit r set where lane r of `met` is true. kAvx: the caller is compiled
// for AVX2, where 32 bytes are one movmsk; otherwise 16 bytes at a time.
template <int P, bool kAvx>
[[gnu::always_inline]] inline uint32_t packet_bits(const PacketMask<P>& met) {
  if constexpr (P == 4 || kAvx) {
    return true_lanes<WideBox, 4 * P>(met);
  } else {
    uint32_t bits = 0;
    for (int h = 0; h < P / 4; ++h) {
      Lanes<int32_t, 16> part;
      __builtin_memcpy(&part, reinterpret_cast<const char*>(&met) + 16 * h, sizeof part);
      bits |= true_lanes<WideBox, 16>(part) << (4 * h);
    }
    return bits;
  }
}

#if MINRT_AVX2_DISPATCH
// x in every lane, for the AVX2 copy: one vbroadcastss. (Written in a
// function without the target attribute and inlined, the same initialiser
// becomes a chain of inserts.)
MINRT_TARGET_AVX2 inline void broadcast_avx(Lanes<WideBox, 32>& out, WideBox x) {
  out = Lanes<WideBox, 32>{x, x, x, x, x, x, x, x};
}
MINRT_TARGET_AVX2 inline void broadcast_avx(Lanes<WideBox, 16>& out, WideBox x) { out = Lanes<WideBox, 16>{x, x, x, x}; }
#endif

// x in every lane. kAvx: the caller is compiled for AVX2. (Vectors are
// passed by reference only, as in wide_traversal.hpp.)
template <int P, bool kAvx>
[[gnu::always_inline]] inline void packet_splat(PacketLanes<P>& v, WideBox x) {
  static_assert(P == 4 || P == 8, "packets of 4 or 8 rays");
#if MINRT_AVX2_DISPATCH
  if constexpr (kAvx) {
    broadcast_avx(v, x);
    return;
  }
#endif
  for (int r = 0; r < P; ++r) v[r] = x;
}

// The smallest lane.
template <int P>
[[gnu::always_inline]] inline WideBox packet_min(const PacketLanes<P>& v) {
  using V = PacketLanes<P>;
  V m = v, s;
  if constexpr (P == 8) {
    s = __builtin_shufflevector(m, m, 4, 5, 6, 7, 0, 1, 2, 3);
    m = s < m ? s : m;
    s = __builtin_shufflevector(m, m, 2, 3, 0, 1, 6, 7, 4, 5);
    m = s < m ? s : m;
    s = __builtin_shufflevector(m, m, 1, 0, 3, 2, 5, 4, 7, 6);
  } else {
    static_assert(P == 4, "packets of 4 or 8 rays");
    s = __builtin_shufflevector(m, m, 2, 3, 0, 1);
    m = s < m ? s : m;
    s = __builtin_shufflevector(m, m, 1, 0, 3, 2);
  }
  m = s < m ? s : m;
  return m[0];
}

// The packet's rays as the box test wants them: WideRay's values of ray r
// in lane r, and the octant's offsets of the near and far bounds.
template <int P>
struct PacketRay {
  using V = PacketLanes<P>;
  V near_origin[3];
  V far_origin[3];
  V near_inv[3];
  V far_inv[3];
  uint32_t near_at[3];
  uint32_t far_at[3];
};

// Fills `out` from rays[r] for each bit r of `active` (the other lanes
// repeat an active ray: their limit keeps them out of every box), with
// WideRay's arithmetic (slab_lanes) lane by lane. False when the
// directions are not all in one octant.
template <int P, class R>
[[gnu::always_inline]] inline bool make_packet_ray(const Ray<R>* rays, uint32_t active, PacketRay<P>& out) {
  using Reals = Lanes<R, P * static_cast<int>(sizeof(R))>;
  using I = PacketMask<P>;
  const uint32_t lead = static_cast<uint32_t>(__builtin_ctz(active));
  for (int a = 0; a < 3; ++a) {
    Reals o, d;
    for (int r = 0; r < P; ++r) {
      const Ray<R>& ray = rays[(active >> r & 1u) != 0 ? static_cast<uint32_t>(r) : lead];
      o[r] = a == 0 ? ray.origin.x : a == 1 ? ray.origin.y : ray.origin.z;
      d[r] = a == 0 ? ray.dir.x : a == 1 ? ray.dir.y : ray.dir.z;
    }
    I negative;
    slab_lanes(o, d, out.near_origin[a], out.far_origin[a], out.near_inv[a], out.far_inv[a], negative);
    uint32_t neg = 0;
    for (int r = 0; r < P; ++r) neg |= (negative[r] != 0 ? 1u : 0u) << r;
    if (neg != 0 && neg != (1u << P) - 1u) return false;
    const uint32_t lo = wide_bound_at(a, false), hi = wide_bound_at(a, true);
    out.near_at[a] = neg != 0 ? hi : lo;
    out.far_at[a] = neg != 0 ? lo : hi;
  }
  return true;
}

// Nearest-hit walk of the packet. `limit(r)`: ray r's best distance so
// far; `leaf(first, count, rays)` tests references first .. first+count-1
// for each ray of the bit set `rays` and may lower their limits. A child is
// taken by the nearest entry of the rays that meet it, the others wait on
// the stack with each ray's entry (infinity for a ray that misses the box)
// and are dropped once no ray's limit reaches its entry.
template <int P, bool kAvx, class R, class Limit, class Leaf>
[[gnu::always_inline]] inline void wide_packet_nearest(const WideBvh<R>& tree, const PacketRay<P>& pr,
                                                       uint32_t active, Limit limit, Leaf leaf) {
  using V = PacketLanes<P>;
  using I = PacketMask<P>;
  const WideBox inf = __builtin_inff();
  const WideNode* const nodes = tree.nodes;
  // Each ray's limit rounded to the nearest float (an entry beyond it is
  // beyond the limit: no float lies between a value and its nearest
  // float); -1 in the lanes of inactive rays, which meet no box.
  V bound;
  for (int r = 0; r < P; ++r) bound[r] = (active >> r & 1u) != 0 ? static_cast<WideBox>(limit(r)) : WideBox(-1);
  uint64_t keys[kWideStack];
  V entries[kWideStack];
  int top = 0;
  // The rays' entries into the box being visited (the root: every active
  // ray's, from where it starts).
  V entry;
  for (int r = 0; r < P; ++r) entry[r] = (active >> r & 1u) != 0 ? WideBox(0) : inf;
  const WideNode* from = nullptr;
  uint32_t lane = 0;
  auto pop = [&]() __attribute__((always_inline)) {
    do {
      if (top == 0) return false;
      --top;
    } while (packet_bits<P, kAvx>(entries[top] <= bound) == 0);
    entry = entries[top];
    const uint32_t at = static_cast<uint32_t>(keys[top]);
    from = nodes + (at >> 3);
    lane = at & 7u;
    return true;
  };
  uint32_t current = 0;
  for (;;) {
    const WideNode* node = nodes + current;
    const char* base = reinterpret_cast<const char*>(node);
    // Rays whose limit no longer reaches this box start past every child.
    const I live = entry <= bound;
    V infinite;
    packet_splat<P, kAvx>(infinite, inf);
    const V start = live ? V{} : infinite;
    V child_entry[kWideArity];
    uint32_t met = 0;
    for (int k = 0; k < kWideArity; ++k) {
      V tmin = start, tmax = bound;
      for (int a = 0; a < 3; ++a) {
        WideBox nb, fb;
        __builtin_memcpy(&nb, base + pr.near_at[a] + sizeof(WideBox) * k, sizeof nb);
        __builtin_memcpy(&fb, base + pr.far_at[a] + sizeof(WideBox) * k, sizeof fb);
        V near, far;
        packet_splat<P, kAvx>(near, nb);
        packet_splat<P, kAvx>(far, fb);
        // wide_entry's arithmetic, lane by lane.
        const V lo = (near - pr.near_origin[a]) * pr.near_inv[a];
        const V hi = (far - pr.far_origin[a]) * pr.far_inv[a];
        tmin = lo > tmin ? lo : tmin;
        tmax = hi < tmax ? hi : tmax;
      }
      const I hit = tmax >= tmin;
      child_entry[k] = hit ? tmin : infinite;
      met |= (packet_bits<P, kAvx>(hit) != 0 ? 1u : 0u) << k;
    }
    met &= node->used_mask;
    if (met != 0) {
      // As the single walk: the nearest child next, the others pushed in
      // order of decreasing distance, by the nearest ray's entry.
      const uint32_t here = current << 3;
      lane = static_cast<uint32_t>(__builtin_ctz(met));
      met &= met - 1;
      uint64_t best = wide_key(packet_min<P>(child_entry[lane]), here | lane);
      const int base_top = top;
      while (met != 0) {
        const uint32_t k = static_cast<uint32_t>(__builtin_ctz(met));
        met &= met - 1;
        uint64_t e = wide_key(packet_min<P>(child_entry[k]), here | k);
        if (e < best) {
          const uint64_t nearer = e;
          e = best;
          best = nearer;
        }
        int i = top++;
        while (i > base_top && keys[i - 1] < e) {
          keys[i] = keys[i - 1];
          entries[i] = entries[i - 1];
          --i;
        }
        keys[i] = e;
        entries[i] = child_entry[e & 7u];
      }
      lane = static_cast<uint32_t>(best) & 7u;
      entry = child_entry[lane];
      from = node;
    } else if (!pop()) {
      return;
    }
    // Test leaves until an inner child comes next.
    for (;;) {
      const uint32_t count = from->count[lane];
      current = from->child[lane];
      if (count == 0) break;
      const uint32_t rays = packet_bits<P, kAvx>(entry <= bound);
      leaf(current, count, rays);
      for (uint32_t b = rays; b != 0; b &= b - 1) {
        const int r = __builtin_ctz(b);
        bound[r] = static_cast<WideBox>(limit(r));
      }
      if (!pop()) return;
    }
  }
}

}  // namespace minrt::general
