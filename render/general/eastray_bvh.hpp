// The bounding-volume hierarchy over an EASTRAY scene's polygon triangles
// (a mesh of thousands of faces would otherwise be tested by every ray),
// built once in the arena by the general tracer's builder (binned SAH,
// render/general/bvh.hpp) over the triangles' padded boxes. It changes
// which triangles are tested, never the hit found: the tracer keeps the
// first of equally near triangles, as its plain loop does.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/eastray/eastray_scene.hpp"
#include "render/general/bvh.hpp"

namespace minrt::eastray {

// Arena bytes the hierarchy of n triangles takes (with its build scratch).
template <class R>
constexpr size_t triangle_bvh_bytes(int32_t n) {
  return general::bvh_footprint<R>(static_cast<uint32_t>(n)) + 64;
}

// False when the arena is too small (the scene then renders without it,
// the same image).
template <class M>
bool build_triangle_bvh(Scene<typename M::real>& s, Arena& arena) {
  using R = typename M::real;
  if (s.triangle_count <= general::kBvhLeafSize) return true;
  general::Bvh<R> bvh;
  const bool built = general::build_bvh_over<M>(static_cast<uint32_t>(s.triangle_count), arena, bvh,
                                                [&](uint32_t i, uint32_t& ref, general::Bounds<R>& box) {
                                                  const Triangle<R>& t = s.triangles[i];
                                                  box = general::Bounds<R>::empty();
                                                  box.grow(t.p0);
                                                  box.grow(t.p1);
                                                  box.grow(t.p2);
                                                  box = general::bvh_detail::padded(box);
                                                  ref = i;
                                                });
  if (!built) return false;
  s.triangle_bvh_nodes = bvh.nodes;
  s.triangle_bvh_refs = bvh.refs;
  s.triangle_bvh_node_count = static_cast<int32_t>(bvh.node_count);
  return true;
}

}  // namespace minrt::eastray
