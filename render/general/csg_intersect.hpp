// Rays against CSG trees of quadric solids (the general model's
// formats/model/csg.hpp and quadric.hpp): membership (a crossing of a solid
// is a surface of its block when the point passes every enclosing AND,
// inside the other items, and OR, outside them; the top node's items are
// independent objects), RANGE as a bound, and the walk over the top node's
// objects through a BVH with the unbounded ones in a list. Of equally near
// hits the object earlier in the list wins, as in the plain walk in order,
// so the hierarchy never changes a pixel. The EASTRAY tracer draws with it.
#pragma once

#include <stdint.h>

#include "core/base/bit_cast.hpp"
#include "core/math/vec3.hpp"
#include "formats/model/csg.hpp"
#include "formats/model/quadric.hpp"
#include "render/general/bvh.hpp"
#include "render/general/quadric_shape.hpp"

namespace minrt::general {

// The solids and the tree over them.
template <class R>
struct CsgScene {
  const model::CsgNode* nodes;
  const model::Quadric<R>* solids;
};

// The top node's objects: a BVH over the bounded ones (node ids in refs;
// nodes may be null) and the unbounded ones, tested by every ray.
template <class R>
struct CsgObjects {
  const BvhNode<R>* nodes;
  const uint32_t* refs;
  const int32_t* unbounded;
  int32_t unbounded_count;
};

template <class R>
struct SolidHit {
  R t = R(-1);
  Vec3<R> normal{};  // unit outward normal of the block at the hit
  int32_t material = model::kNoNode;
  bool found = false;
};

// The least value above a positive t (t itself when infinite or NaN): an
// earlier item may still win at exactly the best t so far.
template <class R>
R next_above(R t) {
  if (!(t > R(0) && t < R(3e38))) return t;
  if constexpr (sizeof(R) == 4) return bit_cast<R>(bit_cast<uint32_t>(t) + 1u);
  else return bit_cast<R>(bit_cast<uint64_t>(t) + 1u);
}

template <class R>
bool csg_inside(const CsgScene<R>& s, int32_t id, const Vec3<R>& p) {
  const model::CsgNode& n = s.nodes[id];
  if (n.kind == model::NodeKind::kLeaf) return inside(s.solids[n.primitive], p);
  if (n.mode == model::NodeKind::kAnd) {
    for (int32_t c = n.first_child; c != model::kNoNode; c = s.nodes[c].next)
      if (!csg_inside(s, c, p)) return false;
    return n.first_child != model::kNoNode;
  }
  for (int32_t c = n.first_child; c != model::kNoNode; c = s.nodes[c].next)
    if (csg_inside(s, c, p)) return true;
  return false;
}

// Whether a point on the surface of `node` is a surface of the whole tree.
template <class R>
bool csg_accepted(const CsgScene<R>& s, int32_t node, const Vec3<R>& p) {
  int32_t cur = node;
  for (int32_t par = s.nodes[cur].parent; par != model::kNoNode; cur = par, par = s.nodes[cur].parent) {
    const model::CsgNode& pn = s.nodes[par];
    if (pn.mode == model::NodeKind::kTop) return true;
    for (int32_t c = pn.first_child; c != model::kNoNode; c = s.nodes[c].next) {
      if (c == cur) continue;
      const bool in = csg_inside(s, c, p);
      if (pn.mode == model::NodeKind::kAnd && !in) return false;
      if (pn.mode == model::NodeKind::kOr && in) return false;
    }
  }
  return true;
}

// The nearest accepted crossing below t_max in the subtree of `id`; lowers
// t_max to it. `shadow`: solids flagged no_shadow are not there.
template <class M>
void csg_nearest(const CsgScene<typename M::real>& s, int32_t id, const Vec3<typename M::real>& o,
                 const Vec3<typename M::real>& d, typename M::real t_min, typename M::real& t_max,
                 SolidHit<typename M::real>& hit, bool shadow) {
  using R = typename M::real;
  using V = Vec3<R>;
  const model::CsgNode& n = s.nodes[id];
  if (n.kind == model::NodeKind::kLeaf) {
    const model::Quadric<R>& solid = s.solids[n.primitive];
    if (shadow && solid.no_shadow) return;
    Crossing<R> c[4];
    const int k = crossings<M>(solid, o, d, t_min, t_max, c);
    for (int i = 0; i < k; ++i) {
      if (!csg_accepted(s, id, o + d * c[i].t)) continue;
      t_max = c[i].t;
      hit.t = c[i].t;
      V wn = solid.to_local.transposed(c[i].normal);
      if (solid.inverted) wn = -wn;
      const R len2 = dot(wn, wn);
      hit.normal = len2 > R(0) ? wn / M::sqrt(len2) : -d;
      hit.material = solid.material[c[i].face];
      hit.found = true;
      return;
    }
    return;
  }
  if (n.kind == model::NodeKind::kRange && !meets<M>(s.solids[n.primitive], o, d, t_min, t_max)) return;
  for (int32_t c = n.first_child; c != model::kNoNode; c = s.nodes[c].next)
    csg_nearest<M>(s, c, o, d, t_min, t_max, hit, shadow);
}

// Every item of a hierarchy's leaves, nearer child first, boxes that begin
// beyond t_max skipped: `visit(ref)` may lower t_max as it finds hits.
template <class R, class Visit>
[[gnu::always_inline]] inline void visit_nearer_first(const BvhNode<R>* nodes, const uint32_t* refs,
                                                      const Vec3<R>& o, const Vec3<R>& d, const R& t_max,
                                                      Visit&& visit) {
  const Vec3<R> inv = inverse_dir(d);
  uint32_t stack[kBvhStack];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode<R>& nd = nodes[stack[--top]];
    if (box_entry(nd.box, o, inv, next_above(t_max)) < R(0)) continue;
    if (nd.count > 0) {
      for (uint32_t k = 0; k < nd.count; ++k) visit(refs[nd.index + k]);
      continue;
    }
    const bool flip = d[nd.axis] < R(0);
    stack[top++] = nd.index + (flip ? 0u : 1u);  // the farther child waits
    stack[top++] = nd.index + (flip ? 1u : 0u);
  }
}

// The nearest hit among the top node's objects, nearer boxes first.
template <class M>
void csg_nearest_object(const CsgScene<typename M::real>& s, const CsgObjects<typename M::real>& objects,
                        const Vec3<typename M::real>& o, const Vec3<typename M::real>& d, typename M::real t_min,
                        typename M::real& t_max, SolidHit<typename M::real>& hit, bool shadow) {
  using R = typename M::real;
  constexpr int32_t kNoObject = 0x7fffffff;  // the caller's t_max stays exclusive
  int32_t best = kNoObject;
  auto test = [&](int32_t id) {
    R limit = best != kNoObject && id < best ? next_above(t_max) : t_max;
    SolidHit<R> h;
    csg_nearest<M>(s, id, o, d, t_min, limit, h, shadow);
    if (!h.found) return;
    hit = h;
    t_max = h.t;
    best = id;
  };
  for (int32_t i = 0; i < objects.unbounded_count; ++i) test(objects.unbounded[i]);
  if (objects.nodes == nullptr) return;
  visit_nearer_first(objects.nodes, objects.refs, o, d, t_max,
                     [&](uint32_t ref) { test(static_cast<int32_t>(ref)); });
}

}  // namespace minrt::general
