// An EASTRAY scene as the reader leaves it (SPEC.md 4, docs/eastray.md):
// global settings, lights, colours (materials), primitives (the general
// model's quadric solids, formats/model/quadric.hpp), the CSG tree of OR /
// AND / RANGE blocks over them (formats/model/csg.hpp), and the triangles
// of polygon meshes. Plain arrays
// in the arena with capacities fixed before parsing (Capacities: from the
// text's size on the host, with floors for parts called many times; fixed
// on the board).
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/math/vec3.hpp"
#include "formats/model/csg.hpp"
#include "formats/model/eastray_mapping.hpp"
#include "formats/model/eastray_shading.hpp"
#include "formats/model/quadric.hpp"
#include "formats/model/scene.hpp"

namespace minrt::eastray {

inline constexpr int32_t kNone = model::kNoNode;  // no node, material or item
inline constexpr int kNameBytes = model::kColorNameBytes;
inline constexpr int kOutputNameBytes = 256;

// Lights and colours are the general model's (formats/model/eastray_shading.hpp).
using LightKind = model::EastrayLightKind;
template <class R>
using Light = model::EastrayLight<R>;
using model::Specular;
template <class R>
using Material = model::EastrayMaterial<R>;

// The shapes and the CSG tree are the general model's (formats/model).
using model::Affine;
using model::Face;
using model::kFaceBottom;
using model::kFaceBox;
using model::kFaceCount;
using model::kFaceSide;
using model::kFaceTop;
using model::NodeKind;
using Shape = model::QuadricShape;
template <class R>
using Primitive = model::Quadric<R>;
using Node = model::CsgNode;

// Polygon meshes are the general model's triangles (formats/model/scene.hpp),
// with their mesh faces alongside.
template <class R>
using Triangle = model::Triangle<R>;
using MeshFace = model::MeshFace;

// The scene-wide settings (display ... voxel) are the general model's
// EastraySettings, with the manual's defaults.
template <class R>
struct Scene : model::EastraySettings<R> {
  char output[kOutputNameBytes] = {};
  char input[kOutputNameBytes] = {};  // `input`: the background image's file
  int32_t input_line = 0, input_col = 0;

  Light<R>* lights = nullptr;
  int32_t light_count = 0, light_capacity = 0;
  Material<R>* materials = nullptr;
  int32_t material_count = 0, material_capacity = 0;
  Primitive<R>* primitives = nullptr;
  int32_t primitive_count = 0, primitive_capacity = 0;
  Node* nodes = nullptr;
  int32_t node_count = 0, node_capacity = 0;
  Triangle<R>* triangles = nullptr;
  MeshFace* faces = nullptr;           // parallel to triangles
  int32_t triangle_count = 0, triangle_capacity = 0;
  Vec3<R>* vertices = nullptr;         // world positions of mesh vertices
  Vec3<R>* vertex_normals = nullptr;   // weighted sums of smooth faces' normals
  int32_t* vertex_ids = nullptr;       // the ids as written
  int32_t vertex_count = 0, vertex_capacity = 0;
  int32_t root = kNone;                // the main obj's kTop node
  // Mapping (formats/model/eastray_mapping.hpp).
  model::EastrayMapFile* map_files = nullptr;
  int32_t map_file_count = 0, map_file_capacity = 0;
  model::EastrayMapping<R>* mappings = nullptr;
  int32_t mapping_count = 0, mapping_capacity = 0;
  model::EastrayMappedObject<R>* mapped_objects = nullptr;
  int32_t mapped_count = 0, mapped_capacity = 0;

  // How many items of each kind the arrays hold.
  struct Capacities {
    int32_t lights, materials, primitives, nodes, triangles, vertices;
    int32_t map_files, mappings, mapped;

