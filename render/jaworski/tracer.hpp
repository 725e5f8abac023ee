// Jaworski's tracer, operation for operation (SPEC.md 3.3): the original
// uses only + - x / and sqrt in double precision, so with the same order of
// operations a double build gives its bytes exactly. Hence its own small
// tracer rather than the general one: no normal flipping, shadow and mirror
// rays start 1e-5 along the normal, the first object wins ties, a depth of
// 0 or a miss gives the background, mixtures are summed in file order, and
// bytes are round-half-to-even of 255 x the clamped value.
//
// The float instantiation (the board's) keeps that structure but computes
// where rays meet surfaces more robustly, since float's roundoff at the
// scene's magnitudes easily exceeds the original's 1e-5 offset: sphere
// discriminants without cancellation (SphereBvh::sphere_delta), the root
// near zero from the roots' product (roots()), a secondary ray never asks
// about the surface it leaves (left_object()), and the offset grows with the
// hit's magnitudes (offset()). Double keeps the original's operations.
#pragma once

#include <stdint.h>

#include "core/image/row_sink.hpp"
#include "core/base/arena.hpp"
#include "formats/jaworski/jaworski_scene.hpp"
#include "render/jaworski/sphere_bvh.hpp"

namespace minrt::jaworski {

template <class M>
class Tracer {
  using R = typename M::real;
  using V = Vec3<R>;

 public:
  // The sphere hierarchy and the directional lights' unit vectors take
  // arena_bytes(scene.object_count, scene.light_count) of `arena`; ready()
  // says whether they fitted (render nothing otherwise).
  Tracer(const Scene<R>& s, Arena& arena) : s_(s), ready_(bvh_.build(s, arena) && unit_lights(arena)) {}
  static size_t arena_bytes(int32_t objects, int32_t lights) {
    return SphereBvh<M>::arena_bytes(objects) + (static_cast<size_t>(lights > 0 ? lights : 0) + 1) * sizeof(V) +
           alignof(V);
  }
  bool ready() const { return ready_; }

  // One row of RGBA bytes; y = 0 is the bottom row, as the original renders.
  // The camera's rays go in fans of kFan neighbours, which first ask the
  // hierarchy which spheres any of them may hit (SphereBvh::gather); each
  // ray then tests only those.
  void render_row(int y, uint8_t* rgba) const {
    const R sw = s_.canvas_width, sh = s_.canvas_height;
    const R left = R(-0.5) * sw, bottom = R(-0.5) * sh;
    const R py = bottom + sh * (M::from_int(y) + R(0.5)) / M::from_int(s_.height);
    const V origin{R(0), R(0), -s_.depth};
    V dirs[kFan];
    typename SphereBvh<M>::Candidate candidates[kCandidates];
    for (int x0 = 0; x0 < s_.width; x0 += kFan) {
      const int n = s_.width - x0 < kFan ? s_.width - x0 : kFan;
      for (int i = 0; i < n; ++i) {
        const R px = left + sw * (M::from_int(x0 + i) + R(0.5)) / M::from_int(s_.width);
        dirs[i] = normalize(V{px, py, s_.depth});
      }
      const V& axis = dirs[n / 2];
      const V e0 = dirs[0] - axis, e1 = dirs[n - 1] - axis;
      const R s0 = M::sqrt(dot(e0, e0)), s1 = M::sqrt(dot(e1, e1));
      const R spread = SphereBvh<M>::widen_spread(s0 > s1 ? s0 : s1);
      // NaN spread (a degenerate scene): every ray walks the hierarchy.
      const int32_t found = spread >= R(0) ? bvh_.gather(origin, axis, spread, candidates, kCandidates) : -1;
      for (int i = 0; i < n; ++i) {
        const V c = found >= 0 ? trace_among(s_.ray_depth, origin, dirs[i], candidates, found)
                               : trace(s_.ray_depth, origin, dirs[i]);
        uint8_t* o = rgba + 4 * (x0 + i);
        o[0] = to_byte(c.x);
        o[1] = to_byte(c.y);
        o[2] = to_byte(c.z);
        o[3] = 255;
      }
    }
  }

  void render(RgbaRowSink sink, uint8_t* row) const {
    sink.begin(s_.width, s_.height);
    for (int y = 0; y < s_.height; ++y) {
      render_row(y, row);
      sink.row(y, row);
    }
    sink.end();
  }

