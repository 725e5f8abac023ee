// EASTRAY's mappings as the general model carries them (manual lines
// 369-398 and 597-673; docs/eastray.md, "Mapping"): the images `map_data`
// names, the mapping entries `< ... >` that follow a colour's parameters or
// an object's colour number, and the mapped objects (an object whose
// colour is mapped keeps its own frame, where its mappings are evaluated).
// The reader (formats/eastray) fills them; the host loads the images
// (host/eastray_maps.cpp); render/general/eastray_mapping.hpp evaluates.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"
#include "formats/model/quadric.hpp"

namespace minrt::model {

inline constexpr int kMapFileBytes = 256;
// Halved images kept of a map read with mip 1 (line 398): enough for a
// 65536-texel side to reach one texel.
inline constexpr int kMipLevels = 16;
inline constexpr int32_t kNoMapping = -1;

// One `map_data` entry: the file as written and the mip-mapping switch.
struct EastrayMapFile {
  char name[32];
  char file[kMapFileBytes];
  bool mip;
  int32_t line, col;  // where the file name stands (the expanded text's)
};

// Projection modes 0-4 (10-14 are the same with `filtered`).
enum class EastrayMapMode : uint8_t { kAllDirections = 0, kPlane = 1, kSphere = 2, kRing = 3, kCylinder = 4 };

// One entry of a mapping block. Entries of the same parameter are chained
// by `next` in the order written.
template <class R>
struct EastrayMapping {
  Affine<R> to_map;    // the object's frame -> the mapping's (its moves undone)
  Affine<R> from_map;  // its moves (normals go to the mapping by the transpose)
  int32_t image;     // map_data number
  int32_t next;      // next entry of the same parameter, or kNoMapping
  R scale;           // multiplies the image's 0..1 values (line 668)
  EastrayMapMode mode;
  bool filtered;     // modes 10-14: bilinear between texels, no jaggies (line 673)
  // kAllDirections: k in u1. Others: the image spans (u1,v1)-(u2,v2) and
  // repeats over (ua1,va1)-(ua2,va2).
  R u1, v1, u2, v2, ua1, va1, ua2, va2;
};

// Parameter slots a mapping can follow (the colour's fields in order; the
// specular parameters by their index in EastrayMaterial::p).
enum EastrayMapSlot : uint8_t {
  kMapDiffuse = 0, kMapReflect, kMapTransmit, kMapIor, kMapHalf, kMapBump, kMapSpecular  // + p index
};
inline constexpr int kSpecularParams = 12;
inline constexpr int kMapSlots = kMapSpecular + kSpecularParams;

// An object placed with a mapped colour or a colour-number mapping: its
// surfaces name `material_count + index` instead of the colour.
template <class R>
struct EastrayMappedObject {
  Affine<R> to_object;   // world -> the frame the object was written in
  Affine<R> to_world;    // its moves (normals go to its frame by the transpose)
  int32_t material;      // the colour number as written
  int32_t number_map;    // colour-number mapping chain, or kNoMapping
};

}  // namespace minrt::model
