#include "format_sides/general_scene.hpp"

namespace minrt::host {

const char* general_path_name(uint32_t path) {
  switch (path) {
    case general::kPathBasic: return "basic (spheres, suns)";
    case general::kPathDirect: return "direct (planes, triangles, bulbs, lenses, exposure)";
    case general::kPathPhong: return "phong (miniRT: spheres, planes)";
    case general::kPathPhongFull: return "phong-full (miniRT: every element)";
    case general::kPathEastray: return "eastray (CSG of quadrics, meshes, EASTRAY's shading)";
    default: return "full (every feature)";
  }
}

}  // namespace minrt::host
