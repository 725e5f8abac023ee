// Part of the min-rt tracer (render/sld/tracer.hpp).
// Ray-object solvers: the general one for any start point, and the
// table-driven ones for rays along a precomputed direction.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::quadratic(const Object& m, R v0, R v1, R v2) -> R {
  const R diag = sqr(v0) * m.abc[0] + sqr(v1) * m.abc[1] + sqr(v2) * m.abc[2];
  if (m.rotated == 0) return diag;
  return diag + v1 * v2 * m.rot[0] + v2 * v0 * m.rot[1] + v0 * v1 * m.rot[2];
}

template <MathPolicy M>
inline auto Tracer<M>::bilinear(const Object& m, R v0, R v1, R v2, R w0, R w1, R w2) -> R {
  const R diag = v0 * w0 * m.abc[0] + v1 * w1 * m.abc[1] + v2 * w2 * m.abc[2];
  if (m.rotated == 0) return diag;
  return diag + ((v2 * w1 + v1 * w2) * m.rot[0] + (v0 * w2 + v2 * w0) * m.rot[1] +
                 (v0 * w1 + v1 * w0) * m.rot[2]) *
                    R(0.5);
}

template <MathPolicy M>
inline auto Tracer<M>::quadric_constant(const Object& m, R cc0) -> R {
  return m.form == kFormQuadric ? cc0 - R(1.0) : cc0;
}

template <MathPolicy M>
inline auto Tracer<M>::solve_box_face(const Object& m, const R* dir, R b0, R b1, R b2, int i0, int i1, int i2)
    -> Solved {
  if (dir[i0] == R(0)) return Solved{0, R(0)};
  const R d = fneg_cond(m.inverted != (dir[i0] < R(0)), m.abc[i0]);
  const R d2 = (d - b0) / dir[i0];
  if (fabs(d2 * dir[i1] + b1) < m.abc[i1] && fabs(d2 * dir[i2] + b2) < m.abc[i2]) return Solved{i0 + 1, d2};
  return Solved{0, R(0)};
}

template <MathPolicy M>
inline auto Tracer<M>::solver(const Object& m, const R* dir, const R* org) -> Solved {
  const R b0 = org[0] - m.center[0];
  const R b1 = org[1] - m.center[1];
  const R b2 = org[2] - m.center[2];
  if (m.form == kFormBox) {
    const Solved x = solve_box_face(m, dir, b0, b1, b2, 0, 1, 2);
    if (x.code != 0) return x;
    const Solved y = solve_box_face(m, dir, b1, b2, b0, 1, 2, 0);
    if (y.code != 0) return y;
    return solve_box_face(m, dir, b2, b0, b1, 2, 0, 1);
  }
  if (m.form == kFormPlane) {
    const R d = dot(dir, m.abc);
    if (d > R(0)) return Solved{1, -dot(m.abc, b0, b1, b2) / d};
    return Solved{0, R(0)};
  }
  const R aa = quadratic(m, dir[0], dir[1], dir[2]);
  if (aa == R(0)) return Solved{0, R(0)};
  const R bb = bilinear(m, dir[0], dir[1], dir[2], b0, b1, b2);
  const R cc = quadric_constant(m, quadratic(m, b0, b1, b2));
  const R d = sqr(bb) - aa * cc;
  if (d > R(0)) {
    const R sd = M::sqrt(d);
    const R t1 = m.inverted ? sd : -sd;
    return Solved{1, (t1 - bb) / aa};
  }
  return Solved{0, R(0)};
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::solve_box_fast(const Object& m, const R* v, const R* c, R b0, R b1, R b2) -> Solved {
  const R d0 = (c[0] - b0) * c[1];
  if (fabs(d0 * v[1] + b1) < m.abc[1] && fabs(d0 * v[2] + b2) < m.abc[2]) return Solved{1, d0};
  const R d1 = (c[2] - b1) * c[3];
  if (fabs(d1 * v[0] + b0) < m.abc[0] && fabs(d1 * v[2] + b2) < m.abc[2]) return Solved{2, d1};
  const R d2 = (c[4] - b2) * c[5];
  if (fabs(d2 * v[0] + b0) < m.abc[0] && fabs(d2 * v[1] + b1) < m.abc[1]) return Solved{3, d2};
  return Solved{0, R(0)};
}

template <MathPolicy M>
template <bool kAheadOnly>
MINRT_INLINE auto Tracer<M>::solve_second_fast(const Object& m, const R* c, R b0, R b1, R b2, R cc) -> Solved {
  const R aa = c[0];
  const R neg_bb = c[1] * b0 + c[2] * b1 + c[3] * b2;
  const R d = sqr(neg_bb) - aa * cc;
  if (d > R(0)) {
    if (kAheadOnly && neg_bb <= c[5]) return Solved{1, R(0)};
    return Solved{1, m.inverted ? (neg_bb + M::sqrt(d)) * c[4] : (neg_bb - M::sqrt(d)) * c[4]};
  }
  return Solved{0, R(0)};
}

template <MathPolicy M>
inline auto Tracer<M>::consts_of(const DirVec& dv, const Object& m) -> const R* {
  return reinterpret_cast<const R*>(reinterpret_cast<const char*>(dv.c) + m.consts_offset);
}

template <MathPolicy M>
inline auto Tracer<M>::solver_fast(const Object& m, const DirVec& dv, const R* org) -> Solved {
  const R b0 = org[0] - m.center[0];
  const R b1 = org[1] - m.center[1];
  const R b2 = org[2] - m.center[2];
  const R* c = consts_of(dv, m);
  if (m.form == kFormBox) return solve_box_fast(m, dv.v, c, b0, b1, b2);
  if (m.form == kFormPlane) {
    if (c[0] < R(0)) return Solved{1, c[1] * b0 + c[2] * b1 + c[3] * b2};
    return Solved{0, R(0)};
  }
  return solve_second_fast(m, c, b0, b1, b2, quadric_constant(m, quadratic(m, b0, b1, b2)));
}

template <MathPolicy M>
template <bool kAheadOnly>
MINRT_INLINE auto Tracer<M>::solver_fast2(const Object& m, const DirVec& dv) -> Solved {
  const R* s = m.start;
  const R* c = consts_of(dv, m);
  if (m.form == kFormBox) return solve_box_fast(m, dv.v, c, s[0], s[1], s[2]);
  if (m.form == kFormPlane) {
    if (c[0] < R(0)) return Solved{1, c[0] * s[3]};
    return Solved{0, R(0)};
  }
  return solve_second_fast<kAheadOnly>(m, c, s[0], s[1], s[2], s[3]);
}

}  // namespace minrt
