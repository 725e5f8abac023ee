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

// The camera's right and up for a unit forward f. World up is +y: right =
// up x f, so +x is on the right of a camera looking along +z (as in four of
// the five 42 implementations read whose handedness could be told,
// docs/minirt.md). It is (f.z, 0, -f.x) scaled by its largest component:
// no cancellation however close f is to vertical, so the image turns with
// the heading and never flips by 90 degrees between two nearby
// orientations. Only a camera looking exactly straight up or down has no
// heading; it gets the limit of a camera tilted from +z (right = +x).
template <class M>
void camera_basis(const Vec3<typename M::real>& f, Vec3<typename M::real>& right, Vec3<typename M::real>& up) {
  using R = typename M::real;
  const R ax = f.x < R(0) ? -f.x : f.x;
  const R az = f.z < R(0) ? -f.z : f.z;
  const R m = ax > az ? ax : az;
  if (m > R(0)) {
    const R rx = f.z / m, rz = -f.x / m;
    const R len = M::sqrt(rx * rx + rz * rz);
    right = Vec3<R>{rx / len, R(0), rz / len};
  } else {
    right = Vec3<R>{R(1), R(0), R(0)};
  }
  up = cross(f, right);
}

template <class M>
model::Camera<typename M::real> place_camera(const View<typename M::real>& view, int32_t width, int32_t height) {
  using R = typename M::real;
  const Vec3<R> f = view.direction;  // unit (the reader normalised it)
  Vec3<R> right, up;
  camera_basis<M>(f, right, up);
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
