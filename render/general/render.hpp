// Renders a general scene: set-up (BVH, feature selection) once, then rows.
// Rows are independent (every random number is a function of the pixel), so
// the host may render them in any order or in parallel threads and get the
// same bytes; the board renders them in order and streams each one.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/base/counter_rng.hpp"
#include "core/image/row_sink.hpp"
#include "formats/model/scene.hpp"
#include "render/general/bvh.hpp"
#include "render/general/camera.hpp"
#include "render/general/cs418_shading.hpp"
#include "render/general/csg_object_bvh.hpp"
#include "render/general/eastray_shading.hpp"
#include "render/general/eastray_view.hpp"
#include "render/general/features.hpp"
#include "render/general/packet_row.hpp"
#include "render/general/phong_shading.hpp"
#include "render/general/tracer.hpp"
#include "render/general/wide_bvh.hpp"

namespace minrt::general {

// The compiled paths: features outside a path's set make the scene use the
// next larger one (features.hpp).
// CS418's (Cs418Shader): spheres and suns, then direct light, then every
// feature of the course.
inline constexpr uint32_t kPathBasic = 0;
inline constexpr uint32_t kPathDirect = kPlanes | kTriangles | kBulbs | kExposure | kLenses;
inline constexpr uint32_t kPathFull = kAllFeatures & ~(kPhong | kSolids);
// miniRT's (PhongShader): spheres and planes, then everything the format has.
inline constexpr uint32_t kPathPhong = kPlanes | kPhong;
inline constexpr uint32_t kPathPhongFull = kPlanes | kPhong | kSolids | kTextures;
// EASTRAY's (EastrayShader): CSG over quadric solids, meshes, its finish and view.
inline constexpr uint32_t kPathEastray = kEastray | kQuadrics | kTriangles;
static_assert(((kPathFull | kPathPhongFull) & (kEastray | kQuadrics)) == 0,
              "no CS418 or miniRT path carries EASTRAY's code");

// Reflected, refracted and GI rays whose weight (the product of the
// shininess, transparency and colour factors on the way to the pixel) is
// below this are not traced: they could move a pixel by at most this
// fraction of the brightest radiance in the scene. Without it a scene of
// glass spheres with 16 bounces traces a binary tree per pixel; with it the
// 33 course tests give the same bytes (docs/cs418.md). 0 traces every ray.
inline constexpr float kDefaultMinWeight = 1.0f / 65536.0f;  // exact in float and double

template <class M>
class Renderer {
  using R = typename M::real;

 public:
  // Builds the BVH in the arena and picks the path. False when the arena is
  // too small (EASTRAY's scenes render without the hierarchies that do not
  // fit: the same image, slower).
  bool setup(const model::Scene<R>& scene, Arena& arena, uint32_t seed, bool force_full = false,
             bool full_tree = false) {
    scene_ = &scene;
    seed_ = seed;
    min_weight_ = full_tree ? R(0) : R(kDefaultMinWeight);
    features_ = features_of(scene);
    // EASTRAY's meshes may go without their hierarchy (every ray then tests
    // every triangle: the same image, slower), as on a board short of room.
    if (!build_bvh<M>(scene, arena, bvh_) && (features_ & kEastray) == 0) return false;
    // Without room for the wide form the binary tree is walked: the same image.
    if constexpr (kWideBvh) {
      if ((features_ & kEastray) == 0 && build_wide_bvh(bvh_, arena, bvh_.wide)) {
        build_sphere_lanes(scene, arena, bvh_);
        bvh_.wide.avx2 = cpu_has_avx2();
      }
    }
    auto* dirs = arena.alloc_zeroed<Vec3<R>>(scene.light_count > 0 ? scene.light_count : 1);
    if (dirs == nullptr) return false;
    for (uint32_t i = 0; i < scene.light_count; ++i)
      if (scene.lights[i].kind == model::LightKind::kSun) dirs[i] = normalize<M>(scene.lights[i].vector);
    light_dirs_ = dirs;
    if constexpr (kWideBvh) {
      if (bvh_.wide.node_count != 0 && scene.triangle_count + scene.solid_count == 0) build_sun_grids(scene, arena);
    }
    if ((features_ & kQuadrics) != 0) build_object_bvh<M>(scene, arena, objects_);
    // Each format's paths, the smallest that has the scene's features;
    // --all-features (force_full): the format's path with every one.
    if ((features_ & kEastray) != 0) path_ = kPathEastray;
    else if ((features_ & kPhong) != 0)
      path_ = !force_full && (features_ & ~kPathPhong) == 0 ? kPathPhong : kPathPhongFull;
    else if (force_full) path_ = kPathFull;
    else if ((features_ & ~kPathBasic) == 0) path_ = kPathBasic;
    else if ((features_ & ~kPathDirect) == 0) path_ = kPathDirect;
    else path_ = kPathFull;
    if constexpr (kWideBvh)
      bvh_.wide.packets = wide_walk() && (path_ == kPathBasic || path_ == kPathDirect || path_ == kPathFull);
    return true;
  }

