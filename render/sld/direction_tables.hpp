// Part of the min-rt tracer (render/sld/tracer.hpp).
// Direction tables and culling: per-direction solver constants, the
// per-start tables and forward-culling masks, and the 300 diffuse
// directions themselves.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::setup_dirvec_constants(DirVec& dv) -> void {
  const R* v = dv.v;
  dv.code = direction_code(v);
  dv.octant = v[0] == R(0) || v[1] == R(0) || v[2] == R(0)
                  ? -1
                  : int32_t{v[0] < R(0)} | int32_t{v[1] < R(0)} << 1 | int32_t{v[2] < R(0)} << 2;
  for (int i = n_objects_ - 1; i >= 0; --i) {
    const Object& m = objects_[i];
    R* c = const_cast<R*>(consts_of(dv, m));
    if (m.form == kFormBox) {
      for (int k = 0; k < 3; ++k) {
        if (v[k] == R(0)) {
          c[2 * k] = R(__builtin_nan(""));
          c[2 * k + 1] = R(0);
        } else {
          c[2 * k] = fneg_cond(m.inverted != (v[k] < R(0)), m.abc[k]);
          c[2 * k + 1] = R(1.0) / v[k];
        }
      }
    } else if (m.form == kFormPlane) {
      const R d = v[0] * m.abc[0] + v[1] * m.abc[1] + v[2] * m.abc[2];
      if (d > R(0)) {
        c[0] = R(-1.0) / d;
        c[1] = -(m.abc[0] / d);
        c[2] = -(m.abc[1] / d);
        c[3] = -(m.abc[2] / d);
      } else {
        c[0] = R(0);
      }
    } else {
      const R aa = quadratic(m, v[0], v[1], v[2]);
      const R c1 = -(v[0] * m.abc[0]);
      const R c2 = -(v[1] * m.abc[1]);
      const R c3 = -(v[2] * m.abc[2]);
      c[0] = aa;
      if (m.rotated != 0) {
        c[1] = c1 - (v[2] * m.rot[1] + v[1] * m.rot[2]) * R(0.5);
        c[2] = c2 - (v[2] * m.rot[0] + v[0] * m.rot[2]) * R(0.5);
        c[3] = c3 - (v[1] * m.rot[0] + v[0] * m.rot[1]) * R(0.5);
      } else {
        c[1] = c1;
        c[2] = c2;
        c[3] = c3;
      }
      if (aa != R(0)) c[4] = R(1.0) / aa;
      else c[1] = R(__builtin_nan(""));
      c[5] = aa != R(0) && !m.inverted && c[4] > R(0) ? R(0) : R(__builtin_nan(""));
    }
  }
}

template <MathPolicy M>
template <bool kCull>
inline auto Tracer<M>::setup_startp(const R* p) -> void {
  copy3(startp_fast_, p);
  if (!kCull) culled_start_valid_ = false;
  for (int i = n_objects_ - 1; i >= 0; --i) {
    Object& m = objects_[i];
    R* s = m.start;
    s[0] = p[0] - m.center[0];
    s[1] = p[1] - m.center[1];
    s[2] = p[2] - m.center[2];
    if (kCull) {
      uint32_t mask = 0;
      if (m.slab_bounded)
        for (int k = 0; k < 3; ++k)
          mask |= uint32_t{s[k] >= m.slab[k]} << (2 * k) | uint32_t{s[k] <= -m.slab[k]} << (2 * k + 1);
      m.fwd = mask;
      // Face k of a box is at d = fl(c - s_k) / v_k with c = -abc_k for
      // v_k > 0 (abc_k inverted) and +abc_k for v_k < 0 (-abc_k inverted):
      // once s_k is past it, fl(c - s_k) has the other sign (or is 0) and
      // d <= 0, or NaN, which fails the face test. A ray whose code avoids
      // every bit here gets no positive distance from the box.
      if (m.form == kFormBox) {
        uint32_t ahead = 0;
        for (int k = 0; k < 3; ++k) {
          const R pos = m.inverted ? m.abc[k] : -m.abc[k];
          ahead |= uint32_t{!(s[k] >= pos)} << (2 * k) | uint32_t{!(s[k] <= -pos)} << (2 * k + 1);
        }
        m.ahead = ahead;
      }
    }
    if (m.form == kFormPlane) {
      s[3] = dot(m.abc, s[0], s[1], s[2]);
    } else if (m.form > kFormPlane) {
      s[3] = quadric_constant(m, quadratic(m, s[0], s[1], s[2]));
    }
    // original: forms below 1 keep a stale constant term here.
  }
}

template <MathPolicy M>
inline auto Tracer<M>::setup_forward_culling() -> void {
  for (int r = 0; r < n_or_rows_; ++r) {
    OrRow& row = or_rows_[r];
    uint32_t all = ~0u;
    for (int k = 0; row.nets[k] != nullptr; ++k) {
      uint32_t mask = 0;
      for (ObjectList e = row.nets[k]; *e != nullptr; ++e) mask |= (*e)->fwd;
      row.fwd[k] = mask;
      all &= mask;
    }
    row.fwd_all = all;
  }
  live_built_ = 0;
}

