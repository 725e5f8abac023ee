// Part of the min-rt tracer (render/sld/tracer.hpp).
// AND/OR networks: inside/outside tests, shadows (with their per-axis
// culling limits) and the nearest intersection.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::is_outside(const Object& m, R q0, R q1, R q2) -> bool {
  const R p0 = q0 - m.center[0];
  const R p1 = q1 - m.center[1];
  const R p2 = q2 - m.center[2];
  if (m.form == kFormBox) {
    const bool inside = fabs(p0) < m.abc[0] && fabs(p1) < m.abc[1] && fabs(p2) < m.abc[2];
    return inside ? m.inverted : !m.inverted;
  }
  if (m.form == kFormPlane) return m.inverted == (dot(m.abc, p0, p1, p2) < R(0));
  return m.inverted == (quadric_constant(m, quadratic(m, p0, p1, p2)) < R(0));
}

template <MathPolicy M>
inline auto Tracer<M>::build_networks(const Scene<R>& scene) -> void {
  for (int n = 0; n < scene.and_count; ++n) {
    int k = 0;
    for (; scene.and_nets[n][k] != -1; ++k) net_objects_[n][k] = &objects_[scene.and_nets[n][k]];
    net_objects_[n][k] = nullptr;
  }
  n_or_rows_ = scene.or_count;
  for (int r = 0; r < scene.or_count; ++r) {
    const int16_t* in = scene.or_nets[r];
    OrRow& row = or_rows_[r];
    row.range = in[0] == limits::kNoRangePrimitive ? nullptr : &objects_[in[0]];
    int k = 1;
    for (; in[k] != -1; ++k) {
      row.nets[k - 1] = net_objects_[in[k]];
      int n = 0;
      while (row.nets[k - 1][n] != nullptr) ++n;
      row.lengths[k - 1] = n;
    }
    row.nets[k - 1] = nullptr;
  }
}

template <MathPolicy M>
inline auto Tracer<M>::all_inside(ObjectList and_net, R q0, R q1, R q2) -> bool {
  for (; *and_net != nullptr; ++and_net)
    if (is_outside(**and_net, q0, q1, q2)) return false;
  return true;
}

template <MathPolicy M>
inline auto Tracer<M>::shadow_and_group(ObjectList and_net) -> bool {
  for (ObjectList e = and_net; *e != nullptr; ++e) {
    const Object& obj = **e;
    const Solved s = solver_fast(obj, light_dirvec_, intersection_point_);
    if (met_before(s, R(-0.2))) {
      const R t = s.dist + R(0.01);
      const R q0 = light_[0] * t + intersection_point_[0];
      const R q1 = light_[1] * t + intersection_point_[1];
      const R q2 = light_[2] * t + intersection_point_[2];
      if (all_inside(and_net, q0, q1, q2)) return true;
    } else if (!obj.inverted) {
      // No hit on an object whose inside counts: the AND set lies within
      // it, so nothing else of the set can be hit either.
      return false;
    }
  }
  return false;
}

template <MathPolicy M>
inline auto Tracer<M>::in_shadow() -> bool {
  // The start with each axis signed so that moving towards the light never
  // decreases it (see setup_shadow_culling).
  const R* p = intersection_point_;
  const R x0 = toward_light_flip_[0] ? -p[0] : p[0];
  const R x1 = toward_light_flip_[1] ? -p[1] : p[1];
  const R x2 = toward_light_flip_[2] ? -p[2] : p[2];
  const ShadowRow* const rows_end = shadow_rows_ + n_shadow_rows_;
  for (const ShadowRow* row = shadow_rows_; row != rows_end; ++row) {
    if (row->all.culls(x0, x1, x2)) continue;
    if (row->range != nullptr &&
        !met_before(solver_fast(*row->range, light_dirvec_, intersection_point_), R(-0.1)))
      continue;
    for (const ShadowNet* n = row->nets; n != row->nets_end; ++n)
      if (!n->lim.culls(x0, x1, x2) && shadow_and_group(n->net)) return true;
  }
  return false;
}

