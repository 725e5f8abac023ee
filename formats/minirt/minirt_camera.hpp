// Places a miniRT camera for an image size (the size is not in the file):
// horizontal field of view, rays through pixel centres (SPEC.md 2.3),
// expressed as the general tracer's flat camera, whose ray for pixel (x, y)
// is forward + right * (2x - W) / m + up * (H - 2y) / m with m = max(W, H).
// Choosing right = r * hw * m / W, up = u * hw * m / W and moving forward by
// half a pixel (r * hw / W - u * hw / W) gives exactly
// f + r * hw * (2(x + 1/2) / W - 1) + u * hh * (1 - 2(y + 1/2) / H),
// hw = tan(FOV / 2), hh = hw * H / W.
#pragma once

#include <stdint.h>

#include "formats/minirt/minirt_reader.hpp"
#include "formats/model/scene.hpp"

namespace minrt::minirt {

// FOV 180 has no finite image plane: it is rendered as this (the subject's
// range [0, 180] includes it). FOV 0 needs nothing: every ray is the axis.
inline constexpr double kMaxRenderedFov = 179.9;

template <class M>
model::Camera<typename M::real> place_camera(const View<typename M::real>& view, int32_t width, int32_t height) {
  using R = typename M::real;
  const Vec3<R> f = view.direction;  // unit (the reader normalised it)
  // World up is +y, or +z when the camera looks (almost) straight up or down.
  const R fy = f.y < R(0) ? -f.y : f.y;
  const Vec3<R> world_up = fy > R(0.999) ? Vec3<R>{R(0), R(0), R(1)} : Vec3<R>{R(0), R(1), R(0)};
  const Vec3<R> right = normalize<M>(cross(f, world_up));
  const Vec3<R> up = cross(right, f);
  R fov = view.fov_degrees;
  if (fov > static_cast<R>(kMaxRenderedFov)) fov = static_cast<R>(kMaxRenderedFov);
  constexpr R kHalfDegree = static_cast<R>(3.14159265358979323846 / 360.0);
  const R half = fov * kHalfDegree;
  const R hw = M::sin(half) / M::cos(half);
  const R w = M::from_int(width);
  const R m = M::from_int(width > height ? width : height);
  model::Camera<R> cam;
  cam.eye = view.position;
  cam.right = right * (hw * m / w);
  cam.up = up * (hw * m / w);
  cam.forward = f + right * (hw / w) - up * (hw / w);
  cam.projection = model::Projection::kFlat;
  return cam;
}

}  // namespace minrt::minirt
