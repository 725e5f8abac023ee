// Jaworski's tracer, operation for operation (SPEC.md 3.3): the original
// uses only + - x / and sqrt in double precision, so with the same order of
// operations a double build gives its bytes exactly. Hence its own small
// tracer rather than the general one: no normal flipping, shadow and mirror
// rays start 1e-5 along the normal, the first object wins ties, a depth of
// 0 or a miss gives the background, mixtures are summed in file order, and
// bytes are round-half-to-even of 255 x the clamped value.
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
  static constexpr R kEps = static_cast<R>(1e-5);
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
  R closest(const V& o, const V& d, int32_t& hit) const {
    Nearest n = planes_hit(o, d);
    bvh_.for_hits(o, d, [&](int32_t i, R doc, R delta) {
      const R root = M::sqrt(delta);
      n.offer(-doc - root, i);
      n.offer(-doc + root, i);
      return false;
    });
    hit = n.hit;
    return n.best;
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
  Nearest planes_hit(const V& o, const V& d) const {
    Nearest n;
    for (int32_t p = 0; p < bvh_.plane_count(); ++p) {
      const int32_t i = bvh_.plane(p);
      const Object<R>& ob = s_.objects[i];
      n.offer(dot(ob.point - o, ob.normal) / dot(d, ob.normal), i);
    }
    return n;
  }

  V normal_at(const Object<R>& ob, const V& x) const {
    return ob.kind == ShapeKind::kSphere ? normalize(x - ob.point) : ob.normal;
  }

  V trace(int32_t depth, const V& o, const V& d) const {
    if (depth == 0) return s_.background;
    int32_t hit;
    const R t = closest(o, d, hit);
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
    Nearest n = planes_hit(o, d);
    for (int32_t k = 0; k < count; ++k) {
      const auto& sp = candidates[k];
      const V oc = o - sp.c;
      const R doc = dot(d, oc);
      const R delta = doc * doc - dot(oc, oc) + sp.r2;
      if (!(delta >= R(0))) continue;
      const R root = M::sqrt(delta);
      n.offer(-doc - root, sp.index);
      n.offer(-doc + root, sp.index);
    }
    return shade(depth, o, d, n.best, n.hit);
  }

  V shade(int32_t depth, const V& o, const V& d, R t, int32_t hit) const {
    if (hit == kNone) return s_.background;
    const Object<R>& ob = s_.objects[hit];
    const V x = o + d * t;
    const SurfaceNode<R>& top = s_.surfaces[ob.surface];
    if (top.s.kind == SurfaceKind::kLuminous) return top.color;
    // The normal once for every part of a mixed surface (each part used to
    // compute the same value again).
    return surface_color(normal_at(ob, x), x, ob.surface, depth, d);
  }

  V surface_color(const V& n, const V& x, int32_t surface, int32_t depth, const V& d) const {
    const SurfaceNode<R>& node = s_.surfaces[surface];
    switch (node.s.kind) {
      case SurfaceKind::kLuminous: return node.color;
      case SurfaceKind::kDiffusive: {
        V sum{};
        for (int32_t i = 0; i < s_.light_count; ++i) sum = sum + shadow(s_.lights[i], x, n);
        return sum * node.color;
      }
      case SurfaceKind::kReflective: {
        const V origin = x + n * kEps;
        const V dir = normalize(d - n * (R(2) * dot(n, d)));
        return trace(depth - 1, origin, dir);
      }
      case SurfaceKind::kMixed: {
        V acc{};
        for (int32_t p = node.s.first_part; p != kNone; p = s_.parts[p].next)
          acc = acc + surface_color(n, x, s_.parts[p].surface, depth, d) * s_.parts[p].weight;
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
  V shadow(const Light<R>& l, const V& x, const V& n) const {
    const V origin = x + n * kEps;
    if (l.kind == LightKind::kDirectional) {
      const R share = max0(dot(l.vector, n));
      if (share == R(0) && finite(l.color)) return V{};
      if (blocked(origin, light_dirs_[&l - s_.lights], false, R(0))) return V{};
      return l.color * share;
    }
    const V v = l.vector - x;
    const V dir = normalize(v);
    const R share = max0(dot(dir, n)) / dot(v, v);
    if (share == R(0) && finite(l.color)) return V{};
    const V xs = x - l.vector;
    if (blocked(origin, dir, true, dot(xs, xs))) return V{};
    return l.color * share;
  }

  static bool finite(const V& c) { return c.x - c.x == R(0) && c.y - c.y == R(0) && c.z - c.z == R(0); }

  // Whether some object is hit at t > 0 (and, when `limited`, t*t < limit2),
  // with closest()'s arithmetic.
  bool blocked(const V& o, const V& d, bool limited, R limit2) const {
    auto blocks = [&](R t) { return t > R(0) && (!limited || t * t < limit2); };
    for (int32_t p = 0; p < bvh_.plane_count(); ++p) {
      const Object<R>& ob = s_.objects[bvh_.plane(p)];
      if (blocks(dot(ob.point - o, ob.normal) / dot(d, ob.normal))) return true;
    }
    return bvh_.for_hits(o, d, [&](int32_t, R doc, R delta) {
      const R root = M::sqrt(delta);
      return blocks(-doc - root) || blocks(-doc + root);
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
