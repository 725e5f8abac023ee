// A bounding-volume hierarchy over the objects of a scene's CSG tree (the
// top node's children: quadrics, boxes, blocks, which are independent), by
// their conservative world bounds (csg_bounds.hpp). Objects unbounded on
// some side go to a list every ray tests; objects that can never be hit (an
// AND of disjoint items) are left out. Built once in the arena by the
// general builder (binned SAH, bvh.hpp); csg_nearest_object walks it
// nearest box first and breaks ties between equally near hits by the
// objects' order, so the image is the one of the plain walk in order.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/model/scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/csg_bounds.hpp"
#include "render/general/csg_intersect.hpp"

namespace minrt::general {

// Arena bytes the hierarchy over n objects takes (with its build scratch).
template <class R>
constexpr size_t object_bvh_bytes(uint32_t n) {
  return bvh_footprint<R>(n) + Arena::footprint<Bounds<R>>(n) + 2 * Arena::footprint<int32_t>(n) + 64;
}

// Fills `out` (the plain walk over the tree when it stays empty). False
// when the arena is too small: the scene then renders with the plain walk,
// the same image, slower.
template <class M>
bool build_object_bvh(const model::Scene<typename M::real>& s, Arena& arena, CsgObjects<typename M::real>& out) {
  using R = typename M::real;
  out = CsgObjects<R>{nullptr, nullptr, nullptr, 0};
  if (s.csg_root == model::kNoNode) return true;
  int32_t n = 0;
  for (int32_t c = s.csg_nodes[s.csg_root].first_child; c != model::kNoNode; c = s.csg_nodes[c].next) ++n;
  if (n == 0) return true;
  auto* unbounded = arena.alloc_zeroed<int32_t>(static_cast<size_t>(n));
  const size_t mark = arena.top_mark();
  auto* ids = arena.alloc_top<int32_t>(static_cast<size_t>(n));
  auto* boxes = arena.alloc_top<Bounds<R>>(static_cast<size_t>(n));
  if (unbounded == nullptr || ids == nullptr || boxes == nullptr) {
    arena.release_top(mark);
    return false;
  }
  const CsgScene<R> tree{s.csg_nodes, s.quadrics};
  int32_t bounded = 0, open = 0;
  for (int32_t c = s.csg_nodes[s.csg_root].first_child; c != model::kNoNode; c = s.csg_nodes[c].next) {
    const OpenBox<R> b = node_box<M>(tree, c);
    if (b.empty()) continue;
    if (!b.finite()) {
      unbounded[open++] = c;
      continue;
    }
    ids[bounded] = c;
    boxes[bounded++] = Bounds<R>{{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
  }
  Bvh<R> bvh;
  const bool built = build_bvh_over<M>(static_cast<uint32_t>(bounded), arena, bvh,
                                       [&](uint32_t i, uint32_t& ref, Bounds<R>& box) {
                                         ref = static_cast<uint32_t>(ids[i]);
                                         box = boxes[i];
                                       });
  arena.release_top(mark);
  if (!built) return false;
  out = CsgObjects<R>{bvh.nodes, bvh.refs, unbounded, open};
  return true;
}

}  // namespace minrt::general
