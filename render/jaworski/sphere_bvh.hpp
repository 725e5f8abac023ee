// A binary bounding-ball hierarchy over a Jaworski scene's spheres that
// skips only spheres the tracer's own arithmetic would miss, so the bytes do
// not change (the 24 reference BMPs pin them). A node's two children, or a
// leaf's one or two spheres, are tested at once in vector lanes (GCC/Clang
// vector extensions: an SSE2 register of doubles on the host, plain scalar
// code where there is no vector unit); every lane does the scalar
// operations in the scalar order. (Four lanes measured slower on SSE2.)
//
// Why a skip is exact. A sphere is missed when the computed
// delta = doc^2 - |oc|^2 + r^2 is negative. For a unit ray direction that
// holds whenever the ray's line passes farther than r + k(|oc| + r) from the
// centre, with k = 7 sqrt(u) (u the unit roundoff): the rounding of delta,
// of oc and of |d|^2 = 1 +- 16u all stay below k^2 |oc|^2. A node bounds its
// spheres by a ball (C, G) with |c - C| + r <= G, so when its own computed
// |oC|^2 - (d.oC)^2 exceeds G^2 (1 + kRel) + kRel |oC|^2, every sphere in it
// is that far from the line (kRel covers 5k, k and the node test's own
// rounding: 1e-6 in double, 2e-2 in float). Rays whose |d|^2 is not within
// 16u of 1, tiny |oC|^2 (subnormal rounding is absolute, not relative) and
// NaN or infinite values are never skipped: every comparison is written so
// that they fail it. Visiting order does not matter because closest()
// breaks ties by object index.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/jaworski/jaworski_scene.hpp"

namespace minrt::jaworski {

template <class M>
class SphereBvh {
  using R = typename M::real;
  using V = Vec3<R>;

 public:
  static constexpr int kWidth = 2;  // children a node (an SSE2 register of doubles); inner nodes use both
  static constexpr int32_t kSearchedSplit = 48;
  typedef R Lanes __attribute__((vector_size(kWidth * sizeof(R))));

  // Two balls: sphere centres with radius * radius (a leaf, `count` of
  // them), or the bounds of two child nodes with their squared, widened radii.
  struct Node {
    Lanes cx, cy, cz, r2;
    int32_t child[kWidth];  // leaf: object indices
    int32_t count;          // lanes in use
    bool leaf;
  };

  // Calls hit(object index, doc, delta) for every sphere whose computed
  // delta is >= 0 (a superset is never needed: those are exactly the ones
  // closest() would offer); hit returns true to stop early.
  template <class F>
  bool for_hits(const V& o, const V& d, F&& hit) const {
    if (node_count_ == 0) return false;
    const bool cull = unit_enough(dot(d, d));
    int32_t stack[kMaxStack];
    int sp = 0;
    stack[sp++] = 0;
    while (sp > 0) {
      const Node& n = nodes_[stack[--sp]];
      const Lanes ox = o.x - n.cx, oy = o.y - n.cy, oz = o.z - n.cz;
      const Lanes doc = d.x * ox + d.y * oy + d.z * oz;
      const Lanes occ = ox * ox + oy * oy + oz * oz;
      if (n.leaf) {
        const Lanes delta = sphere_delta(d, ox, oy, oz, doc, occ, n.r2);
        for (int32_t i = 0; i < n.count; ++i)
          if (delta[i] >= R(0) && hit(n.child[i], doc[i], delta[i])) return true;
        continue;
      }
      // Lanes whose ball the line provably misses (margin > 0) are skipped.
      // kMinScale keeps tiny |oC|^2 (< kMinScale, where the left side can
      // not exceed it) from ever being skipped.
      const Lanes margin = (occ - doc * doc) - (n.r2 + kRel * occ + kMinScale);
      if (!cull || !(margin[1] > R(0))) stack[sp++] = n.child[1];
      if (!cull || !(margin[0] > R(0))) stack[sp++] = n.child[0];
    }
    return false;
  }

  // The discriminant a ray o + t d has with a sphere (centre c, radius^2
  // r2), given oc = o - c, doc = d.oc and occ = |oc|^2; its roots are
  // -doc -+ sqrt(delta). In double it is the original's doc^2 - |oc|^2 + r^2.
  // In float that form cancels: its error, about u |oc|^2, moves a hit
  // point off the surface by about u |oc|^2 / r (speckled self-shadowing
  // when the eye is far from a small sphere), so float computes the same
  // quantity as r^2 - |oc - doc d|^2 (d a unit vector), whose error is
  // about u |oc| r. The node walk's skips still hold: they only need the
  // computed delta to be negative for a line as far from the centre as
  // they require, and this form errs less.
  template <class T>
  static T sphere_delta(const V& d, const T& ox, const T& oy, const T& oz, const T& doc, const T& occ,
                        const T& r2) {
    if constexpr (kDouble) {
      return doc * doc - occ + r2;
    } else {
      const T px = ox - doc * d.x, py = oy - doc * d.y, pz = oz - doc * d.z;
      return r2 - (px * px + py * py + pz * pz);
    }
  }

