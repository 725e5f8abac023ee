// EASTRAY's mappings evaluated at a hit (manual lines 597-673, 558;
// docs/eastray.md, "Mapping"): the projections of modes 0-4 (10-14 the
// same, filtered between texels and mip-mapped: the halved images built
// here, the level chosen by the pixel's footprint), the image's tile and
// its range, the sum
// of overlapping entries, bump mapping and colour-number (attribute)
// mapping. A surface whose material is at or above material_count is a
// mapped object: its colour's parameters are replaced by their mappings
// where one is in range, evaluated in the frame the object was written in.
#pragma once

#include "formats/model/eastray_mapping.hpp"
#include "formats/model/eastray_shading.hpp"
#include "formats/model/scene.hpp"

namespace minrt::general {

// Offset, in the object's units, of the two extra height samples that give
// a bump map's slope (small against any feature a texel of a map spans).
inline constexpr double kBumpStep = 1e-3;

namespace eastray_map_detail {

template <class R>
R absr(R v) {
  return v < R(0) ? -v : v;
}

// Texel (x, y) wrapped into the image, as 0..1.
template <class R>
Vec3<R> texel_at(const model::Texture& t, int32_t x, int32_t y) {
  x %= t.width;
  y %= t.height;
  if (x < 0) x += t.width;
  if (y < 0) y += t.height;
  const uint8_t* p = t.rgb + (static_cast<size_t>(y) * static_cast<size_t>(t.width) + static_cast<size_t>(x)) * 3u;
  // Divided, not multiplied by 1/255: 51 gives exactly the number 0.2 reads as.
  return Vec3<R>{R(p[0]) / R(255), R(p[1]) / R(255), R(p[2]) / R(255)};
}

// The image at tile coordinates (s, t) in [0, 1) (s across from the left,
// t down from the top): the texel under it, or (filtered) the bilinear
// blend of the four around it, the tile wrapping at its edges.
template <class M>
Vec3<typename M::real> sample(const model::Texture& t, typename M::real s, typename M::real v, bool filtered) {
  using R = typename M::real;
  const R x = s * R(t.width), y = v * R(t.height);
  if (!filtered) return texel_at<R>(t, M::to_int(M::floor(x)), M::to_int(M::floor(y)));
  const R fx = M::floor(x - R(0.5)), fy = M::floor(y - R(0.5));
  const R ax = x - R(0.5) - fx, ay = y - R(0.5) - fy;
  const int32_t x0 = M::to_int(fx), y0 = M::to_int(fy);
  const Vec3<R> a = texel_at<R>(t, x0, y0), b = texel_at<R>(t, x0 + 1, y0);
  const Vec3<R> c = texel_at<R>(t, x0, y0 + 1), d = texel_at<R>(t, x0 + 1, y0 + 1);
  return (a * (R(1) - ax) + b * ax) * (R(1) - ay) + (c * (R(1) - ax) + d * ax) * ay;
}

// The image seen through a footprint `texels` texels of it wide: filtered
// in the image itself up to one texel, beyond that between the two halved
// images around log2(texels) (trilinear), the smallest one past the last.
template <class M>
Vec3<typename M::real> sample_mip(const model::Texture& t, const model::Texture* mips, typename M::real s,
                                  typename M::real v, typename M::real texels) {
  using R = typename M::real;
  if (mips == nullptr || mips[0].width <= 0 || !(texels > R(1))) return sample<M>(t, s, v, true);
  int32_t last = 0;  // halved images there are
  while (last < model::kMipLevels && mips[last].width > 0) ++last;
  const R level = M::log(texels) * R(1.44269504088896340736);  // log2
  if (!(level < M::from_int(last))) return sample<M>(mips[last - 1], s, v, true);
  const int32_t k = M::to_int(M::floor(level));
  const R f = level - M::from_int(k);
  const model::Texture& a = k == 0 ? t : mips[k - 1];
  return sample<M>(a, s, v, true) * (R(1) - f) + sample<M>(mips[k], s, v, true) * f;
}

template <class M>
typename M::real fraction(typename M::real x) {
  return x - M::floor(x);
}

// Tile coordinate of u between the image's corners a (left or top) and b.
template <class M>
typename M::real tile(typename M::real u, typename M::real a, typename M::real b) {
  return fraction<M>((u - a) / (b - a));
}

template <class R>
bool between(R u, R a, R b) {
  return a <= b ? (u >= a && u <= b) : (u >= b && u <= a);
}

}  // namespace eastray_map_detail

// Bytes the halved images of a w x h map take (down to one texel, at most
// kMipLevels of them).
inline size_t eastray_mip_bytes(int32_t w, int32_t h) {
  size_t n = 0;
  for (int k = 0; k < model::kMipLevels && (w > 1 || h > 1); ++k) {
    w = (w + 1) / 2, h = (h + 1) / 2;
    n += static_cast<size_t>(w) * static_cast<size_t>(h) * 3u;
  }
  return n;
}

// The halved images of `base` into `levels` (kMipLevels, width 0 past the
// last), their texels in `bytes` (eastray_mip_bytes of them): each texel
// the rounded mean of the 2 x 2 under it (those inside, at an odd edge).
// Integers only: the host and the board build the same bytes.
inline void eastray_build_mips(const model::Texture& base, uint8_t* bytes, model::Texture* levels) {
  model::Texture src = base;
  for (int k = 0; k < model::kMipLevels; ++k) {
    levels[k] = model::Texture{};
    if (src.width <= 1 && src.height <= 1) continue;
    const int32_t w = (src.width + 1) / 2, h = (src.height + 1) / 2;
    uint8_t* out = bytes;
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x)
        for (int c = 0; c < 3; ++c) {
          uint32_t sum = 0, count = 0;
          for (int32_t sy = 2 * y; sy <= 2 * y + 1 && sy < src.height; ++sy)
            for (int32_t sx = 2 * x; sx <= 2 * x + 1 && sx < src.width; ++sx, ++count)
              sum += src.rgb[(static_cast<size_t>(sy) * static_cast<size_t>(src.width) + static_cast<size_t>(sx)) * 3u +
                             static_cast<size_t>(c)];
          *out++ = static_cast<uint8_t>((sum + count / 2) / count);
        }
    levels[k] = model::Texture{w, h, bytes};
    bytes = out;
    src = levels[k];
  }
}