template <MathPolicy M>
inline auto Tracer<M>::setup_shadow_culling() -> void {
  const R nan = R(__builtin_nan(""));
  for (int k = 0; k < 3; ++k) toward_light_flip_[k] = light_[k] > R(0);
  // A shadow point is fl(fl(light_k t) + p_k) with t <= fl(-0.2 + 0.01), so
  // along a flipped axis it lies at least at fl(reach_k + x_k).
  const R t_max = R(-0.2) + R(0.01);
  R reach[3];
  for (int k = 0; k < 3; ++k) {
    const R r = light_[k] * t_max;
    reach[k] = toward_light_flip_[k] ? -r : r;
    if (!(reach[k] >= R(0)) || !finite(reach[k])) reach[k] = R(0);
  }
  ShadowNet* out = shadow_nets_;
  n_shadow_rows_ = 0;
  for (int r = 0; r < n_or_rows_; ++r) {
    const OrRow& row = or_rows_[r];
    // A row without networks shadows nothing at all.
    if (row.nets[0] == nullptr) continue;
    ShadowRow& srow = shadow_rows_[n_shadow_rows_++];
    // The highest limit of the row's networks per axis, NaN when one of
    // them has none.
    const R inf = R(__builtin_inf());
    ShadowLimits all{{-inf, -inf, -inf}};
    srow.range = row.range;
    srow.nets = out;
    for (int n = 0; row.nets[n] != nullptr; ++n) {
      ShadowLimits lim{{nan, nan, nan}};
      for (ObjectList e = row.nets[n]; *e != nullptr; ++e) {
        const Object& m = **e;
        if (!m.slab_bounded) continue;
        for (int k = 0; k < 3; ++k) {
          const R x = reached_limit(shadow_limit(m.center[k], m.slab[k], toward_light_flip_[k]), reach[k]);
          if (!(lim.limit[k] <= x)) lim.limit[k] = x;  // the lowest, NaN replaced
        }
      }
      if (row.nets[n][0]->form == kFormPlane && row.nets[n][1] == nullptr) plane_shadow_limit(*row.nets[n][0], lim);
      for (int k = 0; k < 3; ++k)
        if (all.limit[k] < lim.limit[k] || lim.limit[k] != lim.limit[k]) all.limit[k] = lim.limit[k];
      *out++ = ShadowNet{lim, row.nets[n]};
    }
    srow.nets_end = out;
    srow.all = all;
  }
}

template <MathPolicy M>
inline auto Tracer<M>::plane_shadow_limit(const Object& m, ShadowLimits& lim) -> void {
  const R* c = consts_of(light_dirvec_, m);
  if (!(c[0] < R(0))) {
    // solver_fast never meets the plane along the light: no shadow at all.
    lim.limit[0] = -R(__builtin_inf());
    return;
  }
  int axis = -1;
  for (int k = 0; k < 3; ++k) {
    if (m.abc[k] == R(0)) continue;
    if (axis >= 0) return;  // not axis-aligned
    axis = k;
  }
  if (axis < 0) return;
  // The other terms of c[1] b0 + c[2] b1 + c[3] b2 are signed zeros (or NaN,
  // which casts no shadow either), so the distance is fl(ck fl(p_k - center_k)),
  // monotonic in p_k: along the flipped axis it must not decrease.
  const R ck = c[1 + axis];
  const bool flipped = toward_light_flip_[axis];
  if (!(flipped ? ck < R(0) : ck > R(0))) return;
  const R center = m.center[axis];
  const R edge = center + R(-0.2) / ck;
  R x = flipped ? -edge : edge;
  for (int tries = 0; tries < 64; ++tries) {
    const R dist = ck * ((flipped ? -x : x) - center);
    if (!(dist < R(-0.2))) {
      if (!(lim.limit[axis] <= x)) lim.limit[axis] = x;
      return;
    }
    x = x + (fabs(x) + fabs(center) + R(1)) * R(1.0e-9);
  }
}

template <MathPolicy M>
inline auto Tracer<M>::reached_limit(R limit, R reach) -> R {
  if (reach == R(0) || !finite(limit)) return limit;
  R x = limit - reach;
  for (int tries = 0; tries < 64; ++tries) {
    if (reach + x >= limit) return x;
    x = x + (fabs(x) + fabs(limit) + reach) * R(1.0e-6);
  }
  return limit;
}