  // render_row_watched renders what render_row would, every texel read
  // going to g_texel_watch (surface_maps.hpp): host-send's recording, or a
  // board holding sparse textures. Only for a scene on the CS418 path with
  // every feature (one with textures always is); render_row is untouched.
  bool can_watch_texels() const { return path_ == kPathFull; }
  void render_row_watched(int y, uint8_t* rgba) const { row<kPathFull | kTexelWatch>(y, rgba); }

  uint32_t features() const { return features_; }
  uint32_t path() const { return path_; }
  const Bvh<R>& bvh() const { return bvh_; }
  // The plain walk over the CSG tree instead of its objects' hierarchy: the
  // same image (tests).
  const CsgObjects<R>& objects() const { return objects_; }
  void drop_object_bvh() { objects_ = CsgObjects<R>{nullptr, nullptr, nullptr, 0}; }
  // The binary tree's walk, or the wide one's with 16-byte vectors only,
  // instead of the widest this CPU has: the same image (tests).
  void drop_wide_bvh() { bvh_.wide = WideSlot<R>{}; }
  // Every shadow ray by the walk, without the sun grids: the same image (tests).
  void drop_sun_grids() {
    if constexpr (kWideBvh) bvh_.wide.sun_grid_count = 0;
  }
  bool sun_grids() const {
    if constexpr (kWideBvh) {
      for (uint32_t i = 0; i < bvh_.wide.sun_grid_count; ++i)
        if (bvh_.wide.sun_grids[i].nu != 0) return true;
    }
    return false;
  }
  void use_16_byte_vectors() {
    if constexpr (kWideBvh) bvh_.wide.avx2 = false;
  }
  // Each primary ray by itself, as the board traces them: the same image
  // (tests).
  void drop_packets() {
    if constexpr (kWideBvh) bvh_.wide.packets = false;
  }
  bool packets() const {
    if constexpr (kWideBvh) return bvh_.wide.packets;
    return false;
  }
  bool wide_walk() const {
    if constexpr (kWideBvh) return bvh_.wide.node_count != 0;
    return false;
  }
  bool avx2_walk() const {
    if constexpr (kWideBvh) return bvh_.wide.node_count != 0 && bvh_.wide.avx2;
    return false;
  }

  // One row of RGBA bytes (4 * width). Safe to call from several threads.
  void render_row(int y, uint8_t* rgba) const {
    if constexpr (kWideBvh) {
      if (bvh_.wide.packets) {
        switch (path_) {
          case kPathBasic: return packet_row<kPathBasic>(y, rgba);
          case kPathDirect: return packet_row<kPathDirect>(y, rgba);
          default: return packet_row<kPathFull>(y, rgba);
        }
      }
    }
    switch (path_) {
      case kPathBasic: row<kPathBasic>(y, rgba); break;
      case kPathDirect: row<kPathDirect>(y, rgba); break;
      case kPathPhong: row<kPathPhong>(y, rgba); break;
      case kPathPhongFull: row<kPathPhongFull>(y, rgba); break;
      case kPathEastray: eastray_row(y, rgba); break;
      default: row<kPathFull>(y, rgba); break;
    }
  }

