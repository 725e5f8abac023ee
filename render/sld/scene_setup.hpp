// Part of the min-rt tracer (render/sld/tracer.hpp).
// Scene preparation: the original's globals from the scene (screen, light,
// objects with their rotated quadratic forms, AND/OR networks) and init,
// which takes the tables from the arena.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::init(const Scene<R>& scene, int width, int height, Arena& arena) -> bool {
  width_ = width;
  height_ = height;
  center_[0] = width / 2;
  center_[1] = height / 2;
  scan_pitch_ = R(128.0) / M::from_int(width);
  load_environment(scene);
  load_objects(scene);
  build_networks(scene);
  n_reflections_ = 0;

  const int stride = consts_total(scene);
  R* consts = arena.alloc_zeroed<R>(size_t{kDirvecCount} * stride);
  const int or_entries = or_entries_total(scene);
  live_nets_stride_ = or_entries + n_or_rows_;
  live_rows_ = arena.alloc_zeroed<LiveRow>(8 * static_cast<size_t>(n_or_rows_ + 1));
  live_nets_ = arena.alloc_zeroed<LiveNet>(8 * static_cast<size_t>(live_nets_stride_));
  if (live_rows_ == nullptr || live_nets_ == nullptr) return false;
  shadow_rows_ = arena.alloc_zeroed<ShadowRow>(static_cast<size_t>(n_or_rows_));
  shadow_nets_ = arena.alloc_zeroed<ShadowNet>(static_cast<size_t>(or_entries));
  if ((n_or_rows_ > 0 && shadow_rows_ == nullptr) || (or_entries > 0 && shadow_nets_ == nullptr)) return false;
  // Zeroed like the original's fresh arrays, whose stale slots are read.
  Pixel* pixels = arena.alloc_zeroed<Pixel>(3 * static_cast<size_t>(width));
  row_ = arena.alloc_zeroed<uint8_t>(3 * static_cast<size_t>(width));
  if (consts == nullptr || pixels == nullptr || row_ == nullptr) return false;
  for (int l = 0; l < 3; ++l) lines_[l] = pixels + l * width;
  lines_through_ = -1;
  for (int g = 0; g < kDirvecGroups; ++g)
    for (int i = 0; i < kDirvecsPerGroup; ++i)
      dirvecs_[g][i].c = consts + (g * kDirvecsPerGroup + i) * stride;
  light_dirvec_.c = consts + kLightDirvec * stride;
  for (int r = 0; r < kMaxReflections; ++r)
    reflections_[r].dvec.c = consts + (kLightDirvec + 1 + r) * stride;

  init_dirvecs();
  copy3(light_dirvec_.v, light_);
  setup_dirvec_constants(light_dirvec_);
  setup_shadow_culling();
  setup_reflections(n_objects_ - 1);
  return true;
}

template <MathPolicy M>
inline auto Tracer<M>::load_environment(const Scene<R>& s) -> void {
  const R v1 = rad(s.screen_rotation_deg[0]);
  const R cos_v1 = M::cos(v1), sin_v1 = M::sin(v1);
  const R v2 = rad(s.screen_rotation_deg[1]);
  const R cos_v2 = M::cos(v2), sin_v2 = M::sin(v2);
  screenz_[0] = cos_v1 * sin_v2 * R(200.0);
  screenz_[1] = sin_v1 * R(-200.0);
  screenz_[2] = cos_v1 * cos_v2 * R(200.0);
  screenx_[0] = cos_v2;
  screenx_[1] = R(0);
  screenx_[2] = -sin_v2;
  screeny_[0] = -sin_v1 * sin_v2;
  screeny_[1] = -cos_v1;
  screeny_[2] = -sin_v1 * cos_v2;
  for (int i = 0; i < 3; ++i) viewpoint_[i] = s.screen[i] - screenz_[i];

  const R l1 = rad(s.light_rotation_deg[0]);
  light_[1] = -M::sin(l1);
  const R l2 = rad(s.light_rotation_deg[1]);
  const R cl1 = M::cos(l1);
  light_[0] = cl1 * M::sin(l2);
  light_[2] = cl1 * M::cos(l2);
  beam_ = s.beam;
}

