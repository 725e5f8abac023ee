// Conservative world-space bounds of the general model's quadric solids and
// CSG blocks (formats/model/quadric.hpp, csg.hpp), for the hierarchy over a
// tree's objects (csg_intersect.hpp; built by csg_object_bvh.hpp). A
// side may be infinite (an unclipped cylinder, a plane); a block that is
// infinite on any side is tested by every ray. Every point a ray can hit
// on a primitive lies in the closure of its inside, so an AND block's hits
// lie in the intersection of its items' bounds and an OR block's in their
// union. The bounds are widened well beyond rounding (kBoundPad): a box
// that is too large costs a little time, one that is too small would
// change the image.
#pragma once

#include <stdint.h>

#include "formats/model/csg.hpp"
#include "formats/model/quadric.hpp"
#include "render/general/csg_intersect.hpp"

namespace minrt::general {

// Relative widening of every finite side (float rounding is ~6e-8).
inline constexpr double kBoundPad = 1e-3;

// An axis-aligned box whose sides may be +-infinity (kInfinity and beyond).
template <class R>
struct OpenBox {
  static constexpr R kInfinity = R(1e30);
  R lo[3], hi[3];

  static OpenBox everything() { return {{-kInfinity, -kInfinity, -kInfinity}, {kInfinity, kInfinity, kInfinity}}; }
  static OpenBox nothing() { return {{kInfinity, kInfinity, kInfinity}, {-kInfinity, -kInfinity, -kInfinity}}; }
  bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
  bool finite() const {
    for (int a = 0; a < 3; ++a)
      if (!(lo[a] > -kInfinity && hi[a] < kInfinity)) return false;
    return true;
  }
  void unite(const OpenBox& b) {
    for (int a = 0; a < 3; ++a) {
      if (b.lo[a] < lo[a]) lo[a] = b.lo[a];
      if (b.hi[a] > hi[a]) hi[a] = b.hi[a];
    }
  }
  void intersect(const OpenBox& b) {
    for (int a = 0; a < 3; ++a) {
      if (b.lo[a] > lo[a]) lo[a] = b.lo[a];
      if (b.hi[a] < hi[a]) hi[a] = b.hi[a];
    }
  }
  // Finite sides moved out by kBoundPad of the box's size and position.
  void widen() {
    for (int a = 0; a < 3; ++a) {
      const bool flo = lo[a] > -kInfinity, fhi = hi[a] < kInfinity;
      const R alo = lo[a] < R(0) ? -lo[a] : lo[a], ahi = hi[a] < R(0) ? -hi[a] : hi[a];
      R mag = R(0);
      if (flo && alo > mag) mag = alo;
      if (fhi && ahi > mag) mag = ahi;
      if (flo && fhi) mag = mag + (hi[a] - lo[a]);
      const R pad = mag * R(kBoundPad) + R(1e-6);
      if (flo) lo[a] = lo[a] - pad;
      if (fhi) hi[a] = hi[a] + pad;
    }
  }
};

namespace bounds_detail {

template <class M>
typename M::real root_of(typename M::real v) {
  using R = typename M::real;
  if (v != v) return OpenBox<R>::kInfinity;  // NaN: no bound known
  return v > R(0) ? M::sqrt(v) : R(0);
}

// The local bound of a primitive's inside (before the sign).
template <class M>
OpenBox<typename M::real> local_box(const model::Quadric<typename M::real>& s) {
  using R = typename M::real;
  OpenBox<R> b = OpenBox<R>::everything();
  if (s.shape == model::QuadricShape::kBox) {
    for (int a = 0; a < 3; ++a) b.lo[a] = -s.q[a], b.hi[a] = s.q[a];
    return b;
  }
  if (s.clip_low) b.lo[2] = s.z_low;
  if (s.clip_high) b.hi[2] = s.z_high;
  const R* q = s.q;
  // A half-space across one axis: q_a x_a + q9 < 0.
  if (q[0] == R(0) && q[1] == R(0) && q[2] == R(0) && q[3] == R(0) && q[4] == R(0) && q[5] == R(0)) {
    const int axes = (q[6] != R(0)) + (q[7] != R(0)) + (q[8] != R(0));
    if (axes != 1) return b;
    const int a = q[6] != R(0) ? 0 : q[7] != R(0) ? 1 : 2;
    const R edge = -q[9] / q[6 + a];
    OpenBox<R> h = OpenBox<R>::everything();
    if (q[6 + a] > R(0)) h.hi[a] = edge;
    else h.lo[a] = edge;
    b.intersect(h);
    return b;
  }
  // x^T A x + g.x + q9 < 0 with A = [[q0 q3/2 q5/2] [q3/2 q1 q4/2] [q5/2 q4/2 q2]].
  const R a00 = q[0], a11 = q[1], a22 = q[2], a01 = q[3] / R(2), a12 = q[4] / R(2), a02 = q[5] / R(2);
  const R det2 = a00 * a11 - a01 * a01;
  if (!(a00 > R(0) && det2 > R(0))) return b;  // open across x or y
  // Whole ellipsoid: centre -A^-1 g / 2, reach sqrt(K (A^-1)_ii).
  const R c00 = a11 * a22 - a12 * a12, c11 = a00 * a22 - a02 * a02, c22 = det2;
  const R c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11, c12 = a01 * a02 - a00 * a12;
  const R det3 = a00 * c00 + a01 * c01 + a02 * c02;
  if (det3 > R(0)) {
    const R g0 = q[6], g1 = q[7], g2 = q[8];
    const R m0 = -(c00 * g0 + c01 * g1 + c02 * g2) / (R(2) * det3);
    const R m1 = -(c01 * g0 + c11 * g1 + c12 * g2) / (R(2) * det3);
    const R m2 = -(c02 * g0 + c12 * g1 + c22 * g2) / (R(2) * det3);
    const R k = -(m0 * g0 + m1 * g1 + m2 * g2) / R(2) - q[9];  // -F(m)
    const R m[3] = {m0, m1, m2}, inv[3] = {c00 / det3, c11 / det3, c22 / det3};
    OpenBox<R> e;
    for (int a = 0; a < 3; ++a) {
      const R r = root_of<M>(k * inv[a]);
      e.lo[a] = m[a] - r, e.hi[a] = m[a] + r;
    }
    b.intersect(e);
    return b;
  }
  // The section at height z is an ellipse in x, y with centre m(z) (linear
  // in z) and K(z) = alpha z^2 + beta z + gamma; bounded over a z range
  // that is finite, or over every z when neither depends on z.
  const R i00 = a11 / det2, i11 = a00 / det2, i01 = -a01 / det2;  // (xy block)^-1
  const R u0 = q[6], u1 = q[7], v0 = q[5], v1 = q[4];              // g_xy(z) = u + v z
  const R iu0 = i00 * u0 + i01 * u1, iu1 = i01 * u0 + i11 * u1;
  const R iv0 = i00 * v0 + i01 * v1, iv1 = i01 * v0 + i11 * v1;
  const R alpha = (v0 * iv0 + v1 * iv1) / R(4) - q[2];
  const R beta = (u0 * iv0 + u1 * iv1) / R(2) - q[8];
  const R gamma = (u0 * iu0 + u1 * iu1) / R(4) - q[9];
  const bool constant = v0 == R(0) && v1 == R(0) && alpha == R(0) && beta == R(0);
  if (!constant && !(s.clip_low && s.clip_high)) return b;
  R zs[3] = {R(0), R(0), R(0)};
  int nz = 1;
  if (!constant) {
    zs[0] = s.z_low, zs[1] = s.z_high, nz = 2;
    if (alpha < R(0)) {
      const R top = -beta / (R(2) * alpha);
      if (top > s.z_low && top < s.z_high) zs[nz++] = top;
    }
  }
  R kmax = R(0);
  OpenBox<R> e = OpenBox<R>::nothing();
  for (int i = 0; i < nz; ++i) {
    const R z = zs[i];
    const R k = (alpha * z + beta) * z + gamma;
    if (k > kmax) kmax = k;
    const R mx = -(iu0 + iv0 * z) / R(2), my = -(iu1 + iv1 * z) / R(2);
    if (mx < e.lo[0]) e.lo[0] = mx;
    if (mx > e.hi[0]) e.hi[0] = mx;
    if (my < e.lo[1]) e.lo[1] = my;
    if (my > e.hi[1]) e.hi[1] = my;
  }
  const R rx = root_of<M>(kmax * i00), ry = root_of<M>(kmax * i11);
  e.lo[0] = e.lo[0] - rx, e.hi[0] = e.hi[0] + rx;
  e.lo[1] = e.lo[1] - ry, e.hi[1] = e.hi[1] + ry;
  e.lo[2] = -OpenBox<R>::kInfinity, e.hi[2] = OpenBox<R>::kInfinity;
  b.intersect(e);
  return b;
}

// w + W * box by interval arithmetic (an infinite side times an exact zero
// adds nothing).
template <class R>
OpenBox<R> mapped(const model::Affine<R>& to_world, const OpenBox<R>& l) {
  OpenBox<R> w;
  const R t[3] = {to_world.t.x, to_world.t.y, to_world.t.z};
  for (int i = 0; i < 3; ++i) {
    R lo = t[i], hi = t[i];
    bool neg_inf = false, pos_inf = false;
    for (int j = 0; j < 3; ++j) {
      const R c = to_world.m[i * 3 + j];
      if (c == R(0)) continue;
      const R a = c > R(0) ? l.lo[j] : l.hi[j], bb = c > R(0) ? l.hi[j] : l.lo[j];
      if (!(a > -OpenBox<R>::kInfinity && a < OpenBox<R>::kInfinity)) neg_inf = true;
      else lo = lo + c * a;
      if (!(bb > -OpenBox<R>::kInfinity && bb < OpenBox<R>::kInfinity)) pos_inf = true;
      else hi = hi + c * bb;
    }
    w.lo[i] = neg_inf ? -OpenBox<R>::kInfinity : lo;
    w.hi[i] = pos_inf ? OpenBox<R>::kInfinity : hi;
  }
  return w;
}

}  // namespace bounds_detail

// The world bound of a primitive's hits.
template <class M>
OpenBox<typename M::real> primitive_box(const model::Quadric<typename M::real>& s) {
  using R = typename M::real;
  model::Affine<R> to_world;
  if (!s.to_local.inverse(to_world)) return OpenBox<R>::everything();
  OpenBox<R> l;
  if (s.inverted) {
    // The complement of a half-space is a half-space; of anything else, unbounded.
    const R* q = s.q;
    const bool half = s.shape == model::QuadricShape::kQuadric && !s.clip_low && !s.clip_high && q[0] == R(0) && q[1] == R(0) &&
                      q[2] == R(0) && q[3] == R(0) && q[4] == R(0) && q[5] == R(0) &&
                      (q[6] != R(0)) + (q[7] != R(0)) + (q[8] != R(0)) == 1;
    if (!half) return OpenBox<R>::everything();
    model::Quadric<R> flipped = s;
    for (int i = 6; i < 10; ++i) flipped.q[i] = -q[i];
    l = bounds_detail::local_box<M>(flipped);
  } else {
    l = bounds_detail::local_box<M>(s);
  }
  if (l.empty()) return OpenBox<R>::nothing();
  l.widen();
  OpenBox<R> w = bounds_detail::mapped(to_world, l);
  w.widen();
  for (int a = 0; a < 3; ++a) {  // a NaN side (overflowing moves or coefficients) is open
    if (w.lo[a] != w.lo[a]) w.lo[a] = -OpenBox<R>::kInfinity;
    if (w.hi[a] != w.hi[a]) w.hi[a] = OpenBox<R>::kInfinity;
  }
  return w;
}

// The world bound of a CSG node's hits (recursive over its items).
template <class M>
OpenBox<typename M::real> node_box(const CsgScene<typename M::real>& s, int32_t id) {
  using R = typename M::real;
  const model::CsgNode& n = s.nodes[id];
  if (n.kind == model::NodeKind::kLeaf) return primitive_box<M>(s.solids[n.primitive]);
  if (n.mode == model::NodeKind::kAnd) {
    if (n.first_child == model::kNoNode) return OpenBox<R>::nothing();
    OpenBox<R> b = OpenBox<R>::everything();
    for (int32_t c = n.first_child; c != model::kNoNode; c = s.nodes[c].next) b.intersect(node_box<M>(s, c));
    return b;
  }
  OpenBox<R> b = OpenBox<R>::nothing();
  for (int32_t c = n.first_child; c != model::kNoNode; c = s.nodes[c].next) b.unite(node_box<M>(s, c));
  return b;
}

}  // namespace minrt::general