  // A colour channel's byte: 255 x v clamped to [0, 1], rounded half to
  // even (test/jaworski/jaworski_byte_test.cpp pins it).
  static uint8_t to_byte(R v) {
    const R x = R(255) * max0(min1(v));
    // Round half to even (Haskell's round) by the addition's own rounding:
    // x is in [0, 255] (a NaN v gives 0), so x + 2^52 (2^23 in float) has
    // no bits below the units and rounds x to nearest, ties to even; the
    // subtraction is then exact.
    const R rounded = (x + kRoundShift) - kRoundShift;
    return static_cast<uint8_t>(M::to_int(rounded));
  }

 private:
  static constexpr bool kDouble = sizeof(R) >= 8;
  static constexpr R kEps = static_cast<R>(1e-5);
  static constexpr R kUnit = R(5.9604645e-8);  // float's unit roundoff (used in float only)
  static constexpr R kOffsetUlps = R(4);
  static constexpr R kSplit = R(4097);  // 2^12 + 1: splits a float's 24 bits into two halves
  static constexpr R kRoundShift = sizeof(R) >= 8 ? R(4503599627370496.0) : R(8388608.0);  // 2^52, 2^23
  static constexpr int kFan = 16;         // camera rays that share one gather()
  static constexpr int kCandidates = 32;  // spheres a fan may keep; more: each ray walks the hierarchy

  // v x (1/|v|), as the original normalises.
  static V normalize(const V& v) { return v * (R(1) / M::sqrt(dot(v, v))); }
  // Haskell's max 0 y and min 1 y (a NaN argument gives 0 and NaN).
  static R max0(R y) { return R(0) <= y ? y : R(0); }
  static R min1(R y) { return R(1) <= y ? R(1) : y; }

  // Smallest t > 0 over all objects, the first object on a tie; -1 if none.
  // Objects are visited planes first, then the spheres the hierarchy cannot
  // rule out; a tie goes to the lower index, as in the original's file order.
  R closest(const V& o, const V& d, int32_t& hit, int32_t skip) const {
    Nearest n = planes_hit(o, d, skip);
    bvh_.for_hits(o, d, [&](int32_t i, R doc, R delta) {
      if (i == skip) return false;
      const Roots t = roots(o, i, doc, delta);
      n.offer(t.near, i);
      n.offer(t.far, i);
      return false;
    });
    hit = n.hit;
    return n.best;
  }

  // Where the ray o + t d meets sphere i (doc = d.(o - c), delta >= 0 its
  // discriminant): the original's -doc -+ sqrt(delta) in double. In float
  // the root nearer zero loses everything when the ray starts near the
  // surface of a sphere that is large beside the distance (a ground sphere
  // of radius 1e6 a unit below the eye), so it is c0 / (the other root),
  // the roots' product c0 = |o - c|^2 - r^2 computed without rounding
  // error before the last addition (exact_c0).
  struct Roots {
    R near, far;
  };
  Roots roots(const V& o, int32_t i, R doc, R delta) const {
    const R root = M::sqrt(delta);
    if constexpr (kDouble) {
      return Roots{-doc - root, -doc + root};
    } else {
      const Object<R>& ob = s_.objects[i];
      const R c0 = exact_c0(o - ob.point, ob.radius);
      if (doc < R(0)) {
        const R far = -doc + root;
        return Roots{c0 / far, far};
      }
      const R near = -doc - root;
      return Roots{near, near < R(0) ? c0 / near : -doc + root};
    }
  }

  // |v|^2 - r^2 with one rounding, nearly: each square split into two
  // floats exactly (Dekker's product: halves of 12 bits multiply without
  // rounding) and the eight parts summed with a running compensation
  // (Neumaier), which leaves an error of about u |result| + u^2 |v|^2.
  static R exact_c0(const V& v, R r) {
    R parts[8];
    square(v.x, parts[0], parts[1]);
    square(v.y, parts[2], parts[3]);
    square(v.z, parts[4], parts[5]);
    square(r, parts[6], parts[7]);
    parts[6] = -parts[6];
    parts[7] = -parts[7];
    R sum = R(0), comp = R(0);
    for (const R p : parts) {
      const R t = sum + p;
      comp = comp + (abs(sum) >= abs(p) ? (sum - t) + p : (p - t) + sum);
      sum = t;
    }
    return sum + comp;
  }
  // a * a = hi + lo exactly (for |a| below about 1e34; beyond, NaN or
  // infinite parts, as a * a would overflow anyway).
  static void square(R a, R& hi, R& lo) {
    const R c = kSplit * a;
    const R ah = c - (c - a), al = a - ah;
    hi = a * a;
    lo = ((ah * ah - hi) + R(2) * ah * al) + al * al;
  }

