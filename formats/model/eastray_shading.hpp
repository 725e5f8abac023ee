// EASTRAY's shading as the general model carries it (Finish::kEastray in
// scene.hpp): its lights (infinite, point, spot), its colours (diffuse,
// reflection, transmission with ior and absorption, the specular models of
// the manual) and its global settings (display window, condition, anti,
// camera, mist, sky, env, shadow). The EASTRAY reader fills them
// (formats/eastray); render/general/eastray_shading.hpp draws with them.
#pragma once

#include <stdint.h>

#include "core/math/vec3.hpp"
#include "formats/model/eastray_mapping.hpp"

namespace minrt::model {

struct Texture;  // scene.hpp

inline constexpr int kColorNameBytes = 32;

enum class EastrayLightKind : uint8_t { kInfinite, kPoint, kSpot };

template <class R>
struct EastrayLight {
  EastrayLightKind kind;
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
struct EastrayMaterial {
  char name[kColorNameBytes];
  Vec3<R> diffuse, reflect, transmit;
  R ior, half_distance, bump;
  Specular specular;
  // kBlinn: p[0] intensity, p[1] exponent. kBlinnGauss: rgb, p[3] spread,
  // p[4] Fresnel constant. kAniso1: rgb, p[3..5] circle centre, p[6..8]
  // circle normal, p[9..11] A B C. kAniso2: rgb, p[3..5] scratch
  // direction, p[6..8] A B C. kCookTorrance: rgb, p[3] ratio, p[4]
  // spread 1, p[5] spread 2. kConstant: color1 p[0..2], color2 p[3..5], p[6] k.
  R p[kSpecularParams];
  // The first mapping entry of each parameter (EastrayMapSlot), or kNoMapping.
  int32_t map[kMapSlots];
};

// The scene-wide statements, with the manual's defaults (docs/eastray.md).
template <class R>
struct EastraySettings {
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
  bool stereo = false;  // rmode 1 (line 57): a right and a left image
  // mist, sky, env, shadow, voxel
  R mist_half = R(0);
  bool mist_to_sky = false;
  Vec3<R> sky{}, env{};
  bool shadows = true;
  int32_t voxel = 0;
  // output_mode (lines 152-164): 16 (32K colours) or 24 bits, dither at 16
  int32_t output_bits = 24;
  bool dither = false;
  // back_mode (lines 205-230): 0 the sky behind, sun discs seen; 1 the
  // input image behind, no discs; 2 the input image and the discs. The
  // reflection and transmission switches send a missed secondary ray's
  // power to that background; the alpha mode shapes only .hpi images.
  int32_t background = 0;
  bool back_reflect = false, back_transmit = false, alpha_pure = false;
};

// What the EASTRAY finish reads: the settings, the colours the surfaces
// name by index, and the lights.
template <class R>
struct EastrayShading : EastraySettings<R> {
  const EastrayMaterial<R>* materials = nullptr;
  int32_t material_count = 0;
  const EastrayLight<R>* lights = nullptr;
  int32_t light_count = 0;
  // Mapping (eastray_mapping.hpp): a surface's material at or above
  // material_count names mapped_objects[material - material_count].
  const EastrayMapping<R>* mappings = nullptr;
  const EastrayMappedObject<R>* mapped_objects = nullptr;
  const Texture* map_images = nullptr;  // one per map_data entry, 3 bytes a texel (linear 0..255)
  int32_t map_image_count = 0;
  // Entry i's halved images when read with mip 1: level k (1..) at
  // map_mips[i * kMipLevels + k - 1], width 0 past its last (modes 10-14).
  const Texture* map_mips = nullptr;
  const Texture* input_image = nullptr;  // `input`, behind the image when background is 1 or 2
};

}  // namespace minrt::model
