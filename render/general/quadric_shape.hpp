// One intersector for the general model's quadric solids
// (formats/model/quadric.hpp; every EASTRAY primitive but the polygon,
// kinds 0-8 and 10-16): a general quadric in its local frame, optionally clipped to a
// slab on local z with flat caps, and the box as three slabs. The ray is
// taken into the local frame by the world-to-local affine map (direction
// not renormalised), so the ray parameter t is the world one.
#pragma once

#include "core/math/vec3.hpp"
#include "formats/model/quadric.hpp"

namespace minrt::general {

template <class R>
struct Crossing {
  R t;
  Vec3<R> normal;  // local outward normal of the solid (before the sign)
  int face;
};

template <class R>
R quadric_value(const R* q, const Vec3<R>& p) {
  return q[0] * p.x * p.x + q[1] * p.y * p.y + q[2] * p.z * p.z + q[3] * p.x * p.y + q[4] * p.y * p.z +
         q[5] * p.z * p.x + q[6] * p.x + q[7] * p.y + q[8] * p.z + q[9];
}

template <class R>
Vec3<R> quadric_gradient(const R* q, const Vec3<R>& p) {
  return {R(2) * q[0] * p.x + q[3] * p.y + q[5] * p.z + q[6], R(2) * q[1] * p.y + q[3] * p.x + q[4] * p.z + q[7],
          R(2) * q[2] * p.z + q[4] * p.y + q[5] * p.x + q[8]};
}

// Inside the solid (before the sign), at a local point.
template <class R>
bool local_inside(const model::Quadric<R>& s, const Vec3<R>& p) {
  if (s.shape == model::QuadricShape::kBox) {
    const R ax = p.x < R(0) ? -p.x : p.x, ay = p.y < R(0) ? -p.y : p.y, az = p.z < R(0) ? -p.z : p.z;
    return ax <= s.q[0] && ay <= s.q[1] && az <= s.q[2];
  }
  if (s.clip_low && p.z < s.z_low) return false;
  if (s.clip_high && p.z > s.z_high) return false;
  return quadric_value(s.q, p) < R(0);
}

template <class R>
bool inside(const model::Quadric<R>& s, const Vec3<R>& world) {
  return local_inside(s, s.to_local.point(world)) != s.inverted;
}

// The surface crossings with t in (t_min, t_max), ascending; returns how
// many (at most 4: two on the quadric, two caps; two for the box).
template <class M>
int crossings(const model::Quadric<typename M::real>& s, const Vec3<typename M::real>& origin,
              const Vec3<typename M::real>& dir, typename M::real t_min, typename M::real t_max,
              Crossing<typename M::real>* out) {
  using R = typename M::real;
  using V = Vec3<R>;
  const V o = s.to_local.point(origin);
  const V d = s.to_local.vector(dir);
  int n = 0;
  auto add = [&](R t, const V& normal, int face) {
    if (!(t > t_min && t < t_max)) return;
    int i = n++;
    while (i > 0 && out[i - 1].t > t) {
      out[i] = out[i - 1];
      --i;
    }
    out[i] = Crossing<R>{t, normal, face};
  };
  if (s.shape == model::QuadricShape::kBox) {
    R t0 = -R(1e30), t1 = R(1e30);
    int f0 = -1, f1 = -1;
    const R oo[3] = {o.x, o.y, o.z}, dd[3] = {d.x, d.y, d.z};
    for (int a = 0; a < 3; ++a) {
      const R h = s.q[a];
      if (dd[a] == R(0)) {
        if (oo[a] < -h || oo[a] > h) return 0;
        continue;
      }
      R ta = (-h - oo[a]) / dd[a], tb = (h - oo[a]) / dd[a];
      int fa = model::kFaceBox + 2 * a + 1, fb = model::kFaceBox + 2 * a;  // -axis, +axis faces
      if (ta > tb) {
        const R x = ta;
        ta = tb, tb = x;
        const int y = fa;
        fa = fb, fb = y;
      }
      if (ta > t0) t0 = ta, f0 = fa;
      if (tb < t1) t1 = tb, f1 = fb;
    }
    if (t0 > t1 || f0 < 0 || f1 < 0) return 0;
    auto face_normal = [](int f) {
      const int a = (f - model::kFaceBox) / 2;
      const R sgn = ((f - model::kFaceBox) & 1) != 0 ? R(-1) : R(1);
      return a == 0 ? V{sgn, R(0), R(0)} : a == 1 ? V{R(0), sgn, R(0)} : V{R(0), R(0), sgn};
    };
    add(t0, face_normal(f0), f0);
    add(t1, face_normal(f1), f1);
    return n;
  }
  const R* q = s.q;
  const R a = q[0] * d.x * d.x + q[1] * d.y * d.y + q[2] * d.z * d.z + q[3] * d.x * d.y + q[4] * d.y * d.z +
              q[5] * d.z * d.x;
  const R b = R(2) * (q[0] * o.x * d.x + q[1] * o.y * d.y + q[2] * o.z * d.z) + q[3] * (o.x * d.y + o.y * d.x) +
              q[4] * (o.y * d.z + o.z * d.y) + q[5] * (o.z * d.x + o.x * d.z) + q[6] * d.x + q[7] * d.y + q[8] * d.z;
  const R c = quadric_value(q, o);
  auto on_surface = [&](R t) {
    const V p = o + d * t;
    if (s.clip_low && p.z < s.z_low) return;
    if (s.clip_high && p.z > s.z_high) return;
    add(t, quadric_gradient(q, p), model::kFaceSide);
  };
  if (a == R(0)) {
    if (b != R(0)) on_surface(-c / b);
  } else {
    // A quadric with only squared terms (every centred primitive in its
    // frame) has b^2 - 4ac = -4 (sum over i<j of qi qj (oi dj - oj di)^2
    // + q9 a): b^2 and 4ac cancel their largest terms, which for a thin
    // solid (qi ratios of 1e8 in float, 1e16 in double) leaves only rounding
    // and reports crossings far outside it.
    const bool squares_only =
        q[3] == R(0) && q[4] == R(0) && q[5] == R(0) && q[6] == R(0) && q[7] == R(0) && q[8] == R(0);
    R disc;
    if (squares_only) {
      const R xy = o.x * d.y - o.y * d.x, yz = o.y * d.z - o.z * d.y, zx = o.z * d.x - o.x * d.z;
      disc = R(-4) * (q[0] * q[1] * xy * xy + q[1] * q[2] * yz * yz + q[2] * q[0] * zx * zx + q[9] * a);
    } else {
      disc = b * b - R(4) * a * c;
    }
    if (disc >= R(0)) {
      const R root = M::sqrt(disc);
      const R h = b < R(0) ? R(-0.5) * (b - root) : R(-0.5) * (b + root);
      if (h != R(0)) {
        on_surface(h / a);
        on_surface(c / h);
      } else {
        on_surface(R(0));
      }
    }
  }
  // Caps: where the slab's planes cut the quadric's inside.
  if (d.z != R(0)) {
    if (s.clip_low) {
      const R t = (s.z_low - o.z) / d.z;
      const V p = o + d * t;
      if (quadric_value(q, p) < R(0)) add(t, V{R(0), R(0), R(-1)}, model::kFaceBottom);
    }
    if (s.clip_high) {
      const R t = (s.z_high - o.z) / d.z;
      const V p = o + d * t;
      if (quadric_value(q, p) < R(0)) add(t, V{R(0), R(0), R(1)}, model::kFaceTop);
    }
  }
  return n;
}

// Whether the ray (t in (t_min, t_max)) meets the solid at all: it starts
// inside or crosses its surface. For RANGE bounds.
template <class M>
bool meets(const model::Quadric<typename M::real>& s, const Vec3<typename M::real>& origin,
           const Vec3<typename M::real>& dir, typename M::real t_min, typename M::real t_max) {
  using R = typename M::real;
  if (local_inside(s, s.to_local.point(origin + dir * t_min))) return true;
  Crossing<R> c[4];
  return crossings<M>(s, origin, dir, t_min, t_max, c) > 0;
}

}  // namespace minrt::general

namespace minrt::eastray {
using general::crossings;
using general::Crossing;
using general::inside;
using general::local_inside;
using general::meets;
}  // namespace minrt::eastray
