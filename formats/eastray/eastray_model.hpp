// An EASTRAY scene as the general model (formats/model/scene.hpp) that the
// general tracer draws with Finish::kEastray: the model points at the
// reader's arrays (quadric solids, CSG nodes, triangles and their mesh
// faces, vertex normals, colours, lights); nothing is copied but the
// settings, so it lives as long as the eastray::Scene it was made from.
#pragma once

#include "formats/eastray/eastray_scene.hpp"
#include "formats/model/scene.hpp"

namespace minrt::eastray {

// `shading` receives the settings, colours and lights; `out` points at it.
template <class R>
void to_model(const Scene<R>& in, model::EastrayShading<R>& shading, model::Scene<R>& out) {
  static_cast<model::EastraySettings<R>&>(shading) = in;
  shading.materials = in.materials;
  shading.material_count = in.material_count;
  shading.lights = in.lights;
  shading.light_count = in.light_count;
  shading.mappings = in.mappings;
  shading.mapped_objects = in.mapped_objects;
  out = model::Scene<R>{};
  out.width = in.width;
  out.height = in.height;
  out.finish = model::Finish::kEastray;
  out.triangles = in.triangles;
  out.triangle_count = static_cast<uint32_t>(in.triangle_count);
  out.mesh_faces = in.faces;
  out.vertex_normals = in.vertex_normals;
  out.quadrics = in.primitives;
  out.quadric_count = static_cast<uint32_t>(in.primitive_count);
  out.csg_nodes = in.nodes;
  out.csg_node_count = static_cast<uint32_t>(in.node_count);
  out.csg_root = in.root;
  out.eastray = &shading;
}

}  // namespace minrt::eastray