    // The same number for every kind.
    static constexpr Capacities all(int32_t n) { return {n, n, n, n, n, n, n, n, n}; }
    // Twice as many of every kind (the host grows them when a table is full).
    constexpr Capacities doubled() const {
      auto twice = [](int32_t v) { return v > 0x3fffffff ? 0x7fffffff : 2 * v; };
      return {twice(lights),    twice(materials), twice(primitives), twice(nodes), twice(triangles),
              twice(vertices),  twice(map_files), twice(mappings),   twice(mapped)};
    }
    // For a scene text of `bytes` bytes on the host: every item takes some
    // text (a vertex at least 10 bytes, a triangle 6, an object 16, a light
    // or a colour 20), with floors that leave room for parts called many
    // times; a scene that needs more is told which kind did not fit.
    static constexpr Capacities for_text(size_t bytes) {
      const auto at_least = [](size_t v, int32_t floor) {
        return v > 0x3fffffff ? 0x3fffffff : (static_cast<int32_t>(v) > floor ? static_cast<int32_t>(v) : floor);
      };
      // A map_data entry takes at least 8 bytes, a mapping entry 12, a
      // mapped object 16 (it is an object).
      return {at_least(bytes / 20, 1024), at_least(bytes / 20, 1024), at_least(bytes / 16, 16384),
              at_least(bytes / 8, 32768),  at_least(bytes / 6, 16384),  at_least(bytes / 10, 16384),
              at_least(bytes / 8, 256),    at_least(bytes / 12, 1024),  at_least(bytes / 16, 16384)};
    }
  };

  static constexpr size_t bytes_for(const Capacities& c) {
    return Arena::footprint<Light<R>>(c.lights) + Arena::footprint<Material<R>>(c.materials) +
           Arena::footprint<Primitive<R>>(c.primitives) + Arena::footprint<Node>(c.nodes) +
           Arena::footprint<Triangle<R>>(c.triangles) + Arena::footprint<MeshFace>(c.triangles) + 2 * Arena::footprint<Vec3<R>>(c.vertices) +
           Arena::footprint<int32_t>(c.vertices) + Arena::footprint<model::EastrayMapFile>(c.map_files) +
           Arena::footprint<model::EastrayMapping<R>>(c.mappings) +
           Arena::footprint<model::EastrayMappedObject<R>>(c.mapped);
  }

  // The arrays are sized for the worst case of the text and not zeroed:
  // the reader writes each item whole as it counts it, and nothing reads
  // past the counts, so set-up costs what the scene uses.
  bool allocate(Arena& arena, const Capacities& c) {
    lights = arena.alloc_uninit<Light<R>>(static_cast<size_t>(c.lights));
    materials = arena.alloc_uninit<Material<R>>(static_cast<size_t>(c.materials));
    primitives = arena.alloc_uninit<Primitive<R>>(static_cast<size_t>(c.primitives));
    nodes = arena.alloc_uninit<Node>(static_cast<size_t>(c.nodes));
    triangles = arena.alloc_uninit<Triangle<R>>(static_cast<size_t>(c.triangles));
    faces = arena.alloc_uninit<MeshFace>(static_cast<size_t>(c.triangles));
    vertices = arena.alloc_uninit<Vec3<R>>(static_cast<size_t>(c.vertices));
    vertex_normals = arena.alloc_uninit<Vec3<R>>(static_cast<size_t>(c.vertices));
    vertex_ids = arena.alloc_uninit<int32_t>(static_cast<size_t>(c.vertices));
    map_files = arena.alloc_uninit<model::EastrayMapFile>(static_cast<size_t>(c.map_files));
    mappings = arena.alloc_uninit<model::EastrayMapping<R>>(static_cast<size_t>(c.mappings));
    mapped_objects = arena.alloc_uninit<model::EastrayMappedObject<R>>(static_cast<size_t>(c.mapped));
    map_file_capacity = c.map_files;
    mapping_capacity = c.mappings;
    mapped_capacity = c.mapped;
    light_capacity = c.lights;
    material_capacity = c.materials;
    primitive_capacity = c.primitives;
    node_capacity = c.nodes;
    triangle_capacity = c.triangles;
    vertex_capacity = c.vertices;
    return lights != nullptr && materials != nullptr && primitives != nullptr && nodes != nullptr &&
           triangles != nullptr && faces != nullptr && vertices != nullptr && vertex_normals != nullptr && vertex_ids != nullptr &&
           map_files != nullptr && mappings != nullptr && mapped_objects != nullptr;
  }
};

}  // namespace minrt::eastray