  // Whether |d|^2 = dd is within 16u of 1, as the skips' reasoning needs.
  static bool unit_enough(R dd) { return dd > R(1) - kUnitTolerance && dd < R(1) + kUnitTolerance; }

  // A sphere as gather() hands it on: what the tracer's test reads.
  struct Candidate {
    V c;
    R r2;
    int32_t index;
  };

  // How far apart unit directions may be for gather(): `spread` is the
  // largest computed |d - a| over the rays, widened for rounding.
  static R widen_spread(R spread) { return spread * (R(1) + kRel) + R(64) * kUnit; }

  // Every sphere that one of a fan of rays o + t d may hit, where each d
  // (with |d|^2 within 16u of 1) is within `spread` (widen_spread) of a:
  // the count, or -1 if more than `capacity` (or a is not a unit vector).
  //
  // Why it is exact: for such a d the distance from a ball's centre C to
  // its line is at least the distance to a's line minus |oC| spread, so a
  // ball whose computed distance to a's line exceeds
  // T = sqrt(bound2 + kRel |oC|^2 + kMinScale) + spread |oC| (with a kRel
  // relative margin for T's own rounding) passes the per-ray test's
  // condition for every d, and its spheres would all be missed.
  int32_t gather(const V& o, const V& a, R spread, Candidate* out, int32_t capacity) const {
    if (node_count_ == 0) return 0;
    if (!unit_enough(dot(a, a))) return -1;
    int32_t stack[kMaxStack];
    int sp = 0, count = 0;
    stack[sp++] = 0;
    while (sp > 0) {
      const Node& n = nodes_[stack[--sp]];
      const Lanes ox = o.x - n.cx, oy = o.y - n.cy, oz = o.z - n.cz;
      const Lanes doc = a.x * ox + a.y * oy + a.z * oz;
      const Lanes occ = ox * ox + oy * oy + oz * oz;
      // A sphere's own ball: radius^2 (1 + 4 kRel) covers the widening a
      // node's bound gets.
      const Lanes bound = n.leaf ? n.r2 * (R(1) + R(4) * kRel) : n.r2;
      Lanes reach{};
      for (int i = 0; i < kWidth; ++i)
        reach[i] = M::sqrt(bound[i] + kRel * occ[i] + kMinScale) + spread * M::sqrt(occ[i]);
      const Lanes margin = (occ - doc * doc) - reach * reach * (R(1) + kRel);
      for (int32_t i = n.count - 1; i >= 0; --i) {
        if (margin[i] > R(0)) continue;
        if (!n.leaf) {
          stack[sp++] = n.child[i];
          continue;
        }
        if (count == capacity) return -1;
        out[count++] = Candidate{V{n.cx[i], n.cy[i], n.cz[i]}, n.r2[i], n.child[i]};
      }
    }
    return count;
  }

  // Arena bytes for a scene of `objects` objects (alignment included).
  static size_t arena_bytes(int32_t objects) {
    const size_t n = objects > 0 ? static_cast<size_t>(objects) : 0;
    return (n + 1) * (2 * sizeof(Node) + sizeof(Item) + sizeof(int32_t)) + 2 * alignof(Node);
  }

  // False when the arena is too small.
  bool build(const Scene<R>& s, Arena& arena) {
    int32_t spheres = 0;
    for (int32_t i = 0; i < s.object_count; ++i) spheres += s.objects[i].kind == ShapeKind::kSphere ? 1 : 0;
    plane_count_ = s.object_count - spheres;
    // Inner nodes have two children and leaves at least one sphere, so
    // there are at most 2 spheres - 1 nodes.
    nodes_ = arena.alloc_zeroed<Node>(static_cast<size_t>(2 * spheres + 1));
    Item* items = arena.alloc_zeroed<Item>(static_cast<size_t>(spheres + 1));
    planes_ = arena.alloc_zeroed<int32_t>(static_cast<size_t>(plane_count_ + 1));
    if (nodes_ == nullptr || items == nullptr || planes_ == nullptr) return false;
    int32_t si = 0, pi = 0;
    for (int32_t i = 0; i < s.object_count; ++i) {
      const Object<R>& ob = s.objects[i];
      if (ob.kind == ShapeKind::kSphere) {
        const R r = ob.radius < R(0) ? -ob.radius : ob.radius;
        items[si++] = Item{ob.point, r, ob.radius * ob.radius, i};
      } else {
        planes_[pi++] = i;
      }
    }
    node_count_ = 0;
    if (spheres > 0) {
      node_count_ = 1;
      R g2;
      V c;
      build_node(0, items, spheres, c, g2);
    }
    return true;
  }

  int32_t plane_count() const { return plane_count_; }
  int32_t plane(int32_t i) const { return planes_[i]; }

 private:
  struct Item {
    V c;
    R radius;  // |radius|
    R r2;      // radius * radius, as the tracer computes it
    int32_t index;
  };