// One mapping entry at the point q and normal n of its own frame: false
// when q is outside its range. `value`: the image's colour times the scale.
// A filtered entry with the image's halved images (`mips`) and a pixel
// footprint `foot` (its width in this frame; 0: none) picks their level.
template <class M>
bool eastray_map_entry(const model::EastrayMapping<typename M::real>& e, const model::Texture& image,
                       const Vec3<typename M::real>& q, const Vec3<typename M::real>& n, bool filtered,
                       Vec3<typename M::real>& value, const model::Texture* mips = nullptr,
                       typename M::real foot = typename M::real(0)) {
  using R = typename M::real;
  using V = Vec3<R>;
  using namespace eastray_map_detail;
  if (image.width <= 0 || image.height <= 0 || image.rgb == nullptr) return false;
  constexpr R kPi = R(3.14159265358979323846);
  const bool mip = filtered && mips != nullptr && foot > R(0);
  const R iw = M::from_int(image.width), ih = M::from_int(image.height);
  auto look = [&](R s, R t, R texels) {
    return mip ? sample_mip<M>(image, mips, s, t, texels) : sample<M>(image, s, t, filtered);
  };
  if (e.mode == model::EastrayMapMode::kAllDirections) {
    // Three plane projections, along x, y and z, weighted by how much the
    // normal faces each (line 654): no pole where the image pinches.
    const R wx = absr(n.x), wy = absr(n.y), wz = absr(n.z);
    const R sum = wx + wy + wz;
    if (!(sum > R(0))) return false;
    const R k = e.u1;
    const R texels = mip ? foot * absr(k) * (iw > ih ? iw : ih) : R(0);
    V c{};
    if (wx > R(0)) c += look(fraction<M>(q.y * k), fraction<M>(q.z * k), texels) * (wx / sum);
    if (wy > R(0)) c += look(fraction<M>(q.x * k), fraction<M>(q.z * k), texels) * (wy / sum);
    if (wz > R(0)) c += look(fraction<M>(q.x * k), fraction<M>(q.y * k), texels) * (wz / sum);
    value = c * e.scale;
    return true;
  }
  R u, v;
  R du = foot, dv = foot;  // the footprint in u and in v
  switch (e.mode) {
    case model::EastrayMapMode::kPlane:  // the XY plane: u = x, v = y (line 657)
      u = q.x, v = q.y;
      break;
    case model::EastrayMapMode::kSphere: {  // longitude, latitude from the x axis, both -1..1 (line 659)
      const R r = M::sqrt(q.x * q.x + q.y * q.y);
      if (r == R(0) && q.z == R(0)) return false;
      u = M::atan2(q.y, q.x) / kPi;
      v = M::atan2(q.z, r) / (kPi / R(2));
      if (mip) du = r > R(0) ? foot / (kPi * r) : R(0), dv = foot / (kPi / R(2) * M::sqrt(r * r + q.z * q.z));
      break;
    }
    case model::EastrayMapMode::kRing:  // around the origin on XY: angle -1..1, radius (line 661)
      if (q.x == R(0) && q.y == R(0)) u = R(0);
      else u = M::atan2(q.y, q.x) / kPi;
      v = M::sqrt(q.x * q.x + q.y * q.y);
      if (mip) du = v > R(0) ? foot / (kPi * v) : R(0);
      break;
    default: {  // kCylinder: around z: angle -1..1, v = z (line 663)
      if (q.x == R(0) && q.y == R(0)) u = R(0);
      else u = M::atan2(q.y, q.x) / kPi;
      v = q.z;
      const R r = M::sqrt(q.x * q.x + q.y * q.y);
      if (mip) du = r > R(0) ? foot / (kPi * r) : R(0);
      break;
    }
  }
  if (!between(u, e.ua1, e.ua2) || !between(v, e.va1, e.va2)) return false;
  R texels = R(0);
  if (mip) {
    const R tu = du * iw / absr(e.u2 - e.u1), tv = dv * ih / absr(e.v2 - e.v1);
    texels = tu > tv ? tu : tv;
  }
  value = look(tile<M>(u, e.u1, e.u2), tile<M>(v, e.v1, e.v2), texels) * e.scale;
  return true;
}