// A network whose only solved member would be a box behind the start is
// dropped (that member records nothing), and a row left without networks
// with its range test, whose result nothing would read.
template <MathPolicy M>
inline auto Tracer<M>::build_octant(int o) -> void {
  const uint32_t code = ((o & 1) != 0 ? 2u : 1u) | ((o & 2) != 0 ? 8u : 4u) | ((o & 4) != 0 ? 32u : 16u);
  LiveRow* lr = live_rows_ + o * (n_or_rows_ + 1);
  LiveNet* ln = live_nets_ + o * live_nets_stride_;
  for (int r = 0; r < n_or_rows_; ++r) {
    const OrRow& row = or_rows_[r];
    if ((row.fwd_all & code) != 0) continue;
    LiveNet* first = ln;
    for (int k = 0; row.nets[k] != nullptr; ++k) {
      if ((row.fwd[k] & code) != 0) continue;
      int solved = row.lengths[k];
      if (solved > 0 && (row.nets[k][solved - 1]->ahead & code) == 0) --solved;
      if (solved > 0) *ln++ = LiveNet{row.nets[k], solved};
    }
    if (ln == first) continue;
    *ln++ = LiveNet{nullptr, 0};
    *lr++ = LiveRow{row.range, first};
  }
  *lr = LiveRow{nullptr, nullptr};
  live_built_ |= 1u << o;
}

template <MathPolicy M>
inline auto Tracer<M>::direction_code(const R* v) -> uint32_t {
  uint32_t c = 0;
  for (int k = 0; k < 3; ++k) {
    if (v[k] >= R(0)) c |= 1u << (2 * k);
    if (v[k] <= R(0)) c |= 2u << (2 * k);
  }
  return c;
}

template <MathPolicy M>
inline auto Tracer<M>::setup_slab(Object& o) -> void {
  o.slab_bounded = false;
  if (o.inverted) return;
  if (o.form == kFormBox) {
    copy3(o.slab, o.abc);
    o.slab_bounded = true;
    return;
  }
  if (o.form != kFormQuadric || o.rotated != 0) return;
  for (int k = 0; k < 3; ++k) {
    const R a = o.abc[k];
    if (!(a > R(0)) || !finite(a)) return;
    R h = R(1.001) / M::sqrt(a);
    for (int tries = 0; !(sqr(h) * a - R(1.0) > R(0)); ++tries) {
      if (tries == 8 || !finite(h)) return;
      h = h * R(1.01);
    }
    o.slab[k] = h;
  }
  o.slab_bounded = true;
}

template <MathPolicy M>
inline auto Tracer<M>::adjust_position(R h, R ratio) -> R {
  const R l = M::sqrt(h * h + R(0.1));
  const R tan_h = R(1.0) / l;
  const R theta_h = M::atan(tan_h);
  const R a = theta_h * ratio;
  const R tan_m = M::sin(a) / M::cos(a);
  return tan_m * l;
}

template <MathPolicy M>
inline auto Tracer<M>::calc_dirvec(R rx, R ry, int group_id, int index) -> void {
  R x = R(0.0), y = R(0.0);
  for (int i = 0; i < 5; ++i) {
    x = adjust_position(y, rx);
    y = adjust_position(x, ry);
  }
  const R l = M::sqrt(sqr(x) + sqr(y) + R(1.0));
  const R vx = x / l, vy = y / l, vz = R(1.0) / l;
  DirVec* g = dirvecs_[group_id];
  set3(g[index].v, vx, vy, vz);
  set3(g[index + 40].v, vx, vz, -vy);
  set3(g[index + 80].v, vz, -vx, -vy);
  set3(g[index + 1].v, -vx, -vy, -vz);
  set3(g[index + 41].v, -vx, -vz, vy);
  set3(g[index + 81].v, -vz, vx, vy);
}

template <MathPolicy M>
inline auto Tracer<M>::set3(R* v, R a, R b, R c) -> void {
  v[0] = a;
  v[1] = b;
  v[2] = c;
}

template <MathPolicy M>
inline auto Tracer<M>::init_dirvecs() -> void {
  int group_id = 0, index = 0;
  for (int row = 9; row >= 0; --row) {
    const R ry = M::from_int(row) * R(0.2) - R(0.9);
    int g = group_id;
    for (int col = 4; col >= 0; --col) {
      calc_dirvec(M::from_int(col) * R(0.2) - R(0.9), ry, g, index);
      calc_dirvec(M::from_int(col) * R(0.2) + R(0.1), ry, g, index + 2);
      g = add_mod5(g, 1);
    }
    group_id = add_mod5(group_id, 2);
    index += 4;
  }
  for (int g = kDirvecGroups - 1; g >= 0; --g)
    for (int i = kDirvecsPerGroup - 1; i >= 0; --i) setup_dirvec_constants(dirvecs_[g][i]);
}

}  // namespace minrt