  // The nearest hit so far; offer() keeps the smaller t > 0, and on a tie the
  // lower object index.
  struct Nearest {
    R best = R(-1);
    int32_t hit = kNone;
    void offer(R t, int32_t i) {
      if (t > R(0) && (hit == kNone || t < best || (t == best && i < hit))) {
        best = t;
        hit = i;
      }
    }
  };

  // Every ray tests every plane (the hierarchy holds only spheres).
  Nearest planes_hit(const V& o, const V& d, int32_t skip) const {
    Nearest n;
    for (int32_t p = 0; p < bvh_.plane_count(); ++p) {
      const int32_t i = bvh_.plane(p);
      if (i == skip) continue;
      const Object<R>& ob = s_.objects[i];
      n.offer(dot(ob.point - o, ob.normal) / dot(d, ob.normal), i);
    }
    return n;
  }

  V normal_at(const Object<R>& ob, const V& x) const {
    return ob.kind == ShapeKind::kSphere ? normalize(x - ob.point) : ob.normal;
  }

  // `skip`: an object the ray cannot hit (kNone: none).
  V trace(int32_t depth, const V& o, const V& d, int32_t skip = kNone) const {
    if (depth == 0) return s_.background;
    int32_t hit;
    const R t = closest(o, d, hit, skip);
    return shade(depth, o, d, t, hit);
  }

  // trace() for a camera ray whose possible spheres gather() listed; a
  // direction too far from unit length for gather()'s reasoning walks the
  // hierarchy instead.
  V trace_among(int32_t depth, const V& o, const V& d, const typename SphereBvh<M>::Candidate* candidates,
                int32_t count) const {
    if (depth == 0) return s_.background;
    const R dd = dot(d, d);
    if (!SphereBvh<M>::unit_enough(dd)) return trace(depth, o, d);
    Nearest n = planes_hit(o, d, kNone);
    for (int32_t k = 0; k < count; ++k) {
      const auto& sp = candidates[k];
      const V oc = o - sp.c;
      const R doc = dot(d, oc);
      const R delta = SphereBvh<M>::sphere_delta(d, oc.x, oc.y, oc.z, doc, dot(oc, oc), sp.r2);
      if (!(delta >= R(0))) continue;
      const Roots t = roots(o, sp.index, doc, delta);
      n.offer(t.near, sp.index);
      n.offer(t.far, sp.index);
    }
    return shade(depth, o, d, n.best, n.hit);
  }

  V shade(int32_t depth, const V& o, const V& d, R t, int32_t hit) const {
    if (hit == kNone) return s_.background;
    const Object<R>& ob = s_.objects[hit];
    const V x = o + d * t;
    const SurfaceNode<R>& top = s_.surfaces[ob.surface];
    if (top.s.kind == SurfaceKind::kLuminous) return top.color;
    // The normal and the secondary rays' origin once for every light and
    // every part of a mixed surface.
    const V n = normal_at(ob, x);
    const Hit h{x, n, x + n * offset(o, x, t), hit};
    return surface_color(h, ob.surface, depth, d);
  }

  // A hit point, its normal, where shadow and mirror rays start, and the
  // object hit.
  struct Hit {
    V x, n, origin;
    int32_t object;
  };

  // The object that a secondary ray from h in direction dir leaves, which
  // it then cannot hit again (kNone: any may be hit), in float only. A ray
  // from a point of a sphere or plane that points to the normal's side
  // leaves it for good (a sphere's normal points outward, even seen from
  // inside; a plane is crossed once), so the original's offset keeps its
  // own surface out of the way; float's offset need not, for a large
  // sphere far from the origin (the hit point is off the surface by about
  // u |centre|), so float does not ask. Double asks, as the original does.
  static int32_t left_object(const Hit& h, const V& dir) {
    if constexpr (kDouble) {
      return kNone;
    } else {
      return dot(dir, h.n) > R(0) ? h.object : kNone;
    }
  }

  // How far along the normal secondary rays start: the original's 1e-5 in
  // double. In float the hit point is off by a few units of roundoff of
  // the magnitudes that made it (ray origin, t, the point itself), which
  // 1e-5 need not exceed (speckles where a surface meets another, such as
  // two coincident ones), so it is also at least kOffsetUlps of those.
  static R offset(const V& o, const V& x, R t) {
    if constexpr (kDouble) {
      return kEps;
    } else {
      const R scale = max_abs(o) + max_abs(x) + abs(t);
      const R e = kOffsetUlps * kUnit * scale;
      return e > kEps ? e : kEps;  // a NaN scale keeps 1e-5
    }
  }
  static R abs(R v) { return v < R(0) ? -v : v; }
  static R max_abs(const V& v) {
    const R a = abs(v.x), b = abs(v.y), c = abs(v.z);
    const R m = a > b ? a : b;
    return m > c ? m : c;
  }