template <MathPolicy M>
inline auto Tracer<M>::load_objects(const Scene<R>& s) -> void {
  n_objects_ = s.object_count;
  int offset = 0;
  for (int i = 0; i < n_objects_; ++i) {
    const SceneObject<R>& in = s.objects[i];
    Object& o = objects_[i];
    o.texture = in.texture;
    o.form = in.form;
    o.reflection = in.reflection;
    o.rotated = in.rotated;
    copy3(o.abc, in.abc);
    copy3(o.center, in.center);
    o.diffuse = in.diffuse;
    o.hilight = in.hilight;
    copy3(o.color, in.color);
    for (int k = 0; k < 3; ++k) o.rot[k] = in.rotated != 0 ? rad(in.rotation_deg[k]) : R(0);
    for (int k = 0; k < 4; ++k) o.start[k] = R(0);
    // Planes always count as inverted; the sign read from the file only
    // orients their normal.
    o.inverted = o.form == kFormPlane ? true : in.inverted;
    if (o.form == kFormQuadric) {
      for (int k = 0; k < 3; ++k) {
        const R a = o.abc[k];
        o.abc[k] = a == R(0) ? R(0) : sgn(a) / sqr(a);
      }
    } else if (o.form == kFormPlane) {
      normalize(o.abc, !in.inverted);
    }
    // original: the rotation is applied to every form, boxes and planes too.
    if (o.rotated != 0) rotate_quadratic_form(o.abc, o.rot);
    setup_slab(o);
    o.finite_texture = o.texture != kTextureStripes && o.texture != kTextureRings &&
                       o.texture != kTextureSpots && finite(o.color[0]) && finite(o.color[1]) &&
                       finite(o.color[2]);
    o.ahead = ~0u;
    o.consts_offset = offset * static_cast<int>(sizeof(R));
    o.index = i;
    offset += consts_count(o.form);
  }
}

template <MathPolicy M>
inline auto Tracer<M>::rotate_quadratic_form(R* abc, R* rot) -> void {
  const R cos_x = M::cos(rot[0]), sin_x = M::sin(rot[0]);
  const R cos_y = M::cos(rot[1]), sin_y = M::sin(rot[1]);
  const R cos_z = M::cos(rot[2]), sin_z = M::sin(rot[2]);
  const R m00 = cos_y * cos_z;
  const R m01 = sin_x * sin_y * cos_z - cos_x * sin_z;
  const R m02 = cos_x * sin_y * cos_z + sin_x * sin_z;
  const R m10 = cos_y * sin_z;
  const R m11 = sin_x * sin_y * sin_z + cos_x * cos_z;
  const R m12 = cos_x * sin_y * sin_z - sin_x * cos_z;
  const R m20 = -sin_y;
  const R m21 = sin_x * cos_y;
  const R m22 = cos_x * cos_y;
  const R ao = abc[0], bo = abc[1], co = abc[2];
  abc[0] = ao * sqr(m00) + bo * sqr(m10) + co * sqr(m20);
  abc[1] = ao * sqr(m01) + bo * sqr(m11) + co * sqr(m21);
  abc[2] = ao * sqr(m02) + bo * sqr(m12) + co * sqr(m22);
  rot[0] = R(2.0) * (ao * m01 * m02 + bo * m11 * m12 + co * m21 * m22);
  rot[1] = R(2.0) * (ao * m00 * m02 + bo * m10 * m12 + co * m20 * m22);
  rot[2] = R(2.0) * (ao * m00 * m01 + bo * m10 * m11 + co * m20 * m21);
}

}  // namespace minrt
