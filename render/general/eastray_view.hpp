// EASTRAY's view over the general tracer (Finish::kEastray): the camera
// (the FOV a half-angle, the display's aspect), the display window and its
// step (black outside the window; line 78: a window that breaks its rules
// computes nothing; inside it every step_x-th pixel of every step_y-th row
// is traced and fills its block), antialiasing where neighbours differ,
// and the linear bytes (shaded value x 255, clamped, no gamma). Rows are
// independent, so they may be rendered in any order or in parallel.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"
#include "formats/model/scene.hpp"
#include "render/general/eastray_shading.hpp"

namespace minrt::general {

// rmode 1 (lines 57, 117): the eye of the right (side +1) or left (-1)
// image, moved half the eye separation along the screen's right; the
// separation is parallax times the eye's distance to the look-at point,
// and both eyes look at that point (the image's centre, line 114).
template <class M>
Vec3<typename M::real> eastray_stereo_eye(const model::EastraySettings<typename M::real>& s, int side) {
  using R = typename M::real;
  using V = Vec3<R>;
  const V to = s.look - s.eye;
  const V forward = normalize<M>(to);
  V up = s.up_point - s.look;
  up = up - forward * dot(up, forward);
  const V right = cross(forward, normalize<M>(up));
  const R half = s.parallax * M::sqrt(dot(to, to)) / R(2);
  return s.eye + right * (side > 0 ? half : -half);
}

template <class M, uint32_t F>
class EastrayView {
  using R = typename M::real;
  using V = Vec3<R>;

 public:
  EastrayView(const model::EastrayShading<R>& settings, const Tracer<M, F>& tracer) : s_(settings), tracer_(tracer) {
    constexpr R kDeg = R(kEastrayPi / 180.0);
    forward_ = normalize<M>(s_.look - s_.eye);
    V up = s_.up_point - s_.look;
    up = up - forward_ * dot(up, forward_);
    up_ = normalize<M>(up);
    right_ = cross(forward_, up_);
    tan_h_ = M::sin(s_.fov * kDeg) / M::cos(s_.fov * kDeg);
    tan_v_ = tan_h_ * M::from_int(s_.height) / M::from_int(s_.width) * s_.aspect;
  }

  // The colour seen through image point (fx, fy) in pixels from the
  // top-left corner (a pixel's centre is at +0.5).
  V sample(R fx, R fy) const {
    const R sx = (R(2) * fx / M::from_int(s_.width) - R(1)) * tan_h_;
    const R sy = (R(1) - R(2) * fy / M::from_int(s_.height)) * tan_v_;
    const V d = normalize<M>(forward_ + right_ * sx + up_ * sy);
    // back_mode 1 and 2 (lines 213-226): the input image, stretched over
    // the display by its nearest pixel, is the background behind this
    // pixel; what the rays hand to it (a camera ray that meets nothing, and
    // reflected or transmitted rays under their switches) shows it.
    if (s_.background != 0 && s_.input_image != nullptr) {
      V share{};
      const V c = tracer_.eastray_radiance(s_.eye, d, 0, R(1), R(0), &share);
      if (!(share.x > R(0) || share.y > R(0) || share.z > R(0))) return c;
      const model::Texture& b = *s_.input_image;
      int32_t bx = M::to_int(M::floor(fx / M::from_int(s_.width) * M::from_int(b.width)));
      int32_t by = M::to_int(M::floor(fy / M::from_int(s_.height) * M::from_int(b.height)));
      bx = bx < 0 ? 0 : bx >= b.width ? b.width - 1 : bx;
      by = by < 0 ? 0 : by >= b.height ? b.height - 1 : by;
      const uint8_t* p = b.rgb + (static_cast<size_t>(by) * static_cast<size_t>(b.width) + static_cast<size_t>(bx)) * 3u;
      const V back{R(p[0]) / R(255), R(p[1]) / R(255), R(p[2]) / R(255)};
      return c + back * share;
    }
    return tracer_.eastray_radiance(s_.eye, d, 0, R(1), R(0));
  }

