// A bounding-volume hierarchy over the scene's bounded objects (spheres and
// triangles), built once in the arena with binned SAH and traversed with a
// fixed stack: no recursion, no heap. Planes are unbounded and are tested by
// the tracer on every ray.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/model/scene.hpp"
#include "render/general/intersect.hpp"
#include "render/general/wide_node.hpp"

namespace minrt::general {

inline constexpr int kBvhMaxDepth = 60;     // the traversal stack holds one entry per level
inline constexpr int kBvhStack = kBvhMaxDepth + 4;
// The wide tree's (wide_node.hpp): each visit pops one entry and pushes at
// most kWideArity, kWideArity - 1 more per level, and the binary tree, whose
// depth bounds the wide one's, is never deeper than its build stack.
inline constexpr int kWideStack = (kWideArity - 1) * kBvhStack + kWideArity;
inline constexpr int kBvhLeafSize = 4;
inline constexpr int kBvhBins = 12;
inline constexpr int kBvhHostBins = 16;
inline constexpr uint32_t kTriangleBit = 0x80000000u;  // in a primitive reference
inline constexpr uint32_t kSolidBit = 0x40000000u;     // a cylinder or cone

template <class R>
struct Bounds {
  Vec3<R> lo, hi;

  void grow(const Vec3<R>& p) {
    lo = {p.x < lo.x ? p.x : lo.x, p.y < lo.y ? p.y : lo.y, p.z < lo.z ? p.z : lo.z};
    hi = {p.x > hi.x ? p.x : hi.x, p.y > hi.y ? p.y : hi.y, p.z > hi.z ? p.z : hi.z};
  }
  void grow(const Bounds& b) {
    grow(b.lo);
    grow(b.hi);
  }
  R area() const {
    const Vec3<R> e = hi - lo;
    return e.x * e.y + e.y * e.z + e.z * e.x;
  }
  static Bounds empty() {
    constexpr R kBig = static_cast<R>(3.0e38f);
    return {{kBig, kBig, kBig}, {-kBig, -kBig, -kBig}};
  }
};

// An inner node's children are nodes[index] and nodes[index + 1]; a leaf
// holds refs[index .. index + count).
template <class R>
struct BvhNode {
  Bounds<R> box;
  uint32_t index;
  uint16_t count;  // 0 for an inner node
  uint16_t axis;   // split axis of an inner node (near child first)
};

template <class R>
struct Bvh {
  const BvhNode<R>* nodes = nullptr;
  const uint32_t* refs = nullptr;  // sphere index, triangle index | kTriangleBit, solid index | kSolidBit
  uint32_t node_count = 0;
  // The same tree four-wide (wide_bvh.hpp) where it is built; elsewhere an
  // empty member, so that the board's layout has nothing more.
  [[no_unique_address]] WideSlot<R> wide{};
};

namespace bvh_detail {

template <class R>
R abs_of(R v) {
  return v < R(0) ? -v : v;
}

// Boxes are widened by a few parts in a million of their magnitude so that
// rounding in the box or in the slab test never culls a grazing hit that the
// exact intersection routine would find.
template <class R>
Bounds<R> padded(Bounds<R> b) {
  for (int a = 0; a < 3; ++a) {
    R* lo = a == 0 ? &b.lo.x : a == 1 ? &b.lo.y : &b.lo.z;
    R* hi = a == 0 ? &b.hi.x : a == 1 ? &b.hi.y : &b.hi.z;
    const R mag = (abs_of(*lo) > abs_of(*hi) ? abs_of(*lo) : abs_of(*hi)) + (*hi - *lo);
    const R pad = mag * R(4e-6) + R(1e-12);
    *lo = *lo - pad;
    *hi = *hi + pad;
  }
  return b;
}

template <class R>
Bounds<R> bounds_of(const model::Scene<R>& s, uint32_t ref) {
  Bounds<R> b = Bounds<R>::empty();
  if ((ref & kSolidBit) != 0) {
    // Both end discs inside cubes of the larger radius.
    const model::Solid<R>& c = s.solids[ref & ~kSolidBit];
    const R top = c.radius + c.slope * c.height;
    R r = c.radius > top ? c.radius : top;
    if (r < R(0)) r = -r;
    const Vec3<R> e{r, r, r}, tip = c.base + c.axis * c.height;
    b.grow(c.base - e);
    b.grow(c.base + e);
    b.grow(tip - e);
    b.grow(tip + e);
  } else if ((ref & kTriangleBit) != 0) {
    const model::Triangle<R>& t = s.triangles[ref & ~kTriangleBit];
    b.grow(t.p0);
    b.grow(t.p1);
    b.grow(t.p2);
  } else {
    const model::Sphere<R>& sp = s.spheres[ref];
    const R r = sp.radius < R(0) ? -sp.radius : sp.radius;
    b.lo = sp.center - Vec3<R>{r, r, r};
    b.hi = sp.center + Vec3<R>{r, r, r};
  }
  return padded(b);
}

}  // namespace bvh_detail

// Arena bytes the BVH of n primitives may take (for sizing before the build),
// its wide form included where it is built.
template <class R>
constexpr size_t bvh_footprint(uint32_t n) {
  return Arena::footprint<BvhNode<R>>(2 * static_cast<size_t>(n) + 1) + Arena::footprint<uint32_t>(n) +
         Arena::footprint<Bounds<R>>(n) + Arena::footprint<Vec3<R>>(n) + wide_bvh_footprint<R>(n);
}

// Builds over n items: `item(i, ref, box)` gives the i-th item's reference
// and padded bounds. False when the arena is too small (or, for a
// pathological scene, the tree would be deeper than the stack). The EASTRAY
// tracer builds its hierarchies with it too.
template <class M, class Item>
bool build_bvh_over(uint32_t n, Arena& arena, Bvh<typename M::real>& out, Item item) {
  using R = typename M::real;
  out = Bvh<R>{};
  if (n == 0) return true;
  auto* nodes = arena.alloc_zeroed<BvhNode<R>>(2 * static_cast<size_t>(n));
  auto* refs = arena.alloc_zeroed<uint32_t>(n);
  const size_t mark = arena.top_mark();
  auto* boxes = arena.alloc_top<Bounds<R>>(n);
  auto* centers = arena.alloc_top<Vec3<R>>(n);
  if (nodes == nullptr || refs == nullptr || boxes == nullptr || centers == nullptr) {
    arena.release_top(mark);
    return false;
  }
  for (uint32_t i = 0; i < n; ++i) {
    item(i, refs[i], boxes[i]);
    centers[i] = (boxes[i].lo + boxes[i].hi) * R(0.5);
  }
  // Work items: node to fill, its range of refs, its depth.
  struct Work {
    uint32_t node, begin, end;
    int depth;
  };
  Work stack[kBvhStack];
  int top = 0;
  stack[top++] = Work{0, 0, n, 0};
  uint32_t used = 1;
  while (top > 0) {
    const Work it = stack[--top];
    BvhNode<R>& node = nodes[it.node];
    Bounds<R> box = Bounds<R>::empty();
    Bounds<R> cbox = Bounds<R>::empty();
    for (uint32_t i = it.begin; i < it.end; ++i) {
      box.grow(boxes[i]);
      cbox.grow(centers[i]);
    }
    node.box = box;
    const uint32_t count = it.end - it.begin;
    auto make_leaf = [&] {
      node.index = it.begin;
      node.count = static_cast<uint16_t>(count);
    };
    const bool may_leaf = count <= 0xffffu;
    if (may_leaf && (count <= static_cast<uint32_t>(kBvhLeafSize) || it.depth >= kBvhMaxDepth)) {
      make_leaf();
      continue;
    }
    // Binned SAH: along the widest centroid axis with kBvhBins bins on the
    // board (the instruction counts were measured with it), along each
    // axis with kBvhHostBins on the host, whose tree is walked far more.
    constexpr int kBins = kWideBvh ? kBvhHostBins : kBvhBins;
    const Vec3<R> ext = cbox.hi - cbox.lo;
    int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
    const R lo = cbox.lo[axis];
    const R width = ext[axis];
    int best_split = -1;
    R best = R(0);
    // The bin of primitive i along axis `a`. The board compares with the
    // bins' starts (no float-to-int conversion needed); the host converts
    // and clamps.
    const R scale = width > R(0) ? R(kBins) / width : R(0);  // the board's, one division a node
    R per_unit[3];  // the host's bins per unit of each axis, set before that axis is binned
    auto bin_of = [&](uint32_t i, int a) {
      if constexpr (kWideBvh) {
        const R f = (centers[i][a] - cbox.lo[a]) * per_unit[a];
        const int b = f > R(0) ? static_cast<int>(f) : 0;
        return b < kBins - 1 ? b : kBins - 1;
      } else {
        const R f = (centers[i][a] - lo) * scale;
        int b = 0;
        while (b + 1 < kBins && f >= M::from_int(b + 1)) ++b;
        return b;
      }
    };
    // Bins along axis `a`: updates best, best_split and axis.
    auto try_axis = [&](int a) {
      Bounds<R> bin_box[kBins];
      uint32_t bin_count[kBins] = {};
      for (auto& b : bin_box) b = Bounds<R>::empty();
      for (uint32_t i = it.begin; i < it.end; ++i) {
        const int b = bin_of(i, a);
        bin_box[b].grow(boxes[i]);
        ++bin_count[b];
      }
      R right_area[kBins];
      uint32_t right_count[kBins];
      Bounds<R> acc = Bounds<R>::empty();
      uint32_t cnt = 0;
      for (int b = kBins - 1; b > 0; --b) {
        if (bin_count[b] > 0) acc.grow(bin_box[b]);
        cnt += bin_count[b];
        right_area[b] = cnt > 0 ? acc.area() : R(0);
        right_count[b] = cnt;
      }
      acc = Bounds<R>::empty();
      cnt = 0;
      for (int b = 1; b < kBins; ++b) {
        if (bin_count[b - 1] > 0) acc.grow(bin_box[b - 1]);
        cnt += bin_count[b - 1];
        if (cnt == 0 || right_count[b] == 0) continue;
        const R cost = acc.area() * M::from_int(static_cast<int32_t>(cnt)) +
                       right_area[b] * M::from_int(static_cast<int32_t>(right_count[b]));
        if (best_split < 0 || cost < best) {
          best = cost;
          best_split = b;
          if constexpr (kWideBvh) axis = a;
        }
      }
    };
    if constexpr (kWideBvh) {
      for (int a = 0; a < 3; ++a) {
        if (!(ext[a] > R(0))) continue;
        per_unit[a] = R(kBins) / ext[a];
        try_axis(a);
      }
    } else if (width > R(0)) {
      try_axis(axis);
    }
    const R leaf_cost = box.area() * M::from_int(static_cast<int32_t>(count));
    uint32_t mid;
    if (best_split < 0) {
      if (may_leaf && count <= 16u) {
        make_leaf();
        continue;
      }
      mid = it.begin + count / 2;  // all centres equal: split the list in two
    } else {
      if (may_leaf && count <= 16u && best >= leaf_cost) {
        make_leaf();  // splitting would cost more than testing them all
        continue;
      }
      uint32_t i = it.begin, j = it.end;
      while (i < j) {
        if (bin_of(i, axis) < best_split) {
          ++i;
        } else {
          --j;
          const uint32_t r = refs[i]; refs[i] = refs[j]; refs[j] = r;
          const Bounds<R> bx = boxes[i]; boxes[i] = boxes[j]; boxes[j] = bx;
          const Vec3<R> c = centers[i]; centers[i] = centers[j]; centers[j] = c;
        }
      }
      mid = i;
    }
    if (top + 2 > kBvhStack) {
      arena.release_top(mark);
      return false;
    }
    const uint32_t left = used;
    used += 2;
    node.index = left;
    node.count = 0;
    node.axis = static_cast<uint16_t>(axis);
    stack[top++] = Work{left + 1, mid, it.end, it.depth + 1};
    stack[top++] = Work{left, it.begin, mid, it.depth + 1};
  }
  arena.release_top(mark);
  out.nodes = nodes;
  out.refs = refs;
  out.node_count = used;
  return true;
}

// Builds over every sphere, triangle and solid of a general scene.
template <class M>
bool build_bvh(const model::Scene<typename M::real>& scene, Arena& arena, Bvh<typename M::real>& out) {
  using R = typename M::real;
  const uint32_t n = scene.sphere_count + scene.triangle_count + scene.solid_count;
  const uint32_t polys = scene.sphere_count + scene.triangle_count;
  return build_bvh_over<M>(n, arena, out, [&](uint32_t i, uint32_t& ref, Bounds<R>& box) {
    ref = i < scene.sphere_count ? i
          : i < polys            ? (i - scene.sphere_count) | kTriangleBit
                                 : (i - polys) | kSolidBit;
    box = bvh_detail::bounds_of(scene, ref);
  });
}

// Slab test against a box: the distance at which the ray enters it (0 when
// it starts inside), or a negative value when it misses it or enters beyond
// `limit`. Always inlined: it is the innermost test of every traversal.
template <class R>
[[gnu::always_inline]] inline R box_entry(const Bounds<R>& b, const Vec3<R>& origin, const Vec3<R>& inv, R limit) {
  R t0 = (b.lo.x - origin.x) * inv.x, t1 = (b.hi.x - origin.x) * inv.x;
  R tmin = t0 < t1 ? t0 : t1, tmax = t0 < t1 ? t1 : t0;
  t0 = (b.lo.y - origin.y) * inv.y;
  t1 = (b.hi.y - origin.y) * inv.y;
  R lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
  tmin = lo > tmin ? lo : tmin;
  tmax = hi < tmax ? hi : tmax;
  t0 = (b.lo.z - origin.z) * inv.z;
  t1 = (b.hi.z - origin.z) * inv.z;
  lo = t0 < t1 ? t0 : t1;
  hi = t0 < t1 ? t1 : t0;
  tmin = lo > tmin ? lo : tmin;
  tmax = hi < tmax ? hi : tmax;
  if (tmin < R(0)) tmin = R(0);
  return tmax >= tmin && tmin <= limit ? tmin : R(-1);
}

// What a zero direction component is replaced by before its inverse is
// taken, so the slab test never multiplies zero by infinity.
template <class R>
inline constexpr R kTinyDirection = static_cast<R>(1e-30f);

// 1/d per axis, with zero components (either sign) replaced by
// kTinyDirection.
template <class R>
Vec3<R> inverse_dir(const Vec3<R>& d) {
  auto inv = [](R v) { return R(1) / (v == R(0) ? kTinyDirection<R> : v); };
  return {inv(d.x), inv(d.y), inv(d.z)};
}

}  // namespace minrt::general
