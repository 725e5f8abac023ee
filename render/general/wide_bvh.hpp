// Builds the eight-wide hierarchy (wide_node.hpp) by collapsing the binary
// one (bvh.hpp).
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/math/float_step.hpp"
#include "render/general/bvh.hpp"
#include "render/general/wide_node.hpp"

namespace minrt::general {

// The float at or below (at or above) a finite double: the nearest float
// moved by one step where rounding went the wrong way. Beyond the float
// range the result is the largest float or infinity, still on the right
// side.
inline WideBox wide_box_down(double v) {
  constexpr WideBox kMaxFloat = 3.40282347e38f;
  const WideBox f = static_cast<WideBox>(v);
  if (!(static_cast<double>(f) > v)) return f;
  if (f > kMaxFloat) return kMaxFloat;  // rounded up to infinity
  return f - float_step_bound(f);
}
inline WideBox wide_box_up(double v) { return -wide_box_down(-v); }

// Collapses `bvh` into `out`: every wide node takes the binary node's two
// children and keeps opening the inner one with the largest box until it
// has eight. False (and `out` empty) when the arena is too small or the
// tree has more than kWideMaxNodes nodes: the binary tree is walked then.
template <class R>
bool build_wide_bvh(const Bvh<R>& bvh, Arena& arena, WideBvh<R>& out) {
  out = WideBvh<R>{};
  if (bvh.node_count == 0) return true;
  // The walk's stack keys hold a node's index in 29 bits (wide_traversal.hpp).
  if (bvh.node_count > kWideMaxNodes) return false;
  // The arena's base is only as aligned as the host's allocator makes it:
  // one node's room more, and the nodes start at the first cache line in it.
  auto* raw = arena.alloc_zeroed<uint8_t>(sizeof(WideNode) * static_cast<size_t>(bvh.node_count) + kCacheLine);
  if (raw == nullptr) return false;
  const size_t skip = (kCacheLine - reinterpret_cast<uintptr_t>(raw) % kCacheLine) % kCacheLine;
  auto* nodes = reinterpret_cast<WideNode*>(raw + skip);
  struct Work {
    uint32_t wide, binary;
  };
  Work stack[kWideStack];
  int top = 0;
  stack[top++] = Work{0, 0};
  uint32_t used = 1;
  while (top > 0) {
    const Work w = stack[--top];
    WideNode& node = nodes[w.wide];
    uint32_t kids[kWideArity];
    uint32_t n = 0;
    const BvhNode<R>& b = bvh.nodes[w.binary];
    if (b.count != 0) {
      kids[n++] = w.binary;  // a root that is a leaf
    } else {
      kids[n++] = b.index;
      kids[n++] = b.index + 1;
      while (n < static_cast<uint32_t>(kWideArity)) {
        int open = -1;
        R best = R(0);
        for (uint32_t k = 0; k < n; ++k) {
          const BvhNode<R>& c = bvh.nodes[kids[k]];
          if (c.count == 0 && (open < 0 || c.box.area() > best)) {
            open = static_cast<int>(k);
            best = c.box.area();
          }
        }
        if (open < 0) break;
        const uint32_t first = bvh.nodes[kids[open]].index;
        kids[open] = first;
        kids[n++] = first + 1;
      }
    }
    node.used_mask = (1u << n) - 1u;
    for (uint32_t k = 0; k < static_cast<uint32_t>(kWideArity); ++k) {
      const BvhNode<R>& c = bvh.nodes[kids[k < n ? k : 0]];
      node.lo[0][k] = wide_box_down(c.box.lo.x);
      node.lo[1][k] = wide_box_down(c.box.lo.y);
      node.lo[2][k] = wide_box_down(c.box.lo.z);
      node.hi[0][k] = wide_box_up(c.box.hi.x);
      node.hi[1][k] = wide_box_up(c.box.hi.y);
      node.hi[2][k] = wide_box_up(c.box.hi.z);
      if (k >= n) continue;  // unused lanes repeat child 0's box and are masked off
      if (c.count != 0) {
        node.child[k] = c.index;
        node.count[k] = c.count;
        node.leaf_mask |= 1u << k;
        continue;
      }
      if (top + 1 > kWideStack || used >= bvh.node_count) return false;
      node.child[k] = used;
      node.count[k] = 0;
      stack[top++] = Work{used++, kids[k]};
    }
  }
  out.nodes = nodes;
  out.node_count = used;
  return true;
}

}  // namespace minrt::general
