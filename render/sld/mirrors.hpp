// Part of the min-rt tracer (render/sld/tracer.hpp).
// The mirror table: every reflecting surface, set up once per scene.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::add_reflection(int surface_id, R bright, R v0, R v1, R v2) -> void {
  Reflection& r = reflections_[n_reflections_++];
  r.surface_id = surface_id;
  r.bright = bright;
  set3(r.dvec.v, v0, v1, v2);
  setup_dirvec_constants(r.dvec);
}

template <MathPolicy M>
inline auto Tracer<M>::setup_reflections(int obj_id) -> void {
  if (obj_id < 0) return;
  const Object& obj = objects_[obj_id];
  if (obj.reflection != kReflectMirror || !(obj.diffuse < R(1.0))) return;
  const R br = R(1.0) - obj.diffuse;
  if (obj.form == kFormBox) {
    const int sid = obj_id * 4;
    const R n0 = -light_[0], n1 = -light_[1], n2 = -light_[2];
    add_reflection(sid + 1, br, light_[0], n1, n2);
    add_reflection(sid + 2, br, n0, light_[1], n2);
    add_reflection(sid + 3, br, n0, n1, light_[2]);
  } else if (obj.form == kFormPlane) {
    const R p = dot(light_, obj.abc);
    add_reflection(obj_id * 4 + 1, br, R(2.0) * obj.abc[0] * p - light_[0],
                   R(2.0) * obj.abc[1] * p - light_[1], R(2.0) * obj.abc[2] * p - light_[2]);
  }
}

}  // namespace minrt