// A chain of entries at p, n (the object's frame): the sum of those in
// range (line 671); false when none is. `foot`: the pixel's footprint as a
// vector of this frame (zero: the image itself, no halved one).
template <class M>
bool eastray_map_chain(const model::EastrayShading<typename M::real>& e, int32_t head,
                       const Vec3<typename M::real>& p, const Vec3<typename M::real>& n, bool force_filter,
                       Vec3<typename M::real>& sum, const Vec3<typename M::real>& foot = Vec3<typename M::real>{}) {
  using R = typename M::real;
  bool any = false;
  sum = Vec3<R>{};
  const bool footprint = foot.x != R(0) || foot.y != R(0) || foot.z != R(0);
  for (int32_t i = head; i != model::kNoMapping; i = e.mappings[i].next) {
    const model::EastrayMapping<R>& m = e.mappings[i];
    if (m.image < 0 || m.image >= e.map_image_count) continue;
    Vec3<R> v;
    const model::Texture* mips = e.map_mips != nullptr && m.filtered && footprint
                                     ? e.map_mips + static_cast<size_t>(m.image) * model::kMipLevels
                                     : nullptr;
    R width = R(0);
    if (mips != nullptr) {
      const Vec3<R> f = m.to_map.vector(foot);
      width = M::sqrt(dot(f, f));
    }
    if (eastray_map_entry<M>(m, e.map_images[m.image], m.to_map.point(p), m.from_map.transposed(n),
                             m.filtered || force_filter, v, mips, width)) {
      sum += v;
      any = true;
    }
  }
  return any;
}

// The colour-number (attribute) mapping: the first entry in range whose
// value is not 0 adds its red byte to the colour number (SPEC.md 4.5).
template <class M>
int32_t eastray_mapped_number(const model::EastrayShading<typename M::real>& e,
                              const model::EastrayMappedObject<typename M::real>& o, const Vec3<typename M::real>& p,
                              const Vec3<typename M::real>& n) {
  using R = typename M::real;
  for (int32_t i = o.number_map; i != model::kNoMapping; i = e.mappings[i].next) {
    const model::EastrayMapping<R>& m = e.mappings[i];
    if (m.image < 0 || m.image >= e.map_image_count) continue;
    Vec3<R> v;
    if (!eastray_map_entry<M>(m, e.map_images[m.image], m.to_map.point(p), m.from_map.transposed(n), false, v))
      continue;
    const int32_t add = M::to_int(M::floor(v.x * R(255) + R(0.5)));
    if (add == 0) continue;
    const int32_t number = o.material + add;
    return number >= 0 && number < e.material_count ? number : o.material;
  }
  return o.material;
}