  // Every row in order into the sink; `row_buffer` holds 4 * width bytes.
  void render(RgbaRowSink sink, uint8_t* row_buffer) const {
    sink.begin(scene_->width, scene_->height);
    for (int y = 0; y < scene_->height; ++y) {
      render_row(y, row_buffer);
      sink.row(y, row_buffer);
    }
    sink.end();
  }

 private:
  void eastray_row(int y, uint8_t* out) const {
    const Tracer<M, kPathEastray> tracer(*scene_, bvh_, light_dirs_, min_weight_, &objects_);
    EastrayView<M, kPathEastray>(*scene_->eastray, tracer).render_row(y, out);
  }

  // A grid for each of the first suns (sun_grid.hpp) when the image has
  // enough samples to repay it; a light without one, or a grid that does
  // not fit, leaves its shadow rays to the walk.
  void build_sun_grids(const model::Scene<R>& scene, Arena& arena) {
    const uint32_t count = scene.light_count < kSunGridLights ? scene.light_count : kSunGridLights;
    if (count == 0 || scene.sphere_count == 0) return;
    const uint64_t samples = static_cast<uint64_t>(scene.width) * static_cast<uint64_t>(scene.height) *
                             static_cast<uint64_t>(scene.samples > 0 ? scene.samples : 1);
    if (samples < static_cast<uint64_t>(kSunGridSamples) * scene.sphere_count) return;
    auto* grids = arena.alloc_zeroed<SunGrid<R>>(count);
    if (grids == nullptr) return;
    for (uint32_t i = 0; i < count; ++i) {
      grids[i] = SunGrid<R>{};
      if (scene.lights[i].kind == model::LightKind::kSun) build_sun_grid<M>(scene, light_dirs_[i], arena, grids[i]);
    }
    bvh_.wide.sun_grids = grids;
    bvh_.wide.sun_grid_count = count;
  }

  template <uint32_t F>
  void row(int y, uint8_t* out) const {
    const model::Scene<R>& s = *scene_;
    Tracer<M, F> tracer(s, bvh_, light_dirs_, min_weight_);  // one per row: its shadow cache is this row's
    const CameraRays<M> camera(s);
    const R half = R(0.5);
    for (int x = 0; x < s.width; ++x) {
      CounterRng rng(seed_, static_cast<uint32_t>(y) * static_cast<uint32_t>(s.width) + static_cast<uint32_t>(x));
      Vec3<R> sum{};
      int32_t hits = 0;
      for (int32_t k = 0; k < s.samples; ++k) {
        // The samples of a pixel share its stream: the draws at each hit do
        // not depend on the weight cut-off (branches fork their own streams).
        CounterRng& sample_rng = rng;
        R px = M::from_int(x), py = M::from_int(y);
        if constexpr ((F & kLensOrAa) != 0) {
          if (s.samples > 1) {
            // Jitter centred on the unjittered ray (SPEC.md 1.3).
            px = px + (sample_rng.uniform<M>() - half);
            py = py + (sample_rng.uniform<M>() - half);
          }
        }
        Ray<R> ray;
        if (!camera.primary(px, py, sample_rng, ray)) continue;
        const Sample<R> smp = tracer.trace(ray, 0, 0, R(1), R(0), sample_rng);
        if (!smp.hit) continue;
        sum += smp.color;
        ++hits;
      }
      Tracer<M, F>::pixel(s, sum, hits, out + 4 * x);
    }
  }

  // CS418's rows on the host with the primary rays in packets
  // (packet_row.hpp).
  template <uint32_t F>
  void packet_row(int y, uint8_t* out) const {
    const Tracer<M, F> tracer(*scene_, bvh_, light_dirs_, min_weight_);  // one per row, as in row()
    general::packet_row<M, F, kPacketRays>(*scene_, tracer, CameraRays<M>(*scene_), seed_, y, out);
  }

  const model::Scene<R>* scene_ = nullptr;
  Bvh<R> bvh_{};
  uint32_t seed_ = 0;
  uint32_t features_ = 0;
  uint32_t path_ = kPathFull;
  R min_weight_ = static_cast<R>(kDefaultMinWeight);
  const Vec3<R>* light_dirs_ = nullptr;
  CsgObjects<R> objects_{nullptr, nullptr, nullptr, 0};
};

}  // namespace minrt::general
