// Collects a scene while a reader parses it, then lays it out in the arena.
// Readers cannot know the counts before the end (CS418 interleaves vertices,
// triangles, spheres and material changes), so every item goes first into a
// log of fixed-size records at the arena's top end; finish() allocates the
// exact arrays from the bottom, fills them in file order and releases the
// log. Arithmetic only (no math policy): the precomputation here needs no
// square root.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/arena.hpp"
#include "formats/model/scene.hpp"

namespace minrt::model {

template <class R>
class SceneBuilder {
 public:
  explicit SceneBuilder(Arena& arena) : arena_(arena), mark_(arena.top_mark()) {}

  // Each add returns false when the arena is full.
  bool add_material(const Material<R>& m) {
    Record* r = push(Kind::kMaterial);
    if (r == nullptr) return false;
    r->material = m;
    ++materials_;
    return true;
  }
  // Objects use the material added last (a default one if none was).
  bool add_sphere(const Vec3<R>& center, R radius) {
    Record* r = push(Kind::kSphere);
    if (r == nullptr) return false;
    r->sphere = Sphere<R>{center, radius, current_material(), objects_++};
    ++spheres_;
    return true;
  }
  bool add_plane(const Vec3<R>& abc, R d) {
    Record* r = push(Kind::kPlane);
    if (r == nullptr) return false;
    // (A, B, C, D) scaled as (A, B, C) is when A^2 + B^2 + C^2 under- or
    // overflows: the same plane, where the square would give a NaN or
    // zero point.
    const Vec3<R> n = squarable_direction(abc);
    const R dn = squarable(abc) ? d : d / largest_component(abc);
    const R scale = -dn / dot(n, n);
    r->plane = Plane<R>{n, n * scale, current_material(), objects_++};
    ++planes_;
    return true;
  }
  bool add_solid(const Solid<R>& solid) {
    Record* r = push(Kind::kSolid);
    if (r == nullptr) return false;
    r->solid = solid;
    r->solid.material = current_material();
    r->solid.order = objects_++;
    ++solids_;
    return true;
  }
  bool add_vertex(const Vec3<R>& position, R u, R v) {
    Record* r = push(Kind::kVertex);
    if (r == nullptr) return false;
    r->vertex = Vertex<R>{position, u, v};
    ++vertices_;
    return true;
  }
  // Indices are 0-based into the vertices added so far (checked by the caller).
  bool add_triangle(uint32_t i0, uint32_t i1, uint32_t i2) {
    Record* r = push(Kind::kTriangle);
    if (r == nullptr) return false;
    r->tri = TriangleRef{{i0, i1, i2}, current_material(), objects_++};
    ++triangles_;
    return true;
  }
  bool add_light(const Light<R>& light) {
    Record* r = push(Kind::kLight);
    if (r == nullptr) return false;
    r->light = light;
    ++lights_;
    return true;
  }

  uint32_t vertex_count() const { return vertices_; }
  uint32_t object_count() const { return objects_; }
  uint32_t light_count() const { return lights_; }

  // Fills the scene's arrays; false when the arena is too small.
  bool finish(Scene<R>& scene) {
    const uint32_t material_total = materials_ + 1;  // [0] is the default
    auto* materials = arena_.alloc_zeroed<Material<R>>(material_total);
    auto* spheres = arena_.alloc_zeroed<Sphere<R>>(spheres_);
    auto* planes = arena_.alloc_zeroed<Plane<R>>(planes_);
    auto* triangles = arena_.alloc_zeroed<Triangle<R>>(triangles_);
    auto* lights = arena_.alloc_zeroed<Light<R>>(lights_);
    auto* solids = arena_.alloc_zeroed<Solid<R>>(solids_);
    // Vertices are needed only to build the triangles: scratch at the top.
    auto* vertices = arena_.alloc_top<Vertex<R>>(vertices_ > 0 ? vertices_ : 1);
    if (materials == nullptr || spheres == nullptr || planes == nullptr || triangles == nullptr ||
        lights == nullptr || solids == nullptr || vertices == nullptr) {
      arena_.release_top(mark_);
      return false;
    }
    materials[0] = Material<R>{};
    uint32_t nm = 1, ns = 0, np = 0, nt = 0, nl = 0, nv = 0, nc = 0;
    for (uint32_t i = 0; i < count_; ++i) {
      const Record& r = first_[-static_cast<ptrdiff_t>(i)];
      switch (r.kind) {
        case Kind::kMaterial: materials[nm++] = r.material; break;
        case Kind::kSphere: spheres[ns++] = r.sphere; break;
        case Kind::kPlane: planes[np++] = r.plane; break;
        case Kind::kVertex: vertices[nv++] = r.vertex; break;
        case Kind::kTriangle: triangles[nt++] = make_triangle(r.tri, vertices); break;
        case Kind::kLight: lights[nl++] = r.light; break;
        case Kind::kSolid: solids[nc++] = r.solid; break;
      }
    }
    arena_.release_top(mark_);
    count_ = 0;
    scene.materials = materials;
    scene.material_count = material_total;
    scene.spheres = spheres;
    scene.sphere_count = spheres_;
    scene.planes = planes;
    scene.plane_count = planes_;
    scene.triangles = triangles;
    scene.triangle_count = triangles_;
    scene.lights = lights;
    scene.light_count = lights_;
    scene.solids = solids;
    scene.solid_count = solids_;
    return true;
  }


 private:
  enum class Kind : uint8_t { kMaterial, kSphere, kPlane, kVertex, kTriangle, kLight, kSolid };
  struct TriangleRef {
    uint32_t index[3];
    uint32_t material;
    uint32_t order;
  };
  struct Record {
    Kind kind;
    union {
      Material<R> material;
      Sphere<R> sphere;
      Plane<R> plane;
      Vertex<R> vertex;
      TriangleRef tri;
      Light<R> light;
      Solid<R> solid;
    };
  };

  Record* push(Kind kind) {
    Record* r = arena_.alloc_top<Record>(1);
    if (r == nullptr) return nullptr;
    if (count_ == 0) first_ = r;
    ++count_;
    r->kind = kind;
    return r;
  }
  uint32_t current_material() const { return materials_; }  // 0 = default

  static Triangle<R> make_triangle(const TriangleRef& t, const Vertex<R>* v) {
    const Vertex<R>& a = v[t.index[0]];
    const Vertex<R>& b = v[t.index[1]];
    const Vertex<R>& c = v[t.index[2]];
    Triangle<R> out{};
    out.p0 = a.position;
    out.p1 = b.position;
    out.p2 = c.position;
    const Vec3<R> d1 = b.position - a.position;
    const Vec3<R> d2 = c.position - a.position;
    out.normal = cross(d1, d2);
    const Vec3<R> a1 = cross(d2, out.normal);
    const Vec3<R> a2 = cross(d1, out.normal);
    out.e1 = a1 / dot(a1, d1);
    out.e2 = a2 / dot(a2, d2);
    out.u[0] = a.u;
    out.u[1] = b.u;
    out.u[2] = c.u;
    out.v[0] = a.v;
    out.v[1] = b.v;
    out.v[2] = c.v;
    out.material = t.material;
    out.order = t.order;
    return out;
  }

  Arena& arena_;
  size_t mark_;
  Record* first_ = nullptr;
  uint32_t count_ = 0;
  uint32_t materials_ = 0, spheres_ = 0, planes_ = 0, vertices_ = 0, triangles_ = 0, lights_ = 0, solids_ = 0;
  uint32_t objects_ = 0;

 public:
  static constexpr size_t record_bytes() { return sizeof(Record); }
};

}  // namespace minrt::model
