// A bounding-volume hierarchy over the main obj's objects (quadrics, boxes,
// CSG blocks: the root's items, which are independent), by their
// conservative world bounds (csg_bounds.hpp). Objects unbounded on some
// side go to a list every ray tests; objects that can never be hit (an AND
// of disjoint items) are left out. Built once in the arena by the general
// tracer's builder (binned SAH, render/general/bvh.hpp); the tracer walks
// it nearest box first and breaks ties between equally near hits by the
// objects' order, so the image is the one of the plain walk in order.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/eastray/eastray_scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/csg_bounds.hpp"

namespace minrt::eastray {

// Arena bytes the hierarchy over n objects takes (with its build scratch).
template <class R>
constexpr size_t object_bvh_bytes(int32_t n) {
  return general::bvh_footprint<R>(static_cast<uint32_t>(n)) + Arena::footprint<general::Bounds<R>>(n) +
         2 * Arena::footprint<int32_t>(n) + 64;
}

// False when the arena is too small (the scene then renders without it,
// the same image).
template <class M>
bool build_object_bvh(Scene<typename M::real>& s, Arena& arena) {
  using R = typename M::real;
  if (s.root == kNone) return true;
  int32_t n = 0;
  for (int32_t c = s.nodes[s.root].first_child; c != kNone; c = s.nodes[c].next) ++n;
  if (n == 0) return true;
  auto* unbounded = arena.alloc_zeroed<int32_t>(static_cast<size_t>(n));
  const size_t mark = arena.top_mark();
  auto* ids = arena.alloc_top<int32_t>(static_cast<size_t>(n));
  auto* boxes = arena.alloc_top<general::Bounds<R>>(static_cast<size_t>(n));
  if (unbounded == nullptr || ids == nullptr || boxes == nullptr) {
    arena.release_top(mark);
    return false;
  }
  int32_t bounded = 0, open = 0;
  for (int32_t c = s.nodes[s.root].first_child; c != kNone; c = s.nodes[c].next) {
    const general::OpenBox<R> b = general::node_box<M>(general::CsgScene<R>{s.nodes, s.primitives}, c);
    if (b.empty()) continue;
    if (!b.finite()) {
      unbounded[open++] = c;
      continue;
    }
    ids[bounded] = c;
    boxes[bounded++] = general::Bounds<R>{{b.lo[0], b.lo[1], b.lo[2]}, {b.hi[0], b.hi[1], b.hi[2]}};
  }
  general::Bvh<R> bvh;
  const bool built = general::build_bvh_over<M>(static_cast<uint32_t>(bounded), arena, bvh,
                                                [&](uint32_t i, uint32_t& ref, general::Bounds<R>& box) {
                                                  ref = static_cast<uint32_t>(ids[i]);
                                                  box = boxes[i];
                                                });
  arena.release_top(mark);
  if (!built) return false;
  s.object_bvh_nodes = bvh.nodes;
  s.object_bvh_refs = bvh.refs;
  s.object_bvh_node_count = static_cast<int32_t>(bvh.node_count);
  s.unbounded_objects = unbounded;
  s.unbounded_count = open;
  return true;
}

}  // namespace minrt::eastray
