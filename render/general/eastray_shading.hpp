// EASTRAY's finish (Finish::kEastray), the general tracer's policy for
// EASTRAY scenes: visibility through the CSG tree of quadric solids
// (csg_intersect.hpp, by membership, RANGE as a bound) and the mesh
// triangles, and the manual's shading: ambient (env), diffuse, specular
// models 0, 1, 4, 5, mirror reflection, Fresnel transmission with
// absorption, mist, the sky with visible sun discs (or the background
// image through back_mode's switches), three light kinds with
// 2^(-d/h) fall-off and shadows through transparent blockers. The camera,
// display window and antialiasing are eastray_view.hpp. docs/eastray.md
// has every formula.
//
// The tie rule is EASTRAY's: of equally near hits the object earlier in
// the tree wins, objects win over triangles, and the earlier triangle over
// a later one (CS418's rule, Hit::offer, is the later object).
#pragma once

#include "render/general/eastray_mapping.hpp"
#include "render/general/tracer.hpp"

namespace minrt::general {

inline constexpr int kMaxShadowLayers = 16;  // transparent blockers a shadow ray passes
inline constexpr double kEastrayPi = 3.14159265358979323846;

namespace eastray_detail {

template <class R>
R abs(R v) {
  return v < R(0) ? -v : v;
}
template <class R>
R maxc(const Vec3<R>& v) {
  return v.x > v.y ? (v.x > v.z ? v.x : v.z) : (v.y > v.z ? v.y : v.z);
}
template <class M>
typename M::real pow_pos(typename M::real base, typename M::real e) {  // base^e for base >= 0
  using R = typename M::real;
  if (e == R(0)) return R(1);
  if (!(base > R(0))) return R(0);
  return M::exp(e * M::log(base));
}
template <class M>
typename M::real half_life(typename M::real d, typename M::real half) {  // 2^(-d/half); none when half <= 0
  using R = typename M::real;
  if (!(half > R(0))) return R(1);
  return M::exp(-d / half * R(0.69314718055994530942));
}
template <class R>
R pow5(R x) {
  const R x2 = x * x;
  return x2 * x2 * x;
}
// Blinn's / Cook-Torrance's masking and shadowing.
template <class R>
R geometry(R ndh, R ndv, R ndl, R vdh) {
  if (!(vdh > R(0))) return R(0);
  R g = R(1);
  const R a = R(2) * ndh * ndv / vdh, b = R(2) * ndh * ndl / vdh;
  if (a < g) g = a;
  if (b < g) g = b;
  return g;
}
// A start point pushed off the surface along `side`, so a new ray does
// not meet the surface it leaves.
template <class R>
Vec3<R> offset(const Vec3<R>& p, const Vec3<R>& side) {
  const R m = R(1) + maxc(Vec3<R>{abs(p.x), abs(p.y), abs(p.z)});
  const R bias = sizeof(R) == 4 ? R(2e-4) : R(1e-8);
  return p + side * (bias * m);
}

}  // namespace eastray_detail

template <class M, uint32_t F>
class EastrayShader : public TracerCore<M, F> {
  using R = typename M::real;
  using Base = TracerCore<M, F>;

 public:
  using Base::Base;

  // How a ray came to be: back_mode's switches (lines 217-226) act on
  // reflected and transmitted rays that meet nothing.
  enum class Arrival { kCamera, kReflected, kTransmitted };
  // The colour a ray from `o` along unit `d` brings back; `medium_half` is
  // the absorption half distance of the body it travels in (0: air, where
  // the mist is). With `back` (back_mode 1 and 2), the share of the
  // background behind the pixel that shows through is written there (the
  // pixel is colour + back x background): a camera ray that meets nothing,
  // and a reflected or transmitted one whose switch is 1, hand their power
  // to it. `travelled`: the ray's path from the eye so far, which with the
  // pixel's angle gives the footprint that picks a mip-mapped image's level.
  Vec3<R> eastray_radiance(const Vec3<R>& o, const Vec3<R>& d, int depth, R weight, R medium_half,
                           Vec3<R>* back = nullptr, Arrival arrival = Arrival::kCamera, R travelled = R(0)) const;
  // Whether a ray from `o` along `d` meets anything (EASTRAY's background image).
  bool eastray_hits(const Vec3<R>& o, const Vec3<R>& d) const {
    return eastray_nearest(o, d, R(0), R(1e30), false).found;
  }

