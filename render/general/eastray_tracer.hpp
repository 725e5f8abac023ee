// The EASTRAY tracer: CSG by membership (a crossing of a primitive is a
// surface of its block when the point passes every enclosing AND (inside
// the other items) and OR (outside them); the main obj's items are
// independent objects), RANGE as a bound, polygon triangles, and the
// manual's shading: ambient (env), diffuse, specular models 0, 1, 4, 5,
// mirror reflection, Fresnel transmission with absorption, mist, the sky
// with visible sun discs, three light kinds with 2^(-d/h) fall-off, the
// display window and step, and adaptive antialiasing. docs/eastray.md has
// every formula.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/image/row_sink.hpp"
#include "core/math/vec3.hpp"
#include "formats/eastray/eastray_scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/csg_intersect.hpp"

namespace minrt::eastray {

inline constexpr int kMaxShadowLayers = 16;  // transparent blockers a shadow ray passes

template <class M>
class Tracer {
  using R = typename M::real;
  using V = Vec3<R>;

 public:
  explicit Tracer(const Scene<R>& scene) : s_(scene) {
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
    return radiance(s_.eye, d, 0, R(1), R(0));
  }

  // One image row (0 = top) as linear floats, 3 per pixel: black outside
  // the display window (line 78: a window that breaks its rules computes
  // nothing); inside it every step_x-th pixel of every step_y-th row is
  // traced and fills its block; antialiased where neighbours differ. Rows
  // are independent, so they may be rendered in any order or in parallel.
  void render_row(int y, R* rgb) const {
    const int w = s_.width;
    for (int i = 0; i < w * 3; ++i) rgb[i] = R(0);
    if (!window_valid() || y < s_.y0 || y > s_.y1) return;
    const int traced = s_.y0 + (y - s_.y0) / s_.step_y * s_.step_y;
    for (int x = s_.x0; x <= s_.x1; x += s_.step_x) {
      V c = sample(M::from_int(x) + R(0.5), M::from_int(traced) + R(0.5));
      if (s_.anti != 0) c = antialias(x, traced, c);
      for (int bx = x; bx < x + s_.step_x && bx <= s_.x1; ++bx) {
        R* p = rgb + static_cast<size_t>(bx) * 3;
        p[0] = c.x, p[1] = c.y, p[2] = c.z;
      }
    }
  }

