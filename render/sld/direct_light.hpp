// Part of the min-rt tracer (render/sld/tracer.hpp).
// Direct light along a primary ray: trace_ray with its mirror recursion,
// the light source's diffuse and highlight terms and their reflections.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::add_light(R bright, R hilight, R hilight_scale) -> void {
  if (bright > R(0)) accum(rgb_, bright, texture_color_);
  if (hilight > R(0)) {
    const R ihl = sqr(sqr(hilight)) * hilight_scale;
    rgb_[0] = rgb_[0] + ihl;
    rgb_[1] = rgb_[1] + ihl;
    rgb_[2] = rgb_[2] + ihl;
  }
}

template <MathPolicy M>
inline auto Tracer<M>::trace_reflections(R diffuse, R hilight_scale, const R* dir) -> void {
  for (int i = n_reflections_ - 1; i >= 0; --i) {
    const Reflection& r = reflections_[i];
    if (!judge_intersection_fast<false>(r.dvec)) continue;
    if (intersected_object_id_ * 4 + intsec_rectside_ != r.surface_id) continue;
    const R p = dot(nvector_, r.dvec.v);
    const R scale = r.bright;
    const R bright = scale * diffuse * p;
    const R hilight = scale * dot(dir, r.dvec.v);
    // add_light adds nothing unless one of them is positive, so the shadow
    // test (pure) is only needed then.
    if (adds_light(bright, hilight) && !in_shadow()) add_light(bright, hilight, hilight_scale);
  }
}

template <MathPolicy M>
template <bool kLight>
inline auto Tracer<M>::trace_ray(int nref, R energy, R* dir, Pixel& pixel) -> int {
  for (; nref < kMaxDepth; ++nref) {
    if (!judge_intersection(dir)) {
      pixel.surface_ids[nref] = -1;
      if (kLight && nref != 0) {
        const R hl = -dot(dir, light_);
        if (hl > R(0)) {
          const R ihl = sqr(hl) * hl * energy * beam_;
          rgb_[0] = rgb_[0] + ihl;
          rgb_[1] = rgb_[1] + ihl;
          rgb_[2] = rgb_[2] + ihl;
        }
      }
      return nref + 1;
    }
    const int obj_id = intersected_object_id_;
    const Object& obj = objects_[obj_id];
    const R diffuse = obj.diffuse * energy;
    get_nvector(obj, dir);
    copy3(startp_, intersection_point_);
    utexture(obj, intersection_point_);
    pixel.surface_ids[nref] = obj_id * 4 + intsec_rectside_;
    copy3(pixel.points[nref], intersection_point_);
    if (obj.diffuse < R(0.5)) {
      pixel.calc_diffuse[nref] = false;
    } else {
      pixel.calc_diffuse[nref] = true;
      const R s = R(1.0) / R(256.0) * diffuse;
      for (int k = 0; k < 3; ++k) pixel.energy[nref][k] = texture_color_[k] * s;
      copy3(pixel.normals[nref], nvector_);
    }
    const R w = R(-2.0) * dot(dir, nvector_);
    accum(dir, w, nvector_);
    // Only the geometry the pixel keeps when tracing skipped rows again (band_rows.hpp).
    if constexpr (kLight) {
      const R hilight_scale = energy * obj.hilight;
      const R bright = -dot(nvector_, light_) * diffuse;
      const R hilight = -dot(dir, light_);
      if (adds_light(bright, hilight) && !in_shadow()) add_light(bright, hilight, hilight_scale);
      setup_startp(intersection_point_);
      trace_reflections(diffuse, hilight_scale, dir);
    }
    // original: below this energy the next slot's surface id is not reset
    // and keeps whatever an earlier row left there.
    if (!(R(0.1) < energy)) return nref + 1;
    if (nref < kMaxDepth - 1) pixel.surface_ids[nref + 1] = -1;
    if (obj.reflection != kReflectMirror) return nref < kMaxDepth - 1 ? nref + 2 : kMaxDepth;
    energy = energy * (R(1.0) - obj.diffuse);
  }
  return kMaxDepth;
}

}  // namespace minrt