  static constexpr bool kDouble = sizeof(R) >= 8;
  static constexpr R kRel = kDouble ? R(1e-6) : R(2e-2);
  static constexpr R kUnit = kDouble ? R(1.1102230246251565e-16) : R(5.9604645e-8);  // unit roundoff
  static constexpr R kUnitTolerance = R(16) * kUnit;
  static constexpr R kMinScale = kDouble ? R(1e-200) : R(1e-20);
  // Median halves of 2^31 spheres reach kSearchedSplit in 26 levels, and
  // searched splits add fewer than kSearchedSplit more; the walk keeps one
  // pending sibling a level.
  static constexpr int kMaxStack = 32 + kSearchedSplit + 8;

  static R key(const Item& s, int axis) { return axis == 0 ? s.c.x : axis == 1 ? s.c.y : s.c.z; }

  // The ball around items[0, count): centre the middle of the centres'
  // box, radius the farthest reach; false if some value is NaN.
  static bool ball(const Item* items, int32_t count, V& centre, R& radius, V& extent) {
    V lo = items[0].c, hi = lo;
    for (int32_t i = 1; i < count; ++i) {
      const V& c = items[i].c;
      lo = V{c.x < lo.x ? c.x : lo.x, c.y < lo.y ? c.y : lo.y, c.z < lo.z ? c.z : lo.z};
      hi = V{c.x > hi.x ? c.x : hi.x, c.y > hi.y ? c.y : hi.y, c.z > hi.z ? c.z : hi.z};
    }
    centre = (lo + hi) * R(0.5);
    extent = hi - lo;
    R g = R(0);
    bool ok = true;
    for (int32_t i = 0; i < count; ++i) {
      const V e = items[i].c - centre;
      const R reach = M::sqrt(dot(e, e)) + items[i].radius;
      if (!(reach >= R(0))) ok = false;
      if (reach > g) g = reach;
    }
    radius = g;
    return ok;
  }

  // Fills node `id` from items[0, count); gives back its bounding ball
  // (centre, widened squared radius) for the parent's lane.
  void build_node(int32_t id, Item* items, int32_t count, V& centre, R& bound2) {
    R g;
    V extent;
    const bool ok = ball(items, count, centre, g, extent);
    g = g * (R(1) + kRel);
    bound2 = ok ? g * g * (R(1) + kRel) : R(1) / R(0);  // NaN somewhere: never skip this ball

    Node& n = nodes_[id];
    if (count <= kWidth) {
      n.leaf = true;
      n.count = count;
      for (int32_t i = 0; i < count; ++i) {
        n.cx[i] = items[i].c.x;
        n.cy[i] = items[i].c.y;
        n.cz[i] = items[i].c.z;
        n.r2[i] = items[i].r2;
        n.child[i] = items[i].index;
      }
      return;
    }
    // Two halves: for a few spheres the split (axis and place) whose balls
    // cover least (count x radius^2 summed), else the median along the
    // widest axis.
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    int32_t split = count / 2;
    if (count <= kSearchedSplit) {
      R best = R(-1);
      for (int a = 0; a < 3; ++a) {
        sort(items, count, a);
        for (int32_t k = 1; k < count; ++k) {
          V c, e;
          R gl, gr;
          if (!ball(items, k, c, gl, e) || !ball(items + k, count - k, c, gr, e)) continue;
          const R cost = M::from_int(k) * gl * gl + M::from_int(count - k) * gr * gr;
          if (best < R(0) || cost < best) {
            best = cost;
            axis = a;
            split = k;
          }
        }
      }
    }
    sort(items, count, axis);
    n.leaf = false;
    n.count = kWidth;
    const int32_t first = node_count_;
    node_count_ += kWidth;
    const int32_t ends[kWidth] = {split, count};
    int32_t begin = 0;
    for (int32_t part = 0; part < kWidth; ++part) {
      V c;
      R b2;
      build_node(first + part, items + begin, ends[part] - begin, c, b2);
      n.cx[part] = c.x;
      n.cy[part] = c.y;
      n.cz[part] = c.z;
      n.r2[part] = b2;
      n.child[part] = first + part;
      begin = ends[part];
    }
  }

  // Heap sort of items[0, count) by centre along `axis`: it ends whatever
  // the comparisons say (NaN centres only unbalance the tree).
  static void sort(Item* a, int32_t count, int axis) {
    auto sift = [&](int32_t root, int32_t end) {
      for (;;) {
        int32_t child = 2 * root + 1;
        if (child >= end) return;
        if (child + 1 < end && key(a[child], axis) < key(a[child + 1], axis)) ++child;
        if (!(key(a[root], axis) < key(a[child], axis))) return;
        const Item t = a[root];
        a[root] = a[child];
        a[child] = t;
        root = child;
      }
    };
    for (int32_t i = count / 2 - 1; i >= 0; --i) sift(i, count);
    for (int32_t end = count - 1; end > 0; --end) {
      const Item t = a[0];
      a[0] = a[end];
      a[end] = t;
      sift(0, end);
    }
  }

  Node* nodes_ = nullptr;
  int32_t* planes_ = nullptr;
  int32_t node_count_ = 0, plane_count_ = 0;
};

}  // namespace minrt::jaworski