  // The whole image, top row first, into an RGBA sink (alpha 255):
  // `linear` holds 3 * width reals, `rgba` 4 * width bytes.
  void render(const RgbaRowSink& sink, R* linear, uint8_t* rgba) const {
    sink.begin(s_.width, s_.height);
    for (int y = 0; y < s_.height; ++y) {
      render_row(y, linear);
      for (int x = 0; x < s_.width; ++x) {
        rgba[4 * x] = to_byte(linear[3 * x]);
        rgba[4 * x + 1] = to_byte(linear[3 * x + 1]);
        rgba[4 * x + 2] = to_byte(linear[3 * x + 2]);
        rgba[4 * x + 3] = 255;
      }
      sink.row(y, rgba);
    }
    sink.end();
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
  static constexpr R kDeg = R(3.14159265358979323846 / 180.0);
  static constexpr R kPi = R(3.14159265358979323846);

  struct Hit {
    R t = R(-1);
    V normal{};     // unit outward normal of the solid at the hit (smoothed on meshes)
    V geo{};        // the geometric one: which side a new ray starts on
    int32_t material = kNone;
    bool found = false;
  };

  // ------------------------------------------------------------ antialias
  // Anti n >= 1: n x n samples on a regular grid ("distributed"); -1: 16
  // jittered samples ("stochastic"), only where a neighbour on the step
  // grid differs by at least `level` (0-255) in a channel.
  V antialias(int x, int y, const V& centre) const {
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
  static R abs(R v) { return v < R(0) ? -v : v; }
  static R maxc(const V& v) { return v.x > v.y ? (v.x > v.z ? v.x : v.z) : (v.y > v.z ? v.y : v.z); }
  static R pow_pos(R base, R e) {  // base^e for base >= 0
    if (e == R(0)) return R(1);
    if (!(base > R(0))) return R(0);
    return M::exp(e * M::log(base));
  }
  static R half_life(R d, R half) {  // 2^(-d/half); no fall-off when half <= 0
    if (!(half > R(0))) return R(1);
    return M::exp(-d / half * R(0.69314718055994530942));
  }

  // ------------------------------------------------------------ CSG (render/general/csg_intersect.hpp)
  general::CsgScene<R> csg() const { return {s_.nodes, s_.primitives}; }

  void take(const general::SolidHit<R>& h, Hit& hit) const {
    if (!h.found) return;
    hit.t = h.t;
    hit.normal = h.normal;
    hit.geo = h.normal;
    hit.material = h.material;
    hit.found = true;
  }

  void triangle(int32_t i, const V& o, const V& d, R t_min, R& t_max, Hit& hit, bool shadow) const {
    const Triangle<R>& tr = s_.triangles[i];
    const MeshFace& face = s_.faces[i];
    if (shadow && face.no_shadow) return;
    const V e1 = tr.p1 - tr.p0, e2 = tr.p2 - tr.p0;
    const V pv = cross(d, e2);
    const R det = dot(e1, pv);
    if (det == R(0)) return;
    const R inv = R(1) / det;
    const V tv = o - tr.p0;
    const R u = dot(tv, pv) * inv;
    if (u < R(0) || u > R(1)) return;
    const V qv = cross(tv, e1);
    const R v = dot(d, qv) * inv;
    if (v < R(0) || u + v > R(1)) return;
    const R t = dot(e2, qv) * inv;
    if (!(t > t_min && t < t_max)) return;
    t_max = t;
    hit.t = t;
    hit.found = true;
    hit.material = static_cast<int32_t>(tr.material);
    V nrm = tr.normal;
    hit.geo = tr.normal;
    if (face.smooth) {
      const V sn = s_.vertex_normals[face.vertex[0]] * (R(1) - u - v) + s_.vertex_normals[face.vertex[1]] * u +
                   s_.vertex_normals[face.vertex[2]] * v;
      if (dot(sn, sn) > R(0)) {
        nrm = normalize<M>(sn);
        if (dot(nrm, tr.normal) < R(0)) nrm = -nrm;
      }
    }
    hit.normal = nrm;
  }

  Hit nearest(const V& o, const V& d, R t_min, R t_max, bool shadow) const {
    Hit hit;
    if (s_.root != kNone) {
      general::SolidHit<R> h;
      if (s_.unbounded_objects != nullptr) {
        const general::CsgObjects<R> objects{static_cast<const general::BvhNode<R>*>(s_.object_bvh_nodes),
                                             s_.object_bvh_refs, s_.unbounded_objects, s_.unbounded_count};
        general::csg_nearest_object<M>(csg(), objects, o, d, t_min, t_max, h, shadow);
      } else {
        general::csg_nearest<M>(csg(), s_.root, o, d, t_min, t_max, h, shadow);
      }
      take(h, hit);
    }
    if (s_.triangle_bvh_nodes == nullptr) {
      for (int32_t i = 0; i < s_.triangle_count; ++i) triangle(i, o, d, t_min, t_max, hit, shadow);
      return hit;
    }
    // The hierarchy: nearer child first, boxes beyond the nearest hit
    // skipped; of equally near triangles the first in the list wins, as in
    // the loop above (and on a board without room for the hierarchy).
    const auto* nodes = static_cast<const general::BvhNode<R>*>(s_.triangle_bvh_nodes);
    const V inv = general::inverse_dir(d);
    constexpr int32_t kNoTriangle = 0x7fffffff;  // the t_max so far stays exclusive
    int32_t best = kNoTriangle;
    uint32_t stack[general::kBvhStack];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const general::BvhNode<R>& nd = nodes[stack[--top]];
      if (general::box_entry(nd.box, o, inv, general::next_above(t_max)) < R(0)) continue;
      if (nd.count > 0) {
        for (uint32_t k = 0; k < nd.count; ++k) {
          const int32_t i = static_cast<int32_t>(s_.triangle_bvh_refs[nd.index + k]);
          const R limit = best != kNoTriangle && i < best ? general::next_above(t_max) : t_max;
          R reached = limit;
          triangle(i, o, d, t_min, reached, hit, shadow);
          if (reached != limit) t_max = reached, best = i;
        }
        continue;
      }
      const bool flip = d[nd.axis] < R(0);
      stack[top++] = nd.index + (flip ? 0u : 1u);  // the farther child waits
      stack[top++] = nd.index + (flip ? 1u : 0u);
    }
    return hit;
  }

  // A start point pushed off the surface along `side`, so a new ray does
  // not meet the surface it leaves.
  static V offset(const V& p, const V& side) {
    const R m = R(1) + maxc(V{abs(p.x), abs(p.y), abs(p.z)});
    const R bias = sizeof(R) == 4 ? R(2e-4) : R(1e-8);
    return p + side * (bias * m);
  }

  // Light arriving at p (unit direction L, distance dist) after blockers:
  // opaque ones stop it, transparent ones tint it by their transmittance.
  V shadow_factor(const V& p, const V& l, R dist) const {
    V f{R(1), R(1), R(1)};
    V o = p;
    R remaining = dist;
    for (int layer = 0; layer < kMaxShadowLayers; ++layer) {
      const Hit h = nearest(o, l, s_.eps, remaining, true);
      if (!h.found) return f;
      const Material<R>& m = s_.materials[h.material];
      if (maxc(m.transmit) <= R(0)) return V{};
      f = f * m.transmit;
      o = offset(o + l * h.t, dot(h.normal, l) > R(0) ? h.normal : -h.normal);
      remaining = remaining - h.t;
      if (!(remaining > R(0))) return f;
    }
    return f;
  }

  V sky(const V& d) const {
    V c = s_.sky;
    for (int32_t i = 0; i < s_.light_count; ++i) {  // visible sun discs (back_mode 0)
      const Light<R>& l = s_.lights[i];
      if (l.kind != LightKind::kInfinite || !(l.size_deg > R(0))) continue;
      const R cs = dot(d, l.direction);
      const V x = cross(d, l.direction);
      const R angle = M::atan2(M::sqrt(dot(x, x)), cs);
      const R size = l.size_deg * kDeg;
      if (angle >= size) continue;
      c += l.color * pow_pos(M::cos(angle / size * (kPi / R(2))), l.concentration);
    }
    return c;
  }

  // Local light at p with shading normal n, view direction v (toward the eye).
  // `start`: p pushed off the surface toward the viewer's side.
  V direct(const V& p, const V& start, const V& n, const V& v, const Material<R>& m) const {
    V c = s_.env * m.diffuse;
    const R ndv = dot(n, v);
    for (int32_t i = 0; i < s_.light_count; ++i) {
      const Light<R>& l = s_.lights[i];
      V ldir;
      R dist;
      V in = l.color;
      if (l.kind == LightKind::kInfinite) {
        ldir = l.direction;
        dist = R(1e30);
      } else {
        const V to = l.position - p;
        dist = M::sqrt(dot(to, to));
        if (!(dist > R(0))) continue;
        ldir = to / dist;
        R k = half_life(dist, l.half_distance);
        if (l.kind == LightKind::kSpot) {
          const R ca = -dot(ldir, l.direction);
          if (!(ca > R(0))) continue;
          k = k * pow_pos(ca, l.spread);
        }
        in = in * k;
      }
      const R ndl = dot(n, ldir);
      if (!(ndl > R(0))) continue;
      if (s_.shadows && !l.no_shadow && (l.shadow_range < R(0) || dist <= l.shadow_range)) {
        in = in * shadow_factor(start, ldir, dist);
        if (maxc(in) <= R(0)) continue;
      }
      c += in * m.diffuse * ndl;
      c += in * specular(m, n, v, ldir, ndl, ndv);
    }
    if (m.specular == Specular::kConstant) {
      const V c1{m.p[0], m.p[1], m.p[2]}, c2{m.p[3], m.p[4], m.p[5]};
      c += c2 + (c1 - c2) * pow_pos(ndv > R(0) ? ndv : R(0), m.p[6]);
    }
    return c;
  }

  V specular(const Material<R>& m, const V& n, const V& v, const V& l, R ndl, R ndv) const {
    const V hsum = l + v;
    const R hl = dot(hsum, hsum);
    if (!(hl > R(0))) return V{};
    const V h = hsum / M::sqrt(hl);
    const R ndh = dot(n, h);
    if (!(ndh > R(0))) return V{};
    switch (m.specular) {
      case Specular::kBlinn: {
        const R k = m.p[0] * pow_pos(ndh, m.p[1]);
        return V{k, k, k};
      }
      case Specular::kBlinnGauss: {
        if (!(ndv > R(0))) return V{};
        const R vdh = dot(v, h);
        const R alpha = M::atan2(M::sqrt(R(1) - ndh * ndh > R(0) ? R(1) - ndh * ndh : R(0)), ndh);
        const R ca = m.p[3] * alpha;
        const R dist = M::exp(-ca * ca);
        const R g = geometry(ndh, ndv, ndl, vdh);
        const R f0 = m.p[4];
        const R f = f0 + (R(1) - f0) * pow5(R(1) - vdh);
        const R k = dist * g * f / ndv;
        return V{m.p[0], m.p[1], m.p[2]} * k;
      }
      case Specular::kCookTorrance: {
        if (!(ndv > R(0))) return V{};
        const R vdh = dot(v, h);
        const R c2 = ndh * ndh;
        const R tan2 = (R(1) - c2) / c2;
        auto beckmann = [&](R spread) {
          if (!(spread > R(0))) return R(0);
          const R rough2 = R(1) / (spread * spread);
          return M::exp(-tan2 / rough2) / (kPi * rough2 * c2 * c2);
        };
        const R ratio = m.p[3];
        const R dist = ratio * beckmann(m.p[4]) + (R(1) - ratio) * beckmann(m.p[5]);
        const R g = geometry(ndh, ndv, ndl, vdh);
        const R w = pow5(R(1) - vdh);
        const V f0{m.p[0], m.p[1], m.p[2]};
        const V f = f0 + (V{R(1), R(1), R(1)} - f0) * w;
        return f * (dist * g / (R(4) * ndv));
      }
      default:
        return V{};
    }
  }
  static R pow5(R x) {
    const R x2 = x * x;
    return x2 * x2 * x;
  }
  static R geometry(R ndh, R ndv, R ndl, R vdh) {  // Blinn's / Cook-Torrance's masking and shadowing
    if (!(vdh > R(0))) return R(0);
    R g = R(1);
    const R a = R(2) * ndh * ndv / vdh, b = R(2) * ndh * ndl / vdh;
    if (a < g) g = a;
    if (b < g) g = b;
    return g;
  }

  // The colour a ray brings back. `medium_half`: the half distance of the
  // body the ray travels in (0: air, where the mist is).
  V radiance(const V& o, const V& d, int depth, R weight, R medium_half) const {
    // condition eps (line 91): distances below it count as 0, so a ray
    // never meets the surface it starts on.
    const Hit h = nearest(o, d, depth == 0 ? R(0) : s_.eps, R(1e30), false);
    if (!h.found) return sky(d);
    const Material<R>& m = s_.materials[h.material];
    const V p = o + d * h.t;
    const bool from_inside = dot(h.geo, d) > R(0);
    const V n = from_inside ? -h.normal : h.normal;  // toward the viewer
    const V g = from_inside ? -h.geo : h.geo;
    const V v = -d;
    const V above = offset(p, g), below = offset(p, -g);
    V c = direct(p, above, n, v, m);
    if (depth + 1 < s_.max_depth) {  // condition n: n - 1 levels (line 89)
      const bool clear = maxc(m.transmit) > R(0);
      const R cosi = dot(n, v);
      V kr = m.reflect, kt{};
      V tdir{};
      bool refract = false;
      if (clear) {
        const R eta = from_inside ? m.ior : R(1) / m.ior;  // n1 / n2
        const R sin2t = eta * eta * (R(1) - cosi * cosi);
        if (sin2t < R(1)) {
          const R cost = M::sqrt(R(1) - sin2t);
          // Fresnel for unpolarised light: the mean of s and p reflectances.
          const R rs = (eta * cosi - cost) / (eta * cosi + cost);
          const R rp = (cosi - eta * cost) / (cosi + eta * cost);
          const R fr = (rs * rs + rp * rp) / R(2);
          kr = m.reflect * fr;
          kt = m.transmit * (R(1) - fr);
          tdir = d * eta + n * (eta * cosi - cost);
          refract = true;
        }
        if (from_inside && !s_.inner && refract) kr = V{};  // no branching inside bodies
      }
      if (maxc(kr) > R(0) && weight * maxc(kr) >= s_.min_weight) {
        const V rdir = d + n * (R(2) * cosi);
        c += kr * radiance(above, rdir, depth + 1, weight * maxc(kr), medium_half);
      }
      if (refract && maxc(kt) > R(0) && weight * maxc(kt) >= s_.min_weight) {
        // A body that does not absorb (transparency 0) still keeps the mist
        // out: its half distance is taken as 1e30, where 2^(-t/h) is 1.
        const R next_medium = from_inside ? R(0) : m.half_distance > R(0) ? m.half_distance : R(1e30);
        c += kt * radiance(below, normalize<M>(tdir), depth + 1, weight * maxc(kt), next_medium);
      }
    }
    if (medium_half > R(0)) c = c * half_life(h.t, medium_half);
    if (s_.mist_half > R(0) && !(medium_half > R(0))) {
      const R f = half_life(h.t, s_.mist_half);
      c = c * f;
      if (s_.mist_to_sky) c += s_.sky * (R(1) - f);
    }
    return c;
  }

  const Scene<R>& s_;
  V forward_{}, up_{}, right_{};
  R tan_h_ = R(0), tan_v_ = R(0);
};

}  // namespace minrt::eastray
