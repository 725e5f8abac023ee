// Quadric solids of the general model: a general quadric in a local frame
// (world -> local affine map), optionally clipped to a slab on local z with
// flat caps, or a box; per-face materials; the sign (a complement). EASTRAY
// primitives of kinds 0-8 and 10-16 are these (formats/eastray); the
// intersector is render/general/quadric_shape.hpp, the bounds
// render/general/csg_bounds.hpp.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"

namespace minrt::model {

// An affine map x -> m * x + t (3x3 row-major and a translation).
template <class R>
struct Affine {
  R m[9] = {R(1), R(0), R(0), R(0), R(1), R(0), R(0), R(0), R(1)};
  Vec3<R> t{};

  Vec3<R> point(const Vec3<R>& p) const {
    return {m[0] * p.x + m[1] * p.y + m[2] * p.z + t.x, m[3] * p.x + m[4] * p.y + m[5] * p.z + t.y,
            m[6] * p.x + m[7] * p.y + m[8] * p.z + t.z};
  }
  Vec3<R> vector(const Vec3<R>& v) const {
    return {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[3] * v.x + m[4] * v.y + m[5] * v.z,
            m[6] * v.x + m[7] * v.y + m[8] * v.z};
  }
  // The transpose of the linear part times v (normals through an inverse).
  Vec3<R> transposed(const Vec3<R>& v) const {
    return {m[0] * v.x + m[3] * v.y + m[6] * v.z, m[1] * v.x + m[4] * v.y + m[7] * v.z,
            m[2] * v.x + m[5] * v.y + m[8] * v.z};
  }
  // this * o (o applied first).
  Affine then_after(const Affine& o) const {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i * 3 + j] = m[i * 3] * o.m[j] + m[i * 3 + 1] * o.m[3 + j] + m[i * 3 + 2] * o.m[6 + j];
    r.t = vector(o.t) + t;
    return r;
  }
  R det() const {
    return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
           m[2] * (m[3] * m[7] - m[4] * m[6]);
  }
  // False when singular.
  bool inverse(Affine& out) const {
    const R d = det();
    if (d == R(0)) return false;
    const R inv = R(1) / d;
    out.m[0] = (m[4] * m[8] - m[5] * m[7]) * inv;
    out.m[1] = (m[2] * m[7] - m[1] * m[8]) * inv;
    out.m[2] = (m[1] * m[5] - m[2] * m[4]) * inv;
    out.m[3] = (m[5] * m[6] - m[3] * m[8]) * inv;
    out.m[4] = (m[0] * m[8] - m[2] * m[6]) * inv;
    out.m[5] = (m[2] * m[3] - m[0] * m[5]) * inv;
    out.m[6] = (m[3] * m[7] - m[4] * m[6]) * inv;
    out.m[7] = (m[1] * m[6] - m[0] * m[7]) * inv;
    out.m[8] = (m[0] * m[4] - m[1] * m[3]) * inv;
    out.t = -out.vector(t);
    return true;
  }
};

// The two shapes (EASTRAY's kind numbers map onto these).
enum class QuadricShape : uint8_t { kQuadric, kBox };

// Faces that may carry their own colour.
enum Face : uint8_t { kFaceSide = 0, kFaceTop = 1, kFaceBottom = 2, kFaceBox = 3 /* +x -x +y -y +z -z: 3..8 */ };
inline constexpr int kFaceCount = 9;

template <class R>
struct Quadric {
  QuadricShape shape;
  uint8_t kind;       // the format's kind number (messages, docs)
  bool no_shadow;
  bool inverted;      // sign -1
  bool clip_low, clip_high;  // the slab on local z
  Affine<R> to_local;        // world -> local
  // Local quadric a0 x2 + a1 y2 + a2 z2 + a3 xy + a4 yz + a5 zx + a6 x + a7 y
  // + a8 z + a9 (< 0 inside); box: half extents in q[0..2].
  R q[10];
  R z_low, z_high;
  int32_t material[kFaceCount];
};

}  // namespace minrt::model
