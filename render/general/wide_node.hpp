// The nodes of an eight-wide bounding-volume hierarchy, collapsed from the
// binary one (wide_bvh.hpp): each node keeps its eight children's boxes side
// by side in single precision, one array per bound and axis, so that one ray
// is tested against all eight in a single pass of the same arithmetic, which
// the compiler turns into vector instructions (eight floats in one AVX
// register, two SSE2 registers on any x86-64). The boxes are rounded
// outward and the test is made conservative (wide_traversal.hpp), so a
// float box never culls what the binary tree's box test keeps; the leaves
// are the binary tree's ranges of its reference array and are tested in
// the tracer's own precision. Built on 64-bit hosts; the board keeps the
// binary tree, whose traversal its instruction counts were measured with
// and whose nodes take less memory.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/arena.hpp"
#include "render/general/sun_grid.hpp"

namespace minrt::general {

// Whether the renderer builds and walks the wide tree.
inline constexpr bool kWideBvh = sizeof(void*) >= 8;

inline constexpr int kWideArity = 8;
// The most nodes a wide tree has: the nearest-hit walk's stack keys name a
// node and a lane in 32 bits (wide_traversal.hpp).
inline constexpr uint32_t kWideMaxNodes = 1u << 29;

// Whatever the tracer's precision: half the bytes of doubles, twice the
// boxes per vector.
using WideBox = float;

struct WideNode {
  // lo/hi[axis][child]: the children's boxes, side by side.
  WideBox lo[3][kWideArity];
  WideBox hi[3][kWideArity];
  uint32_t child[kWideArity];  // an inner child's node, or a leaf's first reference
  uint16_t count[kWideArity];  // a leaf's references; 0 for an inner child
  uint32_t used_mask;          // bit k set: child k is set
  uint32_t leaf_mask;          // bit k set: child k is a leaf
  uint32_t pad[2];             // to kWideNodeBytes
};
// Four 64-byte cache lines: the nodes start on a line (wide_bvh.hpp), so
// a node's boxes are three whole lines.
inline constexpr size_t kWideNodeBytes = 256;
inline constexpr size_t kCacheLine = 64;
static_assert(sizeof(WideNode) == kWideNodeBytes, "whole cache lines");

// Where in a node the eight children's low (high: true) bounds along `axis`
// start, in bytes: the walks load a ray's near and far bounds from there.
inline constexpr uint32_t wide_bound_at(int axis, bool high) {
  return static_cast<uint32_t>((high ? offsetof(WideNode, hi) : offsetof(WideNode, lo)) +
                               sizeof(WideBox) * kWideArity * static_cast<size_t>(axis));
}

// The spheres' centres and squared radii by position in the BVH's reference
// array (sphere_lanes.hpp), so that a leaf's spheres load as vectors; other
// primitives' positions hold a negative squared radius, which no ray meets.
// Padded to whole vector groups.
template <class R>
struct SphereLanes {
  const R* x = nullptr;
  const R* y = nullptr;
  const R* z = nullptr;
  const R* r2 = nullptr;  // nullptr: not built
};

template <class R>
struct WideBvh {
  const WideNode* nodes = nullptr;
  uint32_t node_count = 0;  // 0: walk the binary tree
  SphereLanes<R> spheres{};
  const SunGrid<R>* sun_grids = nullptr;  // by light, for the first sun_grid_count lights
  uint32_t sun_grid_count = 0;
  bool avx2 = false;  // walk with the AVX2 copy (simd_dispatch.hpp)
  bool packets = false;  // CS418's primary rays in packets (packet_row.hpp)
};

// What Bvh keeps of the wide tree: the tree on the hosts that build it,
// nothing on the others.
struct NoWideBvh {};
template <class R, bool kBuilt = kWideBvh>
struct WideSlotOf {
  using type = WideBvh<R>;
};
template <class R>
struct WideSlotOf<R, false> {
  using type = NoWideBvh;
};
template <class R>
using WideSlot = typename WideSlotOf<R>::type;

// Sphere lane arrays hold this many positions past the last reference.
inline constexpr uint32_t kSphereLanePad = 4;

// Arena bytes of the wide tree over n primitives (no more nodes than the
// binary tree has, and room to start them on a cache line) and its sphere
// lanes, and the sun grids (sun_grid.hpp).
template <class R>
constexpr size_t wide_bvh_footprint(uint32_t n) {
  return kWideBvh ? Arena::footprint<WideNode>(2 * static_cast<size_t>(n) + 1) + kCacheLine +
                        4 * Arena::footprint<R>(static_cast<size_t>(n) + kSphereLanePad) + sun_grid_footprint<R>(n)
                  : 0;
}

}  // namespace minrt::general
