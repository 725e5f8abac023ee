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
#include "formats/model/quadric.hpp"
#include "formats/model/scene.hpp"

namespace minrt::eastray {

inline constexpr int32_t kNone = model::kNoNode;  // no node, material or item
inline constexpr int kNameBytes = 32;
inline constexpr int kOutputNameBytes = 256;

enum class LightKind : uint8_t { kInfinite, kPoint, kSpot };

template <class R>
struct Light {
  LightKind kind;
  bool no_shadow;
  Vec3<R> position;   // point, spot
  Vec3<R> direction;  // infinite: toward the light; spot: where it shines (both unit)
  Vec3<R> color;
  R size_deg, concentration;  // infinite: the visible disc
  R spread, half_distance;    // spot spread; point and spot fall-off (<= 0: none)
  R shadow_range;             // < 0: shadows at any distance
};

// Specular algorithms of the manual (lines 402-531).
enum class Specular : uint8_t { kBlinn = 0, kBlinnGauss = 1, kAniso1 = 2, kAniso2 = 3, kCookTorrance = 4, kConstant = 5 };

template <class R>
struct Material {
  char name[kNameBytes];
  Vec3<R> diffuse, reflect, transmit;
  R ior, half_distance, bump;
  Specular specular;
  // kBlinn: p[0] intensity, p[1] exponent. kBlinnGauss: rgb, p[3] spread,
  // p[4] Fresnel constant. kCookTorrance: rgb, p[3] ratio, p[4] spread 1,
  // p[5] spread 2. kConstant: color1 p[0..2], color2 p[3..5], p[6] k.
  R p[8];
};

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

template <class R>
struct Scene {
  // display (lines 63-80)
  int32_t width = 256, height = 240, x0 = 0, y0 = 0, x1 = 255, y1 = 239, step_x = 1, step_y = 1;
  R aspect = R(1);
  // condition (84-92)
  int32_t max_depth = 4;
  R min_weight = R(0.01), eps = R(0.00001);
  bool inner = false;
  // anti (94-103)
  int32_t anti = 0;
  R anti_level = R(0);
  // camera (105-117)
  Vec3<R> eye{R(0), R(0), R(10)}, look{}, up_point{R(0), R(10), R(0)};
  R fov = R(30), parallax = R(0);
  // mist, sky, env, shadow, voxel
  R mist_half = R(0);
  bool mist_to_sky = false;
  Vec3<R> sky{}, env{};
  bool shadows = true;
  int32_t voxel = 0;
  char output[kOutputNameBytes] = {};

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
  // A bounding-volume hierarchy over the triangles, when one was built
  // (render/general/eastray_bvh.hpp); without it every ray tests them all.
  const void* triangle_bvh_nodes = nullptr;
  const uint32_t* triangle_bvh_refs = nullptr;
  int32_t triangle_bvh_node_count = 0;
  // A hierarchy over the main obj's objects by their world bounds, and the
  // objects unbounded on some side, tested by every ray
  // (render/general/eastray_object_bvh.hpp); without it every ray walks
  // the whole tree. Both hold node ids.
  const void* object_bvh_nodes = nullptr;
  const uint32_t* object_bvh_refs = nullptr;
  int32_t object_bvh_node_count = 0;
  const int32_t* unbounded_objects = nullptr;
  int32_t unbounded_count = 0;

  // How many items of each kind the arrays hold.
  struct Capacities {
    int32_t lights, materials, primitives, nodes, triangles, vertices;

    // The same number for every kind.
    static constexpr Capacities all(int32_t n) { return {n, n, n, n, n, n}; }
    // For a scene text of `bytes` bytes on the host: every item takes some
    // text (a vertex at least 10 bytes, a triangle 6, an object 16, a light
    // or a colour 20), with floors that leave room for parts called many
    // times; a scene that needs more is told which kind did not fit.
    static constexpr Capacities for_text(size_t bytes) {
      const auto at_least = [](size_t v, int32_t floor) {
        return v > 0x3fffffff ? 0x3fffffff : (static_cast<int32_t>(v) > floor ? static_cast<int32_t>(v) : floor);
      };
      return {at_least(bytes / 20, 1024), at_least(bytes / 20, 1024), at_least(bytes / 16, 16384),
              at_least(bytes / 8, 32768), at_least(bytes / 6, 16384), at_least(bytes / 10, 16384)};
    }
  };

  static constexpr size_t bytes_for(const Capacities& c) {
    return Arena::footprint<Light<R>>(c.lights) + Arena::footprint<Material<R>>(c.materials) +
           Arena::footprint<Primitive<R>>(c.primitives) + Arena::footprint<Node>(c.nodes) +
           Arena::footprint<Triangle<R>>(c.triangles) + Arena::footprint<MeshFace>(c.triangles) + 2 * Arena::footprint<Vec3<R>>(c.vertices) +
           Arena::footprint<int32_t>(c.vertices);
  }

  bool allocate(Arena& arena, const Capacities& c) {
    lights = arena.alloc_zeroed<Light<R>>(static_cast<size_t>(c.lights));
    materials = arena.alloc_zeroed<Material<R>>(static_cast<size_t>(c.materials));
    primitives = arena.alloc_zeroed<Primitive<R>>(static_cast<size_t>(c.primitives));
    nodes = arena.alloc_zeroed<Node>(static_cast<size_t>(c.nodes));
    triangles = arena.alloc_zeroed<Triangle<R>>(static_cast<size_t>(c.triangles));
    faces = arena.alloc_zeroed<MeshFace>(static_cast<size_t>(c.triangles));
    vertices = arena.alloc_zeroed<Vec3<R>>(static_cast<size_t>(c.vertices));
    vertex_normals = arena.alloc_zeroed<Vec3<R>>(static_cast<size_t>(c.vertices));
    vertex_ids = arena.alloc_zeroed<int32_t>(static_cast<size_t>(c.vertices));
    light_capacity = c.lights;
    material_capacity = c.materials;
    primitive_capacity = c.primitives;
    node_capacity = c.nodes;
    triangle_capacity = c.triangles;
    vertex_capacity = c.vertices;
    return lights != nullptr && materials != nullptr && primitives != nullptr && nodes != nullptr &&
           triangles != nullptr && faces != nullptr && vertices != nullptr && vertex_normals != nullptr && vertex_ids != nullptr;
  }
};

}  // namespace minrt::eastray