// The material at a hit of surface `material` at world point p with the
// outward world normal n (bumped in place when the colour has a bump
// mapping). Unmapped colours are returned as they are; mapped ones are
// copied into `scratch` with every mapped parameter replaced. `footprint`:
// the width a pixel covers there (world units; 0: none), which picks the
// halved images of filtered mappings.
template <class M>
const model::EastrayMaterial<typename M::real>& eastray_surface(const model::EastrayShading<typename M::real>& e,
                                                              int32_t material, const Vec3<typename M::real>& p,
                                                              Vec3<typename M::real>& n,
                                                              model::EastrayMaterial<typename M::real>& scratch,
                                                              typename M::real footprint = typename M::real(0)) {
  using R = typename M::real;
  using V = Vec3<R>;
  if (material < e.material_count) return e.materials[material];
  const model::EastrayMappedObject<R>& o = e.mapped_objects[material - e.material_count];
  const V po = o.to_object.point(p);
  V no = o.to_world.transposed(n);
  const R nl = dot(no, no);
  if (nl > R(0)) no = no / M::sqrt(nl);
  const int32_t number = o.number_map == model::kNoMapping ? o.material : eastray_mapped_number<M>(e, o, po, no);
  scratch = e.materials[number];
  model::EastrayMaterial<R>& m = scratch;
  V v;
  auto mono = [](const V& c) { return (c.x + c.y + c.z) / R(3); };
  // The footprint as a vector of the object's frame: one across the surface.
  V foot{};
  if (footprint > R(0) && nl > R(0)) {
    const V nw = normalize<M>(n);
    const V across = normalize<M>(cross(eastray_map_detail::absr(nw.x) < R(0.9) ? V{R(1), R(0), R(0)} : V{R(0), R(1), R(0)}, nw));
    foot = o.to_object.vector(across * footprint);
  }
  if (eastray_map_chain<M>(e, m.map[model::kMapDiffuse], po, no, false, v, foot)) m.diffuse = v;
  if (eastray_map_chain<M>(e, m.map[model::kMapReflect], po, no, false, v, foot)) m.reflect = v;
  if (eastray_map_chain<M>(e, m.map[model::kMapTransmit], po, no, false, v, foot)) m.transmit = v;
  if (eastray_map_chain<M>(e, m.map[model::kMapIor], po, no, false, v, foot)) m.ior = mono(v);
  if (eastray_map_chain<M>(e, m.map[model::kMapHalf], po, no, false, v, foot)) m.half_distance = mono(v);
  for (int i = 0; i < model::kSpecularParams; ++i) {
    const int32_t head = m.map[model::kMapSpecular + i];
    if (head == model::kNoMapping || !eastray_map_chain<M>(e, head, po, no, false, v, foot)) continue;
    // A colour's three take the colour; every other parameter the mean.
    const bool colour = (i == 0 && m.specular != model::Specular::kBlinn) || (i == 3 && m.specular == model::Specular::kConstant);
    if (colour) m.p[i] = v.x, m.p[i + 1] = v.y, m.p[i + 2] = v.z;
    else m.p[i] = mono(v);
  }
  if (m.map[model::kMapBump] != model::kNoMapping && nl > R(0)) {
    // The mapped value is a height along the normal (line 558): the normal
    // leans away from where it rises. Heights come from the filtered image
    // (a texel's steps would have no slope but at their edges), at p and
    // a step along two directions of the surface.
    const int32_t head = m.map[model::kMapBump];
    const V helper = eastray_map_detail::absr(no.x) < R(0.9) ? V{R(1), R(0), R(0)} : V{R(0), R(1), R(0)};
    const V t1 = normalize<M>(cross(helper, no));
    const V t2 = cross(no, t1);
    const R step = R(kBumpStep);
    V h0, h1, h2;
    const R base = m.bump;
    const R a = eastray_map_chain<M>(e, head, po, no, true, h0) ? mono(h0) : base;
    const R b = eastray_map_chain<M>(e, head, po + t1 * step, no, true, h1) ? mono(h1) : base;
    const R c = eastray_map_chain<M>(e, head, po + t2 * step, no, true, h2) ? mono(h2) : base;
    const V bent = no - t1 * ((b - a) / step) - t2 * ((c - a) / step);
    // Back to the world: normals through the inverse transpose of to_object.
    V nw = o.to_object.transposed(bent);
    const R wl = dot(nw, nw);
    if (wl > R(0)) n = nw / M::sqrt(wl);
  }
  if (m.specular == model::Specular::kAniso1 || m.specular == model::Specular::kAniso2) {
    // The scratches' direction at the hit, in the world (eastray_specular
    // reads it from p[3..5] and A B C from p[6..8]): model 2's circles
    // run around the axis p[6..8] through the centre p[3..5]; model 3's
    // lines along p[3..5]; both in the object's frame.
    V dir;
    if (m.specular == model::Specular::kAniso1) {
      const V axis{m.p[6], m.p[7], m.p[8]}, centre{m.p[3], m.p[4], m.p[5]};
      dir = cross(axis, po - centre);
      m.p[6] = m.p[9], m.p[7] = m.p[10], m.p[8] = m.p[11];
    } else {
      dir = V{m.p[3], m.p[4], m.p[5]};
    }
    const V w = o.to_world.vector(dir);
    m.p[3] = w.x, m.p[4] = w.y, m.p[5] = w.z;
  }
  return m;
}

}  // namespace minrt::general
