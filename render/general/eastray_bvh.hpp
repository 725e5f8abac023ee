// A bounding-volume hierarchy over an EASTRAY scene's polygon triangles (a
// mesh of thousands of faces would otherwise be tested by every ray). Built
// once in the arena by splitting at the middle of the centroids' extent on
// the longest axis (half by count when that separates nothing), traversed
// with a fixed stack; it changes which triangles are tested, never the
// nearest hit found. The boxes and the slab test are the general tracer's.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/eastray/eastray_scene.hpp"
#include "render/general/bvh.hpp"

namespace minrt::eastray {

using general::BvhNode;
using general::Bounds;

inline constexpr int kTriangleLeaf = 4;

// Arena bytes the hierarchy of n triangles takes (with its build scratch).
template <class R>
constexpr size_t triangle_bvh_bytes(int32_t n) {
  return Arena::footprint<BvhNode<R>>(2 * static_cast<size_t>(n) + 1) + Arena::footprint<int32_t>(n) +
         Arena::footprint<Vec3<R>>(n) + 64;
}

// False when the arena is too small (the scene then renders without it).
template <class M>
bool build_triangle_bvh(Scene<typename M::real>& s, Arena& arena) {
  using R = typename M::real;
  using V = Vec3<R>;
  const int32_t n = s.triangle_count;
  if (n <= kTriangleLeaf) return true;
  auto* nodes = arena.alloc_zeroed<BvhNode<R>>(2 * static_cast<size_t>(n));
  auto* refs = arena.alloc_zeroed<int32_t>(static_cast<size_t>(n));
  const size_t mark = arena.top_mark();
  auto* centres = arena.alloc_top<V>(static_cast<size_t>(n));
  if (nodes == nullptr || refs == nullptr || centres == nullptr) {
    arena.release_top(mark);
    return false;
  }
  auto box_of = [&](int32_t i) {
    const Triangle<R>& t = s.triangles[i];
    Bounds<R> b = Bounds<R>::empty();
    b.grow(t.p0);
    b.grow(t.p0 + t.e1);
    b.grow(t.p0 + t.e2);
    return general::bvh_detail::padded(b);
  };
  for (int32_t i = 0; i < n; ++i) {
    refs[i] = i;
    const Bounds<R> b = box_of(i);
    centres[i] = (b.lo + b.hi) * R(0.5);
  }
  struct Item {
    int32_t node, begin, end, depth;
  };
  Item stack[general::kBvhStack];
  int top = 0;
  stack[top++] = Item{0, 0, n, 0};
  int32_t used = 1;
  while (top > 0) {
    const Item it = stack[--top];
    BvhNode<R>& node = nodes[it.node];
    Bounds<R> box = Bounds<R>::empty(), cbox = Bounds<R>::empty();
    for (int32_t i = it.begin; i < it.end; ++i) {
      box.grow(box_of(refs[i]));
      cbox.grow(centres[refs[i]]);
    }
    node.box = box;
    const int32_t count = it.end - it.begin;
    if (count <= kTriangleLeaf || it.depth + 1 >= general::kBvhMaxDepth) {
      if (count > 0xffff) {  // a pathological peel: keep testing them all
        arena.release_top(mark);
        return false;
      }
      node.index = static_cast<uint32_t>(it.begin);
      node.count = static_cast<uint16_t>(count);
      continue;
    }
    const V ext = cbox.hi - cbox.lo;
    const int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    const R mid = (cbox.lo[axis] + cbox.hi[axis]) * R(0.5);
    int32_t i = it.begin, j = it.end - 1;
    while (i <= j) {
      if (centres[refs[i]][axis] < mid) {
        ++i;
      } else {
        const int32_t x = refs[i];
        refs[i] = refs[j];
        refs[j--] = x;
      }
    }
    int32_t split = i;
    if (split == it.begin || split == it.end) split = it.begin + count / 2;  // all centroids alike
    node.index = static_cast<uint32_t>(used);
    node.count = 0;
    node.axis = static_cast<uint16_t>(axis);
    stack[top++] = Item{used, it.begin, split, it.depth + 1};
    stack[top++] = Item{used + 1, split, it.end, it.depth + 1};
    used += 2;
  }
  arena.release_top(mark);
  s.triangle_bvh_nodes = nodes;
  s.triangle_bvh_refs = refs;
  s.triangle_bvh_node_count = used;
  return true;
}

}  // namespace minrt::eastray