template <MathPolicy M>
inline auto Tracer<M>::shadow_limit(R center, R slab, bool flipped) -> R {
  const R c = flipped ? -center : center;
  R x = c + slab;
  for (int tries = 0; tries < 64; ++tries) {
    const R diff = flipped ? (-x) - center : x - center;
    if (flipped ? diff <= -slab : diff >= slab) return x;
    x = x + (fabs(x) + fabs(c) + fabs(slab)) * R(1.0e-6);
  }
  return R(__builtin_nan(""));
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::record_hit(ObjectList and_net, const Object& m, Solved s, const R* v,
                                        const R* start) -> bool {
  if (s.code == 0) return m.inverted;  // missed: only an inverted member lets the rest through
  if (R(0) < s.dist && s.dist < tmin_) {
    const R t = s.dist + R(0.01);
    const R q0 = v[0] * t + start[0];
    const R q1 = v[1] * t + start[1];
    const R q2 = v[2] * t + start[2];
    if (all_inside(and_net, q0, q1, q2)) {
      tmin_ = t;
      intersection_point_[0] = q0;
      intersection_point_[1] = q1;
      intersection_point_[2] = q2;
      intersected_object_id_ = m.index;
      intsec_rectside_ = s.code;
    }
  }
  return true;
}

template <MathPolicy M>
inline auto Tracer<M>::judge_intersection(const R* dir) -> bool {
  tmin_ = R(1000000000.0);
  for (int r = 0; r < n_or_rows_; ++r) {
    const OrRow& row = or_rows_[r];
    if (row.range != nullptr && !met_before(solver(*row.range, dir, startp_), tmin_)) continue;
    for (const ObjectList* a = row.nets; *a != nullptr; ++a) {
      for (ObjectList e = *a; *e != nullptr; ++e) {
        const Object& m = **e;
        if (!record_hit(*a, m, solver(m, dir, startp_), dir, startp_)) break;
      }
    }
  }
  return R(-0.1) < tmin_ && tmin_ < R(100000000.0);
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::trace_member(ObjectList net, const Object& m, const DirVec& dv) -> bool {
  return record_hit(net, m, solver_fast2<true>(m, dv), dv.v, startp_fast_);
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::range_admits(const Object& range, const DirVec& dv) -> bool {
  return met_before(solver_fast2(range, dv), tmin_);
}

template <MathPolicy M>
template <bool kCull>
MINRT_INLINE auto Tracer<M>::trace_network(ObjectList net, const DirVec& dv) -> void {
  for (ObjectList e = net; *e != nullptr; ++e) {
    const Object& m = **e;
    // A box the ray can only meet behind its start records nothing; as
    // the network's last member nothing else depends on its result.
    if (kCull && (m.ahead & dv.code) == 0 && e[1] == nullptr) break;
    if (!trace_member(net, m, dv)) break;
  }
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::trace_live_network(const LiveNet& live, const DirVec& dv) -> void {
  for (int i = 0; i < live.solved; ++i)
    if (!trace_member(live.net, *live.net[i], dv)) break;
}

template <MathPolicy M>
template <bool kCull>
MINRT_INLINE auto Tracer<M>::judge_intersection_fast(const DirVec& dv) -> bool {
  tmin_ = R(1000000000.0);
  if (kCull && dv.octant >= 0) {
    // The rows and networks the masks leave for this octant, in order.
    if ((live_built_ & (1u << dv.octant)) == 0) build_octant(dv.octant);
    for (const LiveRow* lr = live_rows_ + dv.octant * (n_or_rows_ + 1); lr->nets != nullptr; ++lr) {
      if (lr->range != nullptr && !range_admits(*lr->range, dv)) continue;
      for (const LiveNet* a = lr->nets; a->net != nullptr; ++a) trace_live_network(*a, dv);
    }
    return R(-0.1) < tmin_ && tmin_ < R(100000000.0);
  }
  const uint32_t code = dv.code;
  for (int r = 0; r < n_or_rows_; ++r) {
    const OrRow& row = or_rows_[r];
    if (kCull && (row.fwd_all & code) != 0) continue;
    if (row.range != nullptr && !range_admits(*row.range, dv)) continue;
    for (int k = 0; row.nets[k] != nullptr; ++k) {
      if (kCull && (row.fwd[k] & code) != 0) continue;
      trace_network<kCull>(row.nets[k], dv);
    }
  }
  return R(-0.1) < tmin_ && tmin_ < R(100000000.0);
}

}  // namespace minrt
