// A scene as the SLD file states it, before any preprocessing. Fixed-size
// storage bounded by limits.hpp, so reading a scene allocates nothing.
#pragma once

#include <stdint.h>

#include "formats/sld/sld_limits.hpp"

#include "core/base/diagnostic.hpp"

namespace minrt {

// Shape codes as the original dispatches on them (its comments number them
// differently): 1 box, 2 plane, 3 quadric (x'Ax = 1), 4 cone (x'Ax = 0).
// Any other code falls through to the quadric solver without the "-1".
enum Form : int32_t { kFormBox = 1, kFormPlane = 2, kFormQuadric = 3, kFormCone = 4 };
enum Texture : int32_t {
  kTextureNone = 0,
  kTextureChecker = 1,
  kTextureStripes = 2,
  kTextureRings = 3,
  kTextureSpots = 4
};
enum Reflection : int32_t { kReflectDiffuse = 0, kReflectGlossy = 1, kReflectMirror = 2 };

template <class R>
struct SceneObject {
  // Integers are kept saturated to 32 bits: the renderer only compares them
  // with small codes, so saturation preserves every decision.
  int32_t texture = 0;
  int32_t form = 0;
  int32_t reflection = 0;
  int32_t rotated = 0;  // nonzero: three rotation angles follow
  R abc[3] = {};
  R center[3] = {};
  bool inverted = false;  // the "polarity" field was negative
  R diffuse = 0;
  R hilight = 0;
  R color[3] = {};
  R rotation_deg[3] = {};
  SourcePos pos;  // where the object's line starts
};

template <class R>
struct Scene {
  R screen[3] = {};
  R screen_rotation_deg[2] = {};
  int32_t light_count = 0;  // read but unused, as in the original
  R light_rotation_deg[2] = {};
  R beam = 0;

  int object_count = 0;
  SceneObject<R> objects[limits::kMaxObjects];

  // Networks keep the original's -1 terminator after the last entry, and the
  // OR matrix its terminating row (first entry -1).
  int and_count = 0;
  int16_t and_nets[limits::kMaxAndNetworkDefinitions + 1][limits::kMaxAndNetworkLength + 1];
  int or_count = 0;
  int16_t or_nets[limits::kMaxOrNetworks + 1][limits::kMaxOrNetworkLength + 1];
};

}  // namespace minrt
