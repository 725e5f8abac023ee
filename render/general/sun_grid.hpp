// Shadow rays toward a sun all carry the sun's direction, so which spheres
// can block one depends only on where its origin falls on the plane across
// that direction: a sphere can block it only if the origin lies within the
// sphere's radius of the sphere's centre there. A sun grid lists, for each
// cell of that plane, the spheres whose disc (the radius plus a margin far
// above the rounding of the exact test) reaches the cell; a shadow ray then
// tests only its cell's spheres, with hit_sphere, so its answer is the
// walk's. Built on the hosts that build the wide tree, for scenes whose
// hierarchy holds only spheres; everything else takes the walk.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/math/float_step.hpp"
#include "core/math/vec3.hpp"
#include "formats/model/scene.hpp"
#include "render/general/intersect.hpp"

namespace minrt::general {

// A sphere with how far its far side lies along the sun's direction
// (rounded up), while the grid is built.
struct SunGridItem {
  float far;
  uint32_t sphere;
};

template <class R>
struct SunGrid {
  Vec3<R> dir{};         // the sun's direction as its shadow rays carry it
  Vec3<R> e1{}, e2{};    // across it
  R u0 = R(0), v0 = R(0);
  R per_unit = R(0);     // cells per unit of e1 and e2
  R reach = R(0);        // origins with a coordinate beyond +-reach take the walk
  R margin = R(0);                  // the discs' margin
  uint32_t nu = 0, nv = 0;          // 0: no grid for this light
  const uint32_t* start = nullptr;  // cell c lists items[start[c] .. start[c + 1])
  // A listed sphere in four bytes, so that the lists stay in cache: its
  // index in the low index_bits, above them its far side as a level,
  // (far - far0) * far_scale rounded up. A cell's list runs from the
  // farthest, so a ray stops at the first sphere whose far side is behind
  // its origin.
  const uint32_t* items = nullptr;
  uint32_t index_bits = 0;
  R far0 = R(0), far_scale = R(0);
};

// Lights that may have a grid (the first ones of the scene), and each grid's
// size for n spheres: at most kSunGridCells * n cells and kSunGridItems * n
// listed spheres (larger discs make coarser cells).
inline constexpr uint32_t kSunGridLights = 4;
inline constexpr uint32_t kSunGridCells = 4;
inline constexpr uint32_t kSunGridItems = 32;
// A grid takes about 900 instructions a sphere to build and saves about
// 700 a shadow ray: it is built when the image has at least this many
// samples a sphere (each sample sends about one shadow ray to each sun).
inline constexpr uint32_t kSunGridSamples = 8;
// An item is four bytes: a sphere's index and its far side's level, in at
// most kSunGridLevelBits (levels exact in float), at least 32 less the bits
// of kSunGridMaxSpheres.
inline constexpr uint32_t kSunGridLevelBits = 16;
inline constexpr uint32_t kSunGridMaxSpheres = 1u << 26;
// The margin, in units of the precision's epsilon times the scene's extent:
// the exact test's rounding is a few epsilons of that, the float model's too.
inline constexpr double kSunGridMargin = 8192.0;

template <class R>
constexpr size_t sun_grid_footprint(uint32_t n) {
  const size_t cells = static_cast<size_t>(kSunGridCells) * n + 2;
  return Arena::footprint<SunGrid<R>>(kSunGridLights) +
         kSunGridLights * (Arena::footprint<uint32_t>(cells + 1) +
                           Arena::footprint<uint32_t>(static_cast<size_t>(kSunGridItems) * n)) +
         Arena::footprint<uint32_t>(cells) + Arena::footprint<SunGridItem>(n);  // the fill's scratch
}

namespace sun_grid_detail {

template <class R>
R magnitude(R x) {
  return x < R(0) ? -x : x;
}

// The cell range [lo, hi] along one axis of the interval [a, b] (clamped to
// the grid): the same arithmetic as the look-up, which is monotonic, so a
// point inside the interval falls in a cell of the range.
template <class R>
void cell_range(R a, R b, R origin, R per_unit, uint32_t n, uint32_t& lo, uint32_t& hi) {
  const R fa = (a - origin) * per_unit, fb = (b - origin) * per_unit;
  lo = fa > R(0) ? static_cast<uint32_t>(fa) : 0u;
  hi = fb > R(0) ? static_cast<uint32_t>(fb) : 0u;
  if (lo > n - 1) lo = n - 1;
  if (hi > n - 1) hi = n - 1;
}

// The float at or above v (finite, within float range).
template <class R>
float float_up(R v) {
  const float f = static_cast<float>(v);
  if (!(static_cast<R>(f) < v)) return f;
  return f + float_step_bound(f);
}

// Heap sort, largest `far` first: no recursion, no room beyond the array.
inline void sort_farthest_first(SunGridItem* a, uint32_t n) {
  // A min-heap on far, whose smallest goes to the end each round.
  auto sift = [&](uint32_t at, uint32_t size) {
    for (;;) {
      uint32_t least = at;
      const uint32_t l = 2 * at + 1, r = l + 1;
      if (l < size && a[l].far < a[least].far) least = l;
      if (r < size && a[r].far < a[least].far) least = r;
      if (least == at) return;
      const SunGridItem t = a[at];
      a[at] = a[least];
      a[least] = t;
      at = least;
    }
  };
  for (uint32_t i = n / 2; i-- > 0;) sift(i, n);
  for (uint32_t end = n; end-- > 1;) {
    const SunGridItem t = a[0];
    a[0] = a[end];
    a[end] = t;
    sift(0, end);
  }
}

}  // namespace sun_grid_detail

// One grid for the sun of direction `dir` (normalised) over the scene's
// spheres; false (grid left empty) when the scene does not suit one or the
// arena is too small.
template <class M>
bool build_sun_grid(const model::Scene<typename M::real>& s, const Vec3<typename M::real>& dir, Arena& arena,
                    SunGrid<typename M::real>& g) {
  using R = typename M::real;
  using sun_grid_detail::magnitude;
  g = SunGrid<R>{};
  const uint32_t n = s.sphere_count;
  if (n == 0 || n > kSunGridMaxSpheres) return false;
  // The extent: every centre coordinate and radius within it.
  R extent = R(0);
  for (uint32_t i = 0; i < n; ++i) {
    const model::Sphere<R>& sp = s.spheres[i];
    const R e = magnitude(sp.radius) + largest_component(sp.center);
    if (!(e <= R(1e30f))) return false;  // too large (for a float far side) or not a number
    if (e > extent) extent = e;
  }
  if (!(magnitude(dir.x) <= R(1) && magnitude(dir.y) <= R(1) && magnitude(dir.z) <= R(1))) return false;
  extent = extent + R(1);
  constexpr R kEpsilon = sizeof(R) >= 8 ? static_cast<R>(2.220446049250313e-16) : static_cast<R>(1.1920929e-7f);
  const R margin = extent * kEpsilon * static_cast<R>(kSunGridMargin);
  g.dir = dir;
  g.reach = R(4) * extent;
  const Vec3<R> away = magnitude(dir.x) < R(0.6f) ? Vec3<R>{R(1), R(0), R(0)} : Vec3<R>{R(0), R(1), R(0)};
  g.e1 = normalize<M>(cross(dir, away));
  g.e2 = cross(dir, g.e1);
  R ulo = R(0), uhi = R(0), vlo = R(0), vhi = R(0);
  for (uint32_t i = 0; i < n; ++i) {
    const model::Sphere<R>& sp = s.spheres[i];
    const R u = dot(sp.center, g.e1), v = dot(sp.center, g.e2), r = magnitude(sp.radius) + margin;
    if (i == 0 || u - r < ulo) ulo = u - r;
    if (i == 0 || u + r > uhi) uhi = u + r;
    if (i == 0 || v - r < vlo) vlo = v - r;
    if (i == 0 || v + r > vhi) vhi = v + r;
  }
  g.u0 = ulo;
  g.v0 = vlo;
  // Cells about as many as kSunGridCells a sphere, coarser while the lists
  // would hold more than kSunGridItems a sphere.
  const R width = uhi - ulo, height = vhi - vlo;
  R cell = M::sqrt(width * height / M::from_int(static_cast<int32_t>(kSunGridCells * n)));
  if (!(cell > R(0))) cell = (width > height ? width : height) + margin;
  // The cells sphere i's disc reaches, on the grid as it stands.
  auto disc_cells = [&](uint32_t i, uint32_t& ua, uint32_t& ub, uint32_t& va, uint32_t& vb) {
    const model::Sphere<R>& sp = s.spheres[i];
    const R u = dot(sp.center, g.e1), v = dot(sp.center, g.e2), r = magnitude(sp.radius) + margin;
    sun_grid_detail::cell_range(u - r, u + r, g.u0, g.per_unit, g.nu, ua, ub);
    sun_grid_detail::cell_range(v - r, v + r, g.v0, g.per_unit, g.nv, va, vb);
  };
  const uint64_t max_cells = static_cast<uint64_t>(kSunGridCells) * n + 1;
  const uint64_t max_items = static_cast<uint64_t>(kSunGridItems) * n;
  uint64_t items = 0;
  for (int tries = 0;; ++tries) {
    if (tries == 64) return false;
    g.per_unit = R(1) / cell;
    const R fu = width * g.per_unit, fv = height * g.per_unit;
    if (fu < R(65536) && fv < R(65536)) {
      g.nu = static_cast<uint32_t>(fu) + 1;
      g.nv = static_cast<uint32_t>(fv) + 1;
      if (static_cast<uint64_t>(g.nu) * g.nv <= max_cells) {
        items = 0;
        for (uint32_t i = 0; i < n && items <= max_items; ++i) {
          uint32_t ua, ub, va, vb;
          disc_cells(i, ua, ub, va, vb);
          items += static_cast<uint64_t>(ub - ua + 1) * (vb - va + 1);
        }
        if (items <= max_items) break;
      }
    }
    cell = cell * R(1.5f);
  }
  const size_t cells = static_cast<size_t>(g.nu) * g.nv;
  // The fill's cursors and order are scratch at the arena's top end.
  const size_t mark = arena.top_mark();
  uint32_t* cursor = arena.alloc_top<uint32_t>(cells);
  auto* order = arena.alloc_top<SunGridItem>(n);
  uint32_t* start = arena.alloc_zeroed<uint32_t>(cells + 1);
  auto* list = arena.alloc_uninit<uint32_t>(items > 0 ? static_cast<size_t>(items) : 1);
  if (start == nullptr || list == nullptr || cursor == nullptr || order == nullptr) {
    arena.release_top(mark);
    g = SunGrid<R>{};
    return false;
  }
  // The spheres from the farthest far side, so that each cell's list,
  // filled in this order, runs from the farthest too.
  for (uint32_t i = 0; i < n; ++i)
    order[i] = SunGridItem{
        sun_grid_detail::float_up(dot(s.spheres[i].center, g.dir) + magnitude(s.spheres[i].radius) + margin), i};
  sun_grid_detail::sort_farthest_first(order, n);
  // The far sides as levels: index_bits for the largest index, up to
  // kSunGridLevelBits of the rest for the level (exact in float). The
  // scale maps the far sides onto 0 .. top - 1, so that its rounding
  // leaves every level at or below the top.
  uint32_t bits = 1;
  while ((n - 1) >> bits != 0) ++bits;
  const uint32_t level_bits = 32 - bits < kSunGridLevelBits ? 32 - bits : kSunGridLevelBits;
  const uint32_t top = (1u << level_bits) - 1u;
  const R far0 = static_cast<R>(order[n - 1].far), span = static_cast<R>(order[0].far) - far0;
  R far_scale = span > R(0) ? static_cast<R>(top - 1) / span : R(0);
  // Far sides too close together for a finite scale share level 0: no ray
  // stops early, none stops wrongly.
  if (!(far_scale < R(1e30f))) far_scale = R(0);
  auto level = [&](float far) {
    const R q = (static_cast<R>(far) - far0) * far_scale;
    uint32_t l = q > R(0) ? static_cast<uint32_t>(q) : 0u;
    if (static_cast<R>(l) < q) ++l;  // up: a level never below its far side's
    return l < top ? l : top;
  };
  // Count, then place each sphere in its cells.
  for (int pass = 0; pass < 2; ++pass) {
    for (uint32_t o = 0; o < n; ++o) {
      uint32_t ua, ub, va, vb;
      disc_cells(order[o].sphere, ua, ub, va, vb);
      for (uint32_t cv = va; cv <= vb; ++cv)
        for (uint32_t cu = ua; cu <= ub; ++cu) {
          const size_t c = static_cast<size_t>(cv) * g.nu + cu;
          if (pass == 0) ++start[c + 1];
          else list[cursor[c]++] = level(order[o].far) << bits | order[o].sphere;
        }
    }
    if (pass == 0) {
      for (size_t c = 0; c < cells; ++c) {
        start[c + 1] += start[c];
        cursor[c] = start[c];
      }
    }
  }
  arena.release_top(mark);
  g.margin = margin;
  g.start = start;
  g.items = list;
  g.index_bits = bits;
  g.far0 = far0;
  g.far_scale = far_scale;
  return true;
}

// Whether the grid answers for this shadow ray: the sun's direction, an
// origin within reach (not a NaN).
template <class R>
[[gnu::always_inline]] inline bool sun_grid_covers(const SunGrid<R>& g, const Ray<R>& ray) {
  return g.nu != 0 && ray.dir.x == g.dir.x && ray.dir.y == g.dir.y && ray.dir.z == g.dir.z &&
         ray.origin.x >= -g.reach && ray.origin.x <= g.reach && ray.origin.y >= -g.reach &&
         ray.origin.y <= g.reach && ray.origin.z >= -g.reach && ray.origin.z <= g.reach;
}

// The spheres that may block a ray the grid covers: calls `blocks(index)`
// for each sphere listed in the origin's cell, but those wholly behind the
// origin (which hit_sphere misses: the origin outside, the centre behind),
// until one says true.
template <class R, class Blocks>
[[gnu::always_inline]] inline bool sun_grid_any(const SunGrid<R>& g, const Vec3<R>& origin, Blocks blocks) {
  const R fu = (dot(origin, g.e1) - g.u0) * g.per_unit, fv = (dot(origin, g.e2) - g.v0) * g.per_unit;
  // Outside the grid is beyond every disc (the origin is finite here).
  if (!(fu >= R(0) && fv >= R(0) && fu < static_cast<R>(g.nu) && fv < static_cast<R>(g.nv))) return false;
  const uint32_t cu = static_cast<uint32_t>(fu), cv = static_cast<uint32_t>(fv);
  const size_t c = static_cast<size_t>(cv) * g.nu + cu;
  // The level of the plane behind the origin, by the arithmetic of the
  // levels, which is monotonic: a sphere's level below it has its far
  // side below the plane.
  const R behind = (dot(origin, g.dir) - g.margin - g.far0) * g.far_scale;
  const uint32_t mask = (1u << g.index_bits) - 1u;
  for (uint32_t k = g.start[c], end = g.start[c + 1]; k < end; ++k) {
    const uint32_t item = g.items[k];
    if (static_cast<R>(item >> g.index_bits) < behind) return false;
    if (blocks(item & mask)) return true;
  }
  return false;
}

}  // namespace minrt::general
