// A ray and the nearest hit found so far, for the general tracer.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"

namespace minrt::general {

template <class R>
struct Ray {
  Vec3<R> origin;
  Vec3<R> dir;  // unit length
};

// Farther than anything in a scene, yet finite in float too: the distance
// a walk looks up to before it has a hit, or a sun's shadow ray always.
template <class R>
inline constexpr R kFarDistance = static_cast<R>(3.0e38f);

// What a hit is on: an index into the scene's array of that kind.
enum class HitKind : uint8_t { kNone, kSphere, kPlane, kTriangle, kSolid };

template <class R>
struct Hit {
  R t;
  HitKind kind = HitKind::kNone;
  uint32_t index = 0;
  uint32_t order = 0;  // file order: on equal t the later object wins
  R b1 = R(0), b2 = R(0);  // triangle barycentrics
  uint8_t part = 0;        // solid: side or which cap (solid_intersect.hpp)

  // CS418's tie rule (SPEC.md 1.3): equal distance, later object.
  bool closer(R t2, uint32_t order2) const {
    return kind == HitKind::kNone || t2 < t || (t2 == t && order2 > order);
  }
  // How far a walk still looks for a closer hit.
  R limit() const { return kind == HitKind::kNone ? kFarDistance<R> : t; }
  // Takes the candidate if it is closer (by the rule above); says whether.
  bool offer(R t2, HitKind kind2, uint32_t index2, uint32_t order2) {
    if (!closer(t2, order2)) return false;
    t = t2;
    kind = kind2;
    index = index2;
    order = order2;
    return true;
  }
};

}  // namespace minrt::general
