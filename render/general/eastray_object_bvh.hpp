// A bounding-volume hierarchy over the main obj's objects (quadrics, boxes,
// CSG blocks: the root's items, which are independent), by their
// conservative world bounds (eastray_bounds.hpp). Objects unbounded on some
// side go to a list every ray tests; objects that can never be hit (an AND
// of disjoint items) are left out. Built once in the arena by splitting at
// the middle of the centres' extent on the longest axis; the tracer walks
// it nearest box first and breaks ties between equally near hits by the
// objects' order, so the image is the one of the plain walk in order.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/eastray/eastray_scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/eastray_bounds.hpp"

namespace minrt::eastray {

inline constexpr int kObjectLeaf = 2;

// Arena bytes the hierarchy over n objects takes (with its build scratch).
template <class R>
constexpr size_t object_bvh_bytes(int32_t n) {
  return general::bvh_footprint<R>(static_cast<uint32_t>(n)) + 3 * Arena::footprint<int32_t>(n) + 64;
}

// False when the arena is too small (the scene then renders without it,
// the same image).
template <class M>
bool build_object_bvh(Scene<typename M::real>& s, Arena& arena) {
  using R = typename M::real;
  using V = Vec3<R>;
  if (s.root == kNone) return true;
  int32_t n = 0;
  for (int32_t c = s.nodes[s.root].first_child; c != kNone; c = s.nodes[c].next) ++n;
  if (n == 0) return true;
  auto* nodes = arena.alloc_zeroed<general::BvhNode<R>>(2 * static_cast<size_t>(n));
  auto* refs = arena.alloc_zeroed<int32_t>(static_cast<size_t>(n));
  auto* unbounded = arena.alloc_zeroed<int32_t>(static_cast<size_t>(n));
  const size_t mark = arena.top_mark();
  auto* boxes = arena.alloc_top<general::Bounds<R>>(static_cast<size_t>(n));
  auto* centres = arena.alloc_top<V>(static_cast<size_t>(n));
  auto* ids = arena.alloc_top<int32_t>(static_cast<size_t>(n));
  if (nodes == nullptr || refs == nullptr || unbounded == nullptr || boxes == nullptr || centres == nullptr ||
      ids == nullptr) {
    arena.release_top(mark);
    return false;
  }
  // While building, refs hold places in the root's list (boxes and
  // centres are indexed by them) and `unbounded` keeps each place's node
  // id; at the end refs become node ids.
  int32_t bounded = 0, open = 0, k = 0;
  for (int32_t c = s.nodes[s.root].first_child; c != kNone; c = s.nodes[c].next, ++k) {
    ids[k] = c;
    const Box<R> b = node_box<M>(s, c);
    if (b.empty()) continue;
    if (!b.finite()) {
      unbounded[open++] = c;
      continue;
    }
    boxes[k] = general::Bounds<R>{{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
    centres[k] = (boxes[k].lo + boxes[k].hi) * R(0.5);
    refs[bounded++] = k;
  }
  struct Item {
    int32_t node, begin, end, depth;
  };
  Item stack[general::kBvhStack];
  int top = 0;
  int32_t used = 0;
  if (bounded > 0) {
    stack[top++] = Item{0, 0, bounded, 0};
    used = 1;
  }
  while (top > 0) {
    const Item it = stack[--top];
    general::BvhNode<R>& node = nodes[it.node];
    general::Bounds<R> box = general::Bounds<R>::empty(), cbox = general::Bounds<R>::empty();
    for (int32_t i = it.begin; i < it.end; ++i) {
      box.grow(boxes[refs[i]]);
      cbox.grow(centres[refs[i]]);
    }
    node.box = box;
    const int32_t count = it.end - it.begin;
    if (count <= kObjectLeaf || it.depth + 1 >= general::kBvhMaxDepth) {
      if (count > 0xffff) {
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
    if (split == it.begin || split == it.end) split = it.begin + count / 2;  // all centres alike
    node.index = static_cast<uint32_t>(used);
    node.count = 0;
    node.axis = static_cast<uint16_t>(axis);
    stack[top++] = Item{used, it.begin, split, it.depth + 1};
    stack[top++] = Item{used + 1, split, it.end, it.depth + 1};
    used += 2;
  }
  for (int32_t i = 0; i < bounded; ++i) refs[i] = ids[refs[i]];
  arena.release_top(mark);
  s.object_bvh_nodes = used > 0 ? nodes : nullptr;
  s.object_bvh_refs = refs;
  s.object_bvh_node_count = used;
  s.unbounded_objects = unbounded;
  s.unbounded_count = open;
  return true;
}

}  // namespace minrt::eastray
