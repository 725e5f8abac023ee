// A scene of Michał Jaworski's ray tracer (SPEC.md 3): spheres and planes
// with surfaces (diffusive, reflective, luminous, and weighted mixtures that
// nest), directional and spherical lights, a pinhole camera behind a canvas.
// Mixtures stay a tree (a linked list of weighted parts per node): the
// original sums them in that order, and a double build must reproduce its
// bytes, so they are not flattened. Plain arrays in the arena, with
// capacities fixed before parsing.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/math/vec3.hpp"

namespace minrt::jaworski {

enum class SurfaceKind : uint8_t { kDiffusive, kReflective, kLuminous, kMixed };

inline constexpr int32_t kNone = -1;

struct Surface {
  SurfaceKind kind;
  int32_t first_part = kNone;  // mixed: its first weighted part
};

template <class R>
struct SurfaceNode {
  Surface s;
  Vec3<R> color;  // diffusive, luminous
};

// One weighted part of a mixture; parts of one mixture are chained by `next`.
template <class R>
struct Part {
  R weight;
  int32_t surface;
  int32_t next = kNone;
};

enum class ShapeKind : uint8_t { kSphere, kPlane };

template <class R>
struct Object {
  ShapeKind kind;
  Vec3<R> point;   // sphere centre, or a point of the plane
  Vec3<R> normal;  // plane: normalised when read (as the original does)
  R radius;
  int32_t surface;
};

enum class LightKind : uint8_t { kDirectional, kSpherical };

template <class R>
struct Light {
  LightKind kind;
  Vec3<R> color;   // intensity x colour
  Vec3<R> vector;  // directional: normalised direction toward the light; spherical: position
};

template <class R>
struct Scene {
  int32_t width = 0, height = 0;
  R canvas_width = R(0), canvas_height = R(0), depth = R(0);
  Vec3<R> background{};
  int32_t ray_depth = 4;

  Object<R>* objects = nullptr;
  int32_t object_count = 0, object_capacity = 0;
  Light<R>* lights = nullptr;
  int32_t light_count = 0, light_capacity = 0;
  SurfaceNode<R>* surfaces = nullptr;
  int32_t surface_count = 0, surface_capacity = 0;
  Part<R>* parts = nullptr;
  int32_t part_count = 0, part_capacity = 0;

  // Capacities for a scene text of `bytes` bytes: every item takes more
  // than two bytes of text.
  static int32_t capacity_for(size_t bytes) { return static_cast<int32_t>(bytes / 2 + 4); }

  bool allocate(Arena& arena, int32_t capacity) {
    objects = arena.alloc_zeroed<Object<R>>(static_cast<size_t>(capacity));
    lights = arena.alloc_zeroed<Light<R>>(static_cast<size_t>(capacity));
    surfaces = arena.alloc_zeroed<SurfaceNode<R>>(static_cast<size_t>(capacity));
    parts = arena.alloc_zeroed<Part<R>>(static_cast<size_t>(capacity));
    object_capacity = light_capacity = surface_capacity = part_capacity = capacity;
    return objects != nullptr && lights != nullptr && surfaces != nullptr && parts != nullptr;
  }
};

}  // namespace minrt::jaworski
