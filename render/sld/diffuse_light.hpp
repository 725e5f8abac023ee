// Part of the min-rt tracer (render/sld/tracer.hpp).
// Diffuse (indirect) light sampled over the precomputed directions and
// shared between a pixel and its neighbours; the rows and the render loop.
#pragma once

#include "render/sld/tracer_class.hpp"

namespace minrt {

template <MathPolicy M>
inline auto Tracer<M>::render(const RowSink& out) -> void {
  out.begin(width_, height_);
  render_rows(0, height_, out);
  out.end();
}

template <MathPolicy M>
MINRT_INLINE auto Tracer<M>::trace_diffuse_ray(const DirVec& dv, R energy) -> void {
  if (!judge_intersection_fast<true>(dv)) return;
  const Object& obj = objects_[intersected_object_id_];
  get_nvector(obj, dv.v);
  const R br = -dot(nvector_, light_);
  const R bright = br > R(0) ? br : R(0.0);
  const R scale = energy * bright * obj.diffuse;
  // Facing away from the light the scale is +-0, and adding +-0 * colour
  // changes nothing (diffuse_ray_ is a sum started at +0, so never -0)
  // unless the colour is not finite; only then does the shadow test matter.
  // Nothing reads the texture colour before the next utexture otherwise.
  if (scale == R(0) && obj.finite_texture) return;
  utexture(obj, intersection_point_);
  if (scale == R(0) && finite(texture_color_[0]) && finite(texture_color_[1]) &&
      finite(texture_color_[2]))
    return;
  if (in_shadow()) return;
  accum(diffuse_ray_, scale, texture_color_);
}

template <MathPolicy M>
inline auto Tracer<M>::trace_diffuse_rays(const DirVec* group, const R* normal, const R* org) -> void {
  // A point sampling all 300 directions comes here once for each group:
  // its tables and octant lists stay valid from the first time.
  if (!culled_start_valid_ || !same_bits(startp_fast_, org)) {
    setup_startp<true>(org);
    setup_forward_culling();
    culled_start_valid_ = true;
  }
  // Entries 2n and 2n+1 point in opposite directions.
  for (int i = kDirvecsPerGroup - 2; i >= 0; i -= 2) {
    const R p = dot(group[i].v, normal);
    if (p < R(0))
      trace_diffuse_ray(group[i + 1], p / R(-150.0));
    else
      trace_diffuse_ray(group[i], p / R(150.0));
  }
}

template <MathPolicy M>
inline auto Tracer<M>::pretrace_diffuse_rays(Pixel& pixel) -> void {
  for (int nref = 0; nref < kMaxDepth; ++nref) {
    if (pixel.surface_ids[nref] < 0) return;
    if (!pixel.calc_diffuse[nref]) continue;
    zero3(diffuse_ray_);
    trace_diffuse_rays(dirvecs_[pixel.group_id], pixel.normals[nref], pixel.points[nref]);
    copy3(pixel.received[nref], diffuse_ray_);
  }
}

template <MathPolicy M>
inline auto Tracer<M>::diffuse_using_1point(Pixel& pixel, int nref) -> void {
  copy3(diffuse_ray_, pixel.received[nref]);
  for (int g = 0; g < kDirvecGroups; ++g)
    if (pixel.group_id != g) trace_diffuse_rays(dirvecs_[g], pixel.normals[nref], pixel.points[nref]);
  accum_product(rgb_, pixel.energy[nref], diffuse_ray_);
}

template <MathPolicy M>
inline auto Tracer<M>::do_without_neighbors(Pixel& pixel, int nref) -> void {
  for (; nref < kMaxDepth; ++nref) {
    if (pixel.surface_ids[nref] < 0) return;
    if (pixel.calc_diffuse[nref]) diffuse_using_1point(pixel, nref);
  }
}

template <MathPolicy M>
inline auto Tracer<M>::try_exploit_neighbors(int x, Pixel* prev, Pixel* cur, Pixel* next) -> void {
  Pixel& pixel = cur[x];
  for (int nref = 0; nref < kMaxDepth; ++nref) {
    const int32_t sid = pixel.surface_ids[nref];
    if (sid < 0) return;
    if (prev[x].surface_ids[nref] != sid || next[x].surface_ids[nref] != sid ||
        cur[x - 1].surface_ids[nref] != sid || cur[x + 1].surface_ids[nref] != sid) {
      do_without_neighbors(pixel, nref);
      return;
    }
    if (pixel.calc_diffuse[nref]) {
      copy3(diffuse_ray_, prev[x].received[nref]);
      add3(diffuse_ray_, cur[x - 1].received[nref]);
      add3(diffuse_ray_, pixel.received[nref]);
      add3(diffuse_ray_, cur[x + 1].received[nref]);
      add3(diffuse_ray_, next[x].received[nref]);
      accum_product(rgb_, pixel.energy[nref], diffuse_ray_);
    }
  }
}

template <MathPolicy M>
inline auto Tracer<M>::eye_row(int y, R* row) const -> void {
  const R ydisp = scan_pitch_ * M::from_int(y - center_[1]);
  row[0] = ydisp * screeny_[0] + screenz_[0];
  row[1] = ydisp * screeny_[1] + screenz_[1];
  row[2] = ydisp * screeny_[2] + screenz_[2];
}

template <MathPolicy M>
inline auto Tracer<M>::eye_ray(const R* row, int x, R* dir) const -> void {
  const R xdisp = scan_pitch_ * M::from_int(x - center_[0]);
  dir[0] = xdisp * screenx_[0] + row[0];
  dir[1] = xdisp * screenx_[1] + row[1];
  dir[2] = xdisp * screenx_[2] + row[2];
  normalize(dir, false);
}

template <MathPolicy M>
template <bool kFull>
inline auto Tracer<M>::pretrace_line(Pixel* line, int y, int group_id) -> void {
  R row[3];
  eye_row(y, row);
  for (int x = width_ - 1; x >= 0; --x) {
    R dir[3];
    eye_ray(row, x, dir);
    zero3(rgb_);
    copy3(startp_, viewpoint_);
    [[maybe_unused]] const int written = trace_ray<kFull>(0, R(1.0), dir, line[x]);
    if constexpr (kFull) {
      copy3(line[x].rgb, rgb_);
      if (slot_rows_ != nullptr) track_slots(line[x], x, y, written);
      line[x].group_id = group_id;
      pretrace_diffuse_rays(line[x]);
      group_id = add_mod5(group_id, 1);
    }
  }
}

template <MathPolicy M>
inline auto Tracer<M>::scan_pixels(int y, Pixel* prev, Pixel* cur, Pixel* next) -> void {
  uint8_t* rgb = row_;
  for (int x = 0; x < width_; ++x, rgb += 3) {
    copy3(rgb_, cur[x].rgb);
    if (y + 1 < height_ && y > 0 && x + 1 < width_ && x > 0)
      try_exploit_neighbors(x, prev, cur, next);
    else
      do_without_neighbors(cur[x], 0);
    rgb[0] = static_cast<uint8_t>(pixel_channel<M>(rgb_[0]));
    rgb[1] = static_cast<uint8_t>(pixel_channel<M>(rgb_[1]));
    rgb[2] = static_cast<uint8_t>(pixel_channel<M>(rgb_[2]));
  }
}

}  // namespace minrt
