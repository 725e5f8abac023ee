// What a scene uses, found once at set-up, so that the tracer can be
// compiled without the code a scene does not need: a sphere-and-sun scene
// runs no triangle, texture, refraction or sampling code (SPEC.md 5; the
// issue asks a scene to pay only for what it uses).
#pragma once

#include <stdint.h>

#include "formats/model/scene.hpp"

namespace minrt::general {

enum Feature : uint32_t {
  kPlanes = 1u << 0,
  kTriangles = 1u << 1,
  kTextures = 1u << 2,
  kBulbs = 1u << 3,
  kSecondary = 1u << 4,  // shininess or transparency
  kRoughness = 1u << 5,
  kGi = 1u << 6,
  kLensOrAa = 1u << 7,   // several samples per pixel or depth of field
  kLenses = 1u << 8,     // fisheye or panorama
  kExposure = 1u << 9,
  kSolids = 1u << 10,  // cylinders and cones (miniRT)
  kPhong = 1u << 11,   // miniRT's finish: ambient, Lambert, Phong, clamp
  // EASTRAY's, outside kAllFeatures: a path of their own, so that no other
  // path carries their code.
  kQuadrics = 1u << 12,  // quadric solids in a CSG tree
  kEastray = 1u << 13,   // EASTRAY's finish (eastray_shading.hpp, eastray_view.hpp)
  // Not a scene's: every texel read goes to the texel watch
  // (surface_maps.hpp), on the CS418 path of a render that asks for it.
  kTexelWatch = 1u << 14,
};
inline constexpr uint32_t kAllFeatures = (1u << 12) - 1;

// The shading is a policy over the tracer's geometry (tracer.hpp), one per
// format, chosen by the path's features: a path carries one format's
// shading and nothing of the others'.
template <class M, uint32_t F>
class Cs418Shader;  // cs418_shading.hpp
template <class M, uint32_t F>
class PhongShader;  // phong_shading.hpp (miniRT)
template <class M, uint32_t F>
class EastrayShader;  // eastray_shading.hpp

namespace detail {
template <class M, uint32_t F, bool kPhongPath = (F & kPhong) != 0, bool kEastrayPath = (F & kEastray) != 0>
struct ShaderOf {
  using type = Cs418Shader<M, F>;
};
template <class M, uint32_t F>
struct ShaderOf<M, F, true, false> {
  using type = PhongShader<M, F>;
};
template <class M, uint32_t F>
struct ShaderOf<M, F, false, true> {
  using type = EastrayShader<M, F>;
};
}  // namespace detail

// The tracer of path F: geometry and the shading of F's format.
template <class M, uint32_t F>
using Tracer = typename detail::ShaderOf<M, F>::type;

template <class R>
uint32_t features_of(const model::Scene<R>& s) {
  uint32_t f = 0;
  if (s.plane_count > 0) f |= kPlanes;
  if (s.triangle_count > 0) f |= kTriangles;
  if (s.solid_count > 0) f |= kSolids;
  if (s.finish == model::Finish::kMinirt) f |= kPhong;
  if (s.csg_root != model::kNoNode) f |= kQuadrics;
  if (s.finish == model::Finish::kEastray) f |= kEastray;
  for (uint32_t i = 0; i < s.material_count; ++i) {
    const model::Material<R>& m = s.materials[i];
    if (m.texture != model::kNoTexture || m.bump != model::kNoTexture) f |= kTextures;
    const Vec3<R> z{};
    auto nonzero = [&](const Vec3<R>& v) { return v.x != z.x || v.y != z.y || v.z != z.z; };
    if (nonzero(m.shininess) || nonzero(m.transparency)) f |= kSecondary;
    if (m.roughness != R(0)) f |= kRoughness;
  }
  for (uint32_t i = 0; i < s.light_count; ++i)
    if (s.lights[i].kind == model::LightKind::kBulb) f |= kBulbs;
  if (s.gi_depth > 0) f |= kGi;
  if (s.samples > 1 || s.camera.depth_of_field) f |= kLensOrAa;
  if (s.camera.projection != model::Projection::kFlat) f |= kLenses;
  if (s.exposure) f |= kExposure;
  return f;
}

}  // namespace minrt::general