  V surface_color(const Hit& h, int32_t surface, int32_t depth, const V& d) const {
    const V& n = h.n;
    const SurfaceNode<R>& node = s_.surfaces[surface];
    switch (node.s.kind) {
      case SurfaceKind::kLuminous: return node.color;
      case SurfaceKind::kDiffusive: {
        V sum{};
        for (int32_t i = 0; i < s_.light_count; ++i) sum = sum + shadow(s_.lights[i], h);
        return sum * node.color;
      }
      case SurfaceKind::kReflective: {
        const V dir = normalize(d - n * (R(2) * dot(n, d)));
        return trace(depth - 1, h.origin, dir, left_object(h, dir));
      }
      case SurfaceKind::kMixed: {
        V acc{};
        for (int32_t p = node.s.first_part; p != kNone; p = s_.parts[p].next)
          acc = acc + surface_color(h, s_.parts[p].surface, depth, d) * s_.parts[p].weight;
        return acc;
      }
    }
    return V{};
  }

  // What a light gives the point x with normal n: nothing when an object
  // along the shadow ray blocks it (any, for a directional light; one nearer
  // than the light, for a spherical one).
  //
  // Two shortcuts give the original's bytes: a light whose unblocked share
  // is +-0 (it is behind the surface) adds +-0 either way, and a sum that
  // starts at +0 is unchanged by +-0, so its shadow ray is not traced; and
  // blocking only asks whether some t > 0 (with t*t below the squared light
  // distance) exists, which the first such object answers, because the
  // nearest t would answer the same (t*t rounds monotonically).
  V shadow(const Light<R>& l, const Hit& h) const {
    const V &x = h.x, &n = h.n, &origin = h.origin;
    if (l.kind == LightKind::kDirectional) {
      const R share = max0(dot(l.vector, n));
      if (share == R(0) && finite(l.color)) return V{};
      const V& dir = light_dirs_[&l - s_.lights];
      if (blocked(origin, dir, false, R(0), left_object(h, dir))) return V{};
      return l.color * share;
    }
    const V v = l.vector - x;
    const V dir = normalize(v);
    const R share = max0(dot(dir, n)) / dot(v, v);
    if (share == R(0) && finite(l.color)) return V{};
    const V xs = x - l.vector;
    if (blocked(origin, dir, true, dot(xs, xs), left_object(h, dir))) return V{};
    return l.color * share;
  }

  static bool finite(const V& c) { return c.x - c.x == R(0) && c.y - c.y == R(0) && c.z - c.z == R(0); }

  // Whether some object is hit at t > 0 (and, when `limited`, t*t < limit2),
  // with closest()'s arithmetic.
  bool blocked(const V& o, const V& d, bool limited, R limit2, int32_t skip) const {
    auto blocks = [&](R t) { return t > R(0) && (!limited || t * t < limit2); };
    for (int32_t p = 0; p < bvh_.plane_count(); ++p) {
      if (bvh_.plane(p) == skip) continue;
      const Object<R>& ob = s_.objects[bvh_.plane(p)];
      if (blocks(dot(ob.point - o, ob.normal) / dot(d, ob.normal))) return true;
    }
    return bvh_.for_hits(o, d, [&](int32_t i, R doc, R delta) {
      if (i == skip) return false;
      const Roots t = roots(o, i, doc, delta);
      return blocks(t.near) || blocks(t.far);
    });
  }

  // Each directional light's normalize(vector), which every shadow ray
  // towards it used to compute again: the same operations, the same value.
  bool unit_lights(Arena& arena) {
    light_dirs_ = arena.alloc_zeroed<V>(static_cast<size_t>(s_.light_count > 0 ? s_.light_count : 0) + 1);
    if (light_dirs_ == nullptr) return false;
    for (int32_t i = 0; i < s_.light_count; ++i)
      if (s_.lights[i].kind == LightKind::kDirectional) light_dirs_[i] = normalize(s_.lights[i].vector);
    return true;
  }

  const Scene<R>& s_;
  SphereBvh<M> bvh_;
  V* light_dirs_ = nullptr;
  bool ready_;
};

}  // namespace minrt::jaworski
