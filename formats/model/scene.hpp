// The general scene model: what every front end but SLD produces (CS418 now;
// Jaworski, miniRT and EASTRAY build on it) and what render/general draws.
// Plain arrays in the arena, sized after parsing (scene_builder.hpp), so the
// same structure serves the host and the board. Objects keep their file
// order in `order`: CS418 lets the later object win a tie in distance.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"
#include "formats/model/csg.hpp"
#include "formats/model/eastray_shading.hpp"
#include "formats/model/quadric.hpp"
#include "formats/model/solid.hpp"

namespace minrt::model {

inline constexpr int32_t kNoTexture = -1;

// Surface response. Colours are linear and unclamped (negative allowed).
template <class R>
struct Material {
  Vec3<R> color{R(1), R(1), R(1)};
  Vec3<R> shininess{};     // reflected fraction, per channel
  Vec3<R> transparency{};  // refracted fraction of the non-reflected part
  R ior = R(1.458);
  R roughness = R(0);      // sigma of the Gaussian normal perturbation
  int32_t texture = kNoTexture;
  int32_t bump = kNoTexture;  // height map perturbing the normal (miniRT spt)
  bool checker = false;       // checkerboard of the colour and its complement (miniRT plc)
};

template <class R>
struct Sphere {
  Vec3<R> center;
  R radius;
  uint32_t material;
  uint32_t order;
};

// Ax + By + Cz + D = 0: `normal` is (A, B, C) as given, `point` the point of
// the plane nearest the origin.
template <class R>
struct Plane {
  Vec3<R> normal;
  Vec3<R> point;
  uint32_t material;
  uint32_t order;
};

template <class R>
struct Vertex {
  Vec3<R> position;
  R u, v;  // texture coordinates
};

// Precomputed for the barycentric test: n = (p1-p0)x(p2-p0), e1 and e2 such
// that b1 = e1.(p-p0), b2 = e2.(p-p0). p1 and p2 are kept for bounding.
// EASTRAY's meshes (Finish::kEastray) are tested by Moller-Trumbore on the
// edges p1-p0 and p2-p0; their `normal` is the unit face normal, facing
// out, and e1, e2, u and v are not used.
template <class R>
struct Triangle {
  Vec3<R> p0, normal, e1, e2, p1, p2;
  R u[3], v[3];
  uint32_t material;
  uint32_t order;
};

// A triangle's place in a mesh, parallel to the triangles (EASTRAY kind
// 20): its corners' indices into the scene's vertex normals (used when
// `smooth`), and whether it casts shadows.
struct MeshFace {
  int32_t vertex[3];
  bool smooth;
  bool no_shadow;
};

// kPoint: a bulb without falloff (miniRT).
enum class LightKind : uint8_t { kSun, kBulb, kPoint };

template <class R>
struct Light {
  LightKind kind;
  Vec3<R> vector;  // sun: direction toward the light (not normalised); bulb: position
  Vec3<R> color;
};

enum class Projection : uint8_t { kFlat, kFisheye, kPanorama };

template <class R>
struct Camera {
  Vec3<R> eye{};
  Vec3<R> forward{R(0), R(0), R(-1)};  // not normalised: its length zooms
  Vec3<R> right{R(1), R(0), R(0)};
  Vec3<R> up{R(0), R(1), R(0)};
  Projection projection = Projection::kFlat;
  bool depth_of_field = false;
  R focus = R(0);
  R lens = R(0);
};

// A decoded texture: sRGB bytes, 3 per texel, rows top first.
struct Texture {
  int32_t width = 0;
  int32_t height = 0;
  const uint8_t* rgb = nullptr;
};

// How the tracer turns linear light into bytes and what it does at the depth
// limit: per format (SPEC.md 5.1). kMinirt: ambient, Lambert and Phong
// terms, clamp and floor to bytes (render/general/phong_shading.hpp).
// kEastray: EASTRAY's lights and colours (`eastray`), linear bytes, its own
// camera, display window and antialiasing (render/general/eastray_shading.hpp).
enum class Finish : uint8_t { kCs418, kMinirt, kEastray };

template <class R>
struct Scene {
  int32_t width = 0;
  int32_t height = 0;
  int32_t bounces = 4;
  int32_t gi_depth = 0;
  int32_t samples = 1;  // aa
  bool exposure = false;
  R exposure_value = R(0);
  Finish finish = Finish::kCs418;
  Vec3<R> ambient{};  // kMinirt: ratio * colour / 255
  bool specular = true;  // kMinirt: false for the subject's mandatory part (ambient and Lambert only)
  Camera<R> camera;

  const Material<R>* materials = nullptr;
  uint32_t material_count = 0;
  const Sphere<R>* spheres = nullptr;
  uint32_t sphere_count = 0;
  const Plane<R>* planes = nullptr;
  uint32_t plane_count = 0;
  const Triangle<R>* triangles = nullptr;
  uint32_t triangle_count = 0;
  const Solid<R>* solids = nullptr;
  uint32_t solid_count = 0;
  const Light<R>* lights = nullptr;
  uint32_t light_count = 0;
  const Texture* textures = nullptr;
  uint32_t texture_count = 0;
  // Quadric solids and the CSG tree over them (quadric.hpp, csg.hpp); the
  // children of the top node `csg_root` are independent objects.
  const Quadric<R>* quadrics = nullptr;
  uint32_t quadric_count = 0;
  const CsgNode* csg_nodes = nullptr;
  uint32_t csg_node_count = 0;
  int32_t csg_root = kNoNode;
  // Beside the triangles when they form meshes: one face per triangle and
  // the unit vertex normals smooth faces index (null when none).
  const MeshFace* mesh_faces = nullptr;
  const Vec3<R>* vertex_normals = nullptr;
  // Finish::kEastray: the settings, colours and lights it shades with.
  const EastrayShading<R>* eastray = nullptr;
};

}  // namespace minrt::model