 private:
  using Base::bvh_;
  using Base::objects_;
  using Base::s_;

  struct EastrayHit {
    R t = R(-1);
    Vec3<R> normal{};  // unit outward normal at the hit (smoothed on meshes)
    Vec3<R> geo{};     // the geometric one: which side a new ray starts on
    int32_t material = model::kNoNode;
    bool found = false;
  };
  EastrayHit eastray_nearest(const Vec3<R>& o, const Vec3<R>& d, R t_min, R t_max, bool shadow) const;
  [[gnu::always_inline]] inline void eastray_triangle(uint32_t i, const Vec3<R>& o, const Vec3<R>& d, R t_min,
                                                      R& t_max, EastrayHit& hit, bool shadow) const;
  Vec3<R> eastray_shadow(const Vec3<R>& p, const Vec3<R>& l, R dist) const;
  Vec3<R> eastray_sky(const Vec3<R>& d) const;
  Vec3<R> eastray_direct(const Vec3<R>& p, const Vec3<R>& start, const Vec3<R>& n, const Vec3<R>& v,
                         const model::EastrayMaterial<R>& m) const;
  Vec3<R> eastray_specular(const model::EastrayMaterial<R>& m, const Vec3<R>& n, const Vec3<R>& v,
                           const Vec3<R>& l, R ndl, R ndv) const;
};

// Moller-Trumbore on the edges p1-p0 and p2-p0; lowers t_max to a hit.
template <class M, uint32_t F>
void EastrayShader<M, F>::eastray_triangle(uint32_t i, const Vec3<R>& o, const Vec3<R>& d, R t_min, R& t_max,
                                    EastrayHit& hit, bool shadow) const {
  using V = Vec3<R>;
  const model::Triangle<R>& tr = s_.triangles[i];
  const model::MeshFace& face = s_.mesh_faces[i];
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

// The nearest surface in (t_min, t_max). `shadow`: solids and faces
// flagged no-shadow are not there.
template <class M, uint32_t F>
typename EastrayShader<M, F>::EastrayHit EastrayShader<M, F>::eastray_nearest(const Vec3<R>& o, const Vec3<R>& d,
                                                                              R t_min, R t_max, bool shadow) const {
  EastrayHit hit;
  if constexpr ((F & kQuadrics) != 0) {
    if (s_.csg_root != model::kNoNode) {
      const CsgScene<R> tree{s_.csg_nodes, s_.quadrics};
      SolidHit<R> h;
      if (objects_ != nullptr && objects_->unbounded != nullptr)
        csg_nearest_object<M>(tree, *objects_, o, d, t_min, t_max, h, shadow);
      else
        csg_nearest<M>(tree, s_.csg_root, o, d, t_min, t_max, h, shadow);
      if (h.found) {
        hit.t = h.t;
        hit.normal = h.normal;
        hit.geo = h.normal;
        hit.material = h.material;
        hit.found = true;
      }
    }
  }
  if constexpr ((F & kTriangles) != 0) {
    if (bvh_.node_count == 0) {  // no room for the hierarchy: all, in order
      for (uint32_t i = 0; i < s_.triangle_count; ++i) eastray_triangle(i, o, d, t_min, t_max, hit, shadow);
      return hit;
    }
    // Nearer child first, boxes beyond the nearest hit skipped; of equally
    // near triangles the first in the list wins, whatever the visit order.
    constexpr uint32_t kNoTriangle = 0xffffffffu;  // the t_max so far stays exclusive
    uint32_t best = kNoTriangle;
    visit_nearer_first(bvh_.nodes, bvh_.refs, o, d, t_max, [&](uint32_t ref) {
      const uint32_t i = ref & ~kTriangleBit;
      const R limit = best != kNoTriangle && i < best ? next_above(t_max) : t_max;
      R reached = limit;
      eastray_triangle(i, o, d, t_min, reached, hit, shadow);
      if (reached != limit) t_max = reached, best = i;
    });
  }
  return hit;
}

// Light arriving at p (unit direction l, distance dist) after blockers:
// opaque ones stop it, transparent ones tint it by their transmittance.
template <class M, uint32_t F>
Vec3<typename M::real> EastrayShader<M, F>::eastray_shadow(const Vec3<R>& p, const Vec3<R>& l, R dist) const {
  using V = Vec3<R>;
  using namespace eastray_detail;
  const model::EastrayShading<R>& e = *s_.eastray;
  V f{R(1), R(1), R(1)};
  V o = p;
  R remaining = dist;
  for (int layer = 0; layer < kMaxShadowLayers; ++layer) {
    const EastrayHit h = eastray_nearest(o, l, e.eps, remaining, true);
    if (!h.found) return f;
    model::EastrayMaterial<R> scratch;
    V n = h.normal;
    const model::EastrayMaterial<R>& m = eastray_surface<M>(e, h.material, o + l * h.t, n, scratch);
    if (maxc(m.transmit) <= R(0)) return V{};
    f = f * m.transmit;
    o = offset(o + l * h.t, dot(h.normal, l) > R(0) ? h.normal : -h.normal);
    remaining = remaining - h.t;
    if (!(remaining > R(0))) return f;
  }
  return f;
}

// The sky, with visible sun discs (back_mode 0 and 2).
template <class M, uint32_t F>
Vec3<typename M::real> EastrayShader<M, F>::eastray_sky(const Vec3<R>& d) const {
  using V = Vec3<R>;
  using namespace eastray_detail;
  const model::EastrayShading<R>& e = *s_.eastray;
  constexpr R kDeg = R(kEastrayPi / 180.0);
  constexpr R kPi = R(kEastrayPi);
  V c = e.sky;
  if (e.background == 1) return c;  // back_mode 1: the discs are not seen (line 213)
  for (int32_t i = 0; i < e.light_count; ++i) {
    const model::EastrayLight<R>& l = e.lights[i];
    if (l.kind != model::EastrayLightKind::kInfinite || !(l.size_deg > R(0))) continue;
    const R cs = dot(d, l.direction);
    const V x = cross(d, l.direction);
    const R angle = M::atan2(M::sqrt(dot(x, x)), cs);
    const R size = l.size_deg * kDeg;
    if (angle >= size) continue;
    c += l.color * pow_pos<M>(M::cos(angle / size * (kPi / R(2))), l.concentration);
  }
  return c;
}

// Local light at p with shading normal n, view direction v (toward the
// eye). `start`: p pushed off the surface toward the viewer's side.
template <class M, uint32_t F>
Vec3<typename M::real> EastrayShader<M, F>::eastray_direct(const Vec3<R>& p, const Vec3<R>& start, const Vec3<R>& n,
                                                    const Vec3<R>& v, const model::EastrayMaterial<R>& m) const {
  using V = Vec3<R>;
  using namespace eastray_detail;
  const model::EastrayShading<R>& e = *s_.eastray;
  V c = e.env * m.diffuse;
  const R ndv = dot(n, v);
  for (int32_t i = 0; i < e.light_count; ++i) {
    const model::EastrayLight<R>& l = e.lights[i];
    V ldir;
    R dist;
    V in = l.color;
    if (l.kind == model::EastrayLightKind::kInfinite) {
      ldir = l.direction;
      dist = R(1e30);
    } else {
      const V to = l.position - p;
      dist = M::sqrt(dot(to, to));
      if (!(dist > R(0))) continue;
      ldir = to / dist;
      R k = half_life<M>(dist, l.half_distance);
      if (l.kind == model::EastrayLightKind::kSpot) {
        const R ca = -dot(ldir, l.direction);
        if (!(ca > R(0))) continue;
        k = k * pow_pos<M>(ca, l.spread);
      }
      in = in * k;
    }
    const R ndl = dot(n, ldir);
    if (!(ndl > R(0))) continue;
    if (e.shadows && !l.no_shadow && (l.shadow_range < R(0) || dist <= l.shadow_range)) {
      in = in * eastray_shadow(start, ldir, dist);
      if (maxc(in) <= R(0)) continue;
    }
    c += in * m.diffuse * ndl;
    c += in * eastray_specular(m, n, v, ldir, ndl, ndv);
  }
  if (m.specular == model::Specular::kConstant) {
    const V c1{m.p[0], m.p[1], m.p[2]}, c2{m.p[3], m.p[4], m.p[5]};
    c += c2 + (c1 - c2) * pow_pos<M>(ndv > R(0) ? ndv : R(0), m.p[6]);
  }
  return c;
}

template <class M, uint32_t F>
Vec3<typename M::real> EastrayShader<M, F>::eastray_specular(const model::EastrayMaterial<R>& m, const Vec3<R>& n,
                                                      const Vec3<R>& v, const Vec3<R>& l, R ndl, R ndv) const {
  using V = Vec3<R>;
  using namespace eastray_detail;
  constexpr R kPi = R(kEastrayPi);
  const V hsum = l + v;
  const R hl = dot(hsum, hsum);
  if (!(hl > R(0))) return V{};
  const V h = hsum / M::sqrt(hl);
  const R ndh = dot(n, h);
  if (!(ndh > R(0))) return V{};
  switch (m.specular) {
    case model::Specular::kBlinn: {
      const R k = m.p[0] * pow_pos<M>(ndh, m.p[1]);
      return V{k, k, k};
    }
    case model::Specular::kBlinnGauss: {
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
    case model::Specular::kCookTorrance: {
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
    case model::Specular::kAniso1:
    case model::Specular::kAniso2: {
      // Ward's anisotropic Gaussian (the manual names the models, lines
      // 573-584, but gives no formula): the scratches' direction t (p[3..5],
      // set at the hit by eastray_surface) laid into the surface, B the
      // roughness along them, A across them (B < A: the highlight streaks
      // across the scratches), C the strength; times n.l like the diffuse.
      if (!(ndv > R(0))) return V{};
      V t{m.p[3], m.p[4], m.p[5]};
      t = t - n * dot(t, n);
      R tl = dot(t, t);
      const R a = m.p[6], b = m.p[7], strength = m.p[8];
      if (!(a > R(0)) || !(b > R(0))) return V{};
      if (!(tl > R(0))) {  // a circle's centre, or scratches along n: any direction of the surface
        t = cross(abs(n.x) < R(0.9) ? V{R(1), R(0), R(0)} : V{R(0), R(1), R(0)}, n);
        tl = dot(t, t);
      }
      t = t / M::sqrt(tl);
      const V bt = cross(n, t);
      const R ht = dot(h, t) / b, hb = dot(h, bt) / a;
      const R k = strength * M::exp(-(ht * ht + hb * hb) / (ndh * ndh)) /
                  (R(4) * kPi * a * b * M::sqrt(ndl * ndv)) * ndl;
      return V{m.p[0], m.p[1], m.p[2]} * k;
    }
    default:
      return V{};
  }
}

template <class M, uint32_t F>
Vec3<typename M::real> EastrayShader<M, F>::eastray_radiance(const Vec3<R>& o, const Vec3<R>& d, int depth, R weight,
                                                      R medium_half, Vec3<R>* back, Arrival arrival,
                                                      R travelled) const {
  using V = Vec3<R>;
  using namespace eastray_detail;
  const model::EastrayShading<R>& e = *s_.eastray;
  if (back != nullptr) *back = V{};
  // condition eps (line 91): distances below it count as 0, so a ray
  // never meets the surface it starts on.
  const EastrayHit h = eastray_nearest(o, d, depth == 0 ? R(0) : e.eps, R(1e30), false);
  if (!h.found) {
    const bool to_background = arrival == Arrival::kCamera || (arrival == Arrival::kReflected && e.back_reflect) ||
                               (arrival == Arrival::kTransmitted && e.back_transmit);
    if (back == nullptr || !to_background) return eastray_sky(d);
    // Its power goes to the background; the sun discs stay where the mode
    // shows them (none under back_mode 1: eastray_sky is the bare sky there).
    *back = V{R(1), R(1), R(1)};
    return eastray_sky(d) - e.sky;
  }
  const V p = o + d * h.t;
  model::EastrayMaterial<R> scratch;
  V mapped_normal = h.normal;
  // A pixel's width where the path from the eye meets this mapped surface
  // (its angle 2 tan(fov) / width; the spreading of curved mirrors and
  // lenses is not followed).
  R footprint = R(0);
  if (e.map_mips != nullptr && h.material >= e.material_count) {
    constexpr R kDeg = R(kEastrayPi / 180.0);
    footprint = (travelled + h.t) * (R(2) * M::sin(e.fov * kDeg) / M::cos(e.fov * kDeg) / M::from_int(e.width));
  }
  const model::EastrayMaterial<R>& m = eastray_surface<M>(e, h.material, p, mapped_normal, scratch, footprint);
  const bool from_inside = dot(h.geo, d) > R(0);
  const V n = from_inside ? -mapped_normal : mapped_normal;  // toward the viewer
  const V g = from_inside ? -h.geo : h.geo;
  const V v = -d;
  const V above = offset(p, g), below = offset(p, -g);
  V c = eastray_direct(p, above, n, v, m);
  if (depth + 1 < e.max_depth) {  // condition n: n - 1 levels (line 89)
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
      if (from_inside && !e.inner && refract) kr = V{};  // no branching inside bodies
    }
    V through{};  // the background's share a secondary ray brings back
    if (maxc(kr) > R(0) && weight * maxc(kr) >= e.min_weight) {
      const V rdir = d + n * (R(2) * cosi);
      c += kr * eastray_radiance(above, rdir, depth + 1, weight * maxc(kr), medium_half, back != nullptr ? &through : nullptr,
                                 Arrival::kReflected, travelled + h.t);
      if (back != nullptr) *back += kr * through;
    }
    if (refract && maxc(kt) > R(0) && weight * maxc(kt) >= e.min_weight) {
      // A body that does not absorb (transparency 0) still keeps the mist
      // out: its half distance is taken as 1e30, where 2^(-t/h) is 1.
      const R next_medium = from_inside ? R(0) : m.half_distance > R(0) ? m.half_distance : R(1e30);
      c += kt * eastray_radiance(below, normalize<M>(tdir), depth + 1, weight * maxc(kt), next_medium,
                                 back != nullptr ? &through : nullptr, Arrival::kTransmitted, travelled + h.t);
      if (back != nullptr) *back += kt * through;
    }
  }
  // The background seen through this hit fades as the hit's colour does.
  if (medium_half > R(0)) {
    const R k = half_life<M>(h.t, medium_half);
    c = c * k;
    if (back != nullptr) *back = *back * k;
  }
  if (e.mist_half > R(0) && !(medium_half > R(0))) {
    const R f = half_life<M>(h.t, e.mist_half);
    c = c * f;
    if (back != nullptr) *back = *back * f;
    if (e.mist_to_sky) c += e.sky * (R(1) - f);
  }
  return c;
}

}  // namespace minrt::general
