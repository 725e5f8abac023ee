// miniRT's surface maps (SPEC.md 2.1): the checkerboard of `plc`, the
// texture and bump map of `spt`. Texels are taken as linear values /255
// (the format has no colour management), nearest texel, clamped at the
// edges; the north pole of a sphere is the top row of its texture.
#pragma once

#include <stdint.h>

#include "core/base/tile_mask.hpp"
#include "formats/model/scene.hpp"

namespace minrt::general {

inline constexpr double kCheckerScale = 2.0;  // side of a square, scene units
inline constexpr double kBumpStrength = 0.8;  // normal tilt per unit of height difference

// Where a unit vector q from a sphere's centre falls on its texture.
template <class R>
struct SphereTexel {
  int32_t col, row;
};

template <class M>
SphereTexel<typename M::real> sphere_texel(const Vec3<typename M::real>& q, const model::Texture& tex) {
  using R = typename M::real;
  constexpr R kPi = static_cast<R>(3.14159265358979323846);
  const R lon = M::atan2(q.x, q.z);
  const R lat = M::atan2(q.y, M::sqrt(q.x * q.x + q.z * q.z));
  const R u = R(1) - (lon + kPi) / (R(2) * kPi);  // 0..1, west to east
  const R v = R(0.5) - lat / kPi;                 // 0 at the north pole
  auto index = [](R f, int32_t n) {
    const R x = M::floor(f * M::from_int(n));
    if (!(x > R(0))) return int32_t{0};  // NaN too
    if (x >= M::from_int(n - 1)) return n - 1;
    return M::to_int(x);
  };
  return {index(u, tex.width), index(v, tex.height)};
}

inline const uint8_t* texel_at(const model::Texture& tex, int32_t col, int32_t row) {
  return tex.rgb + 3 * (static_cast<uint32_t>(row) * static_cast<uint32_t>(tex.width) + static_cast<uint32_t>(col));
}

// The texels a render reads, per texture (known by its texels' address):
// host-send records them to send only those (sparse textures), and a board
// that holds sparse textures checks each read against the tiles it got.
// Only the tracer's paths compiled with kTexelWatch (features.hpp) consult
// it, through read_texel; every other path reads texels as before.
struct TexelWatch {
  struct Entry {
    const uint8_t* rgb;
    int32_t width;
    uint8_t* marks;  // recording: one byte a texel, set to 1 when read
    TileMask tiles;  // checking (bits set): the tiles the board got
  };
  Entry* entries = nullptr;
  int32_t count = 0;
  // Checking: the first read of a texel not sent.
  bool missed = false;
  int32_t miss_entry = 0, miss_col = 0, miss_row = 0;

  void note(const model::Texture& tex, int32_t col, int32_t row) {
    for (int32_t i = 0; i < count; ++i) {
      const Entry& e = entries[i];
      if (e.rgb != tex.rgb) continue;
      if (e.marks != nullptr) {
        e.marks[static_cast<uint32_t>(row) * static_cast<uint32_t>(e.width) + static_cast<uint32_t>(col)] = 1;
      } else if (e.tiles.bits != nullptr && !missed) {
        if (!e.tiles.has(static_cast<uint32_t>(col), static_cast<uint32_t>(row))) {
          missed = true;
          miss_entry = i;
          miss_col = col;
          miss_row = row;
        }
      }
      return;
    }
  }
};

// The watch the kTexelWatch paths report to; set by whoever renders on
// such a path (one render at a time: host-send's recording, the board).
inline TexelWatch* g_texel_watch = nullptr;

// A texel's bytes, noted in the watch on the paths that have it. Always
// inlined: without the watch it is the address arithmetic alone.
template <bool kWatch>
[[gnu::always_inline]] inline const uint8_t* read_texel(const model::Texture& tex, int32_t col, int32_t row) {
  if constexpr (kWatch) g_texel_watch->note(tex, col, row);
  return tex.rgb + 3 * (static_cast<uint32_t>(row) * static_cast<uint32_t>(tex.width) + static_cast<uint32_t>(col));
}

template <class M>
Vec3<typename M::real> sphere_colour(const Vec3<typename M::real>& q, const model::Texture& tex) {
  using R = typename M::real;
  const SphereTexel<R> at = sphere_texel<M>(q, tex);
  const uint8_t* c = texel_at(tex, at.col, at.row);
  const R k = R(1) / R(255);
  return {M::from_int(c[0]) * k, M::from_int(c[1]) * k, M::from_int(c[2]) * k};
}

// The outward normal q of a sphere tilted by the height map's slope:
// central differences across the texel (wrapping east-west, clamped at the
// poles) along the east and south tangents.
template <class M>
Vec3<typename M::real> bumped_normal(const Vec3<typename M::real>& q, const model::Texture& tex) {
  using R = typename M::real;
  const SphereTexel<R> at = sphere_texel<M>(q, tex);
  auto height = [&](int32_t col, int32_t row) {
    col = col < 0 ? tex.width - 1 : col >= tex.width ? 0 : col;
    row = row < 0 ? 0 : row >= tex.height ? tex.height - 1 : row;
    return M::from_int(texel_at(tex, col, row)[0]) * (R(1) / R(255));
  };
  const R du = height(at.col + 1, at.row) - height(at.col - 1, at.row);
  const R dv = height(at.col, at.row + 1) - height(at.col, at.row - 1);
  const R rho2 = q.x * q.x + q.z * q.z;
  if (!(rho2 > R(0))) return q;  // a pole: no tangent plane orientation
  const R rho = M::sqrt(rho2);
  const Vec3<R> east{-q.z / rho, R(0), q.x / rho};
  const Vec3<R> south{q.y * q.x / rho, -rho, q.y * q.z / rho};
  const R k = static_cast<R>(kBumpStrength);
  return normalize<M>(q - (east * du + south * dv) * k);
}

// The checkerboard: the colour on one set of squares, its complement
// (1 - c) on the other, squares aligned to a basis of the plane.
template <class M>
Vec3<typename M::real> checker_colour(const model::Plane<typename M::real>& pl, const Vec3<typename M::real>& n,
                                      const Vec3<typename M::real>& p, const Vec3<typename M::real>& c) {
  using R = typename M::real;
  const R ny = n.y < R(0) ? -n.y : n.y;
  const Vec3<R> helper = ny < R(0.9) ? Vec3<R>{R(0), R(1), R(0)} : Vec3<R>{R(1), R(0), R(0)};
  const Vec3<R> e1 = normalize<M>(cross(n, helper));
  const Vec3<R> e2 = cross(n, e1);
  const Vec3<R> rel = p - pl.point;
  const R inv = R(1) / static_cast<R>(kCheckerScale);
  const R sum = M::floor(dot(rel, e1) * inv) + M::floor(dot(rel, e2) * inv);
  const R odd = sum - R(2) * M::floor(sum * R(0.5));  // 0 or 1, no integer conversion
  if (odd == R(0)) return c;
  return Vec3<R>{R(1) - c.x, R(1) - c.y, R(1) - c.z};
}

}  // namespace minrt::general