  // One image row (0 = top) as RGBA bytes, alpha 255.
  void render_row(int y, uint8_t* rgba) const {
    const int w = s_.width;
    for (int i = 0; i < w; ++i) rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = 0, rgba[4 * i + 3] = 255;
    if (!window_valid() || y < s_.y0 || y > s_.y1) return;
    const int traced = s_.y0 + (y - s_.y0) / s_.step_y * s_.step_y;
    for (int x = s_.x0; x <= s_.x1; x += s_.step_x) {
      V c = sample(M::from_int(x) + R(0.5), M::from_int(traced) + R(0.5));
      if (s_.anti != 0) c = antialias(x, traced, c);
      const uint8_t r = to_byte(c.x), g = to_byte(c.y), b = to_byte(c.z);
      for (int bx = x; bx < x + s_.step_x && bx <= s_.x1; ++bx) {
        uint8_t* p = rgba + static_cast<size_t>(bx) * 4;
        p[0] = r, p[1] = g, p[2] = b;
      }
    }
  }

  bool window_valid() const {
    return 0 <= s_.x0 && s_.x0 <= s_.x1 && s_.x1 < s_.width && 0 <= s_.y0 && s_.y0 <= s_.y1 && s_.y1 < s_.height;
  }

  // The shaded value to a byte: clamped, times 255, truncated (no gamma).
  static uint8_t to_byte(R v) {
    if (!(v > R(0))) return 0;
    if (v >= R(1)) return 255;
    return static_cast<uint8_t>(M::to_int(v * R(255)));
  }

 private:
  // Anti n >= 1: n x n samples on a regular grid ("distributed"); -1: 16
  // jittered samples ("stochastic"), only where a neighbour on the step
  // grid differs by at least `level` (0-255) in a channel.
  V antialias(int x, int y, const V& centre) const {
    using eastray_detail::abs;
    const R level = s_.anti_level / R(255);
    bool edge = false;
    const int dx[4] = {-s_.step_x, s_.step_x, 0, 0}, dy[4] = {0, 0, -s_.step_y, s_.step_y};
    for (int k = 0; k < 4 && !edge; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (nx < s_.x0 || nx > s_.x1 || ny < s_.y0 || ny > s_.y1) continue;
      const V o = sample(M::from_int(nx) + R(0.5), M::from_int(ny) + R(0.5));
      const V diff = o - centre;
      edge = abs(diff.x) >= level || abs(diff.y) >= level || abs(diff.z) >= level;
    }
    if (!edge) return centre;
    V sum{};
    int count = 0;
    if (s_.anti > 0) {
      const int n = s_.anti;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          sum += sample(M::from_int(x) + (M::from_int(i) + R(0.5)) / M::from_int(n),
                        M::from_int(y) + (M::from_int(j) + R(0.5)) / M::from_int(n));
          ++count;
        }
    } else {
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
          const uint32_t hsh = hash(static_cast<uint32_t>(x), static_cast<uint32_t>(y), static_cast<uint32_t>(j * 4 + i));
          const R jx = M::from_int(static_cast<int32_t>(hsh & 0xffff)) / R(65536);
          const R jy = M::from_int(static_cast<int32_t>(hsh >> 16)) / R(65536);
          sum += sample(M::from_int(x) + (M::from_int(i) + jx) / R(4), M::from_int(y) + (M::from_int(j) + jy) / R(4));
          ++count;
        }
    }
    return sum / M::from_int(count);
  }
  static uint32_t hash(uint32_t a, uint32_t b, uint32_t c) {
    uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ (c + 0x165667B1u) * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h;
  }

  const model::EastrayShading<R>& s_;
  const Tracer<M, F>& tracer_;
  V forward_{}, up_{}, right_{};
  R tan_h_ = R(0), tan_v_ = R(0);
};

}  // namespace minrt::general
