// The min-rt tracer's state: its constants, the types of its tables and
// every variable the original kept as a global, in one struct. The tracer
// (tracer_class.hpp) derives from it; the functions of every seam work on
// this one state.
#pragma once

#include <stdint.h>

#include "core/math/math_policy.hpp"
#include "formats/sld/sld_limits.hpp"

namespace minrt {

template <MathPolicy M>
struct TracerState {
  using R = typename M::real;

  static constexpr int kDirvecGroups = 5;
  static constexpr int kDirvecsPerGroup = 120;
  static constexpr int kMaxReflections = 3;  // see setup_reflections
  static constexpr int kMaxDepth = 5;        // reflection levels 0..4
  // Direction tables: the diffuse groups, then the light, then the mirrors.
  static constexpr int kLightDirvec = kDirvecGroups * kDirvecsPerGroup;
  static constexpr int kDirvecCount = kLightDirvec + 1 + kMaxReflections;

  // Per-direction tables: for each object, the constants its fast solver
  // needs for rays along `v` (6 for boxes, 4 for planes, 6 otherwise).
  struct DirVec {
    R v[3];
    R* c;
    uint32_t code;  // direction_code(v)
    int32_t octant;  // bit k: v_k < 0; -1 when a component is 0
  };
  // Fields the intersection loops touch come first, to share cache lines.
  struct Object {
    int32_t form, rotated;
    bool inverted;
    int consts_offset;  // in bytes, to save a shift in the ray loops
    int index;
    R abc[3];
    R rot[3];  // after preprocessing: the yz, zx, xy cross-term coefficients
    R start[4];  // per ray-start table: start - center, and the constant term
    R center[3];
    int32_t texture, reflection;
    R diffuse, hilight;
    R color[3];
    // Half-widths of a box around the points is_outside counts as inside;
    // only for non-inverted boxes and axis-aligned ellipsoids.
    R slab[3];
    bool slab_bounded;
    uint32_t fwd;  // forward-culling mask from the current start point
    // Boxes: the direction-code bits (see direction_code) along which a face
    // the fast solver can return may lie ahead of the current start point;
    // all bits for other forms (see setup_startp).
    uint32_t ahead;
    // utexture gives a finite colour at any point: no texture, or the
    // checker (0 or 255), over finite base colours.
    bool finite_texture;
  };
  struct Reflection {
    int surface_id;
    DirVec dvec;
    R bright;
  };
  // What the direct trace leaves in a pixel for the diffuse pass. Pixel rows
  // are reused every three lines without clearing, as in the original, whose
  // stale entries can decide later pixels.
  struct Pixel {
    R rgb[3];
    R points[kMaxDepth][3];
    int32_t surface_ids[kMaxDepth];
    bool calc_diffuse[kMaxDepth];
    R energy[kMaxDepth][3];
    R received[kMaxDepth][3];  // diffuse light from this pixel's 60 rays
    int32_t group_id;
    R normals[kMaxDepth][3];
  };

  // AND networks as null-terminated lists of objects, OR rows as their range
  // primitive (null for none) and null-terminated lists of AND networks:
  // resolved once so the ray loops follow pointers instead of indices.
  using ObjectList = const Object* const*;
  // Shadow culling. A shadow point is light * t + p with t < -0.19; along
  // an axis where light_k <= 0 it is >= p_k, rounding included, so once
  // p_k >= limit with fl(limit - center_k) >= slab_k no shadow point is
  // inside that member and its network cannot shadow (mirrored where
  // light_k > 0: the flipped axes). A row is skipped when one axis limit
  // covers all its networks.
  struct ShadowLimits {
    R limit[3];  // NaN: no limit on that axis
    bool culls(R x0, R x1, R x2) const { return x0 >= limit[0] || x1 >= limit[1] || x2 >= limit[2]; }
  };

  struct OrRow {
    const Object* range;
    ObjectList nets[limits::kMaxOrNetworkLength + 1];
    int32_t lengths[limits::kMaxOrNetworkLength];  // members of each network
    uint32_t fwd[limits::kMaxOrNetworkLength];  // see setup_forward_culling
    uint32_t fwd_all;
  };
  // The shadow test's own flat copy of the OR rows (see
  // setup_shadow_culling): each row's networks with their limits, rows
  // without networks left out, so in_shadow walks two arrays in order.
  struct ShadowNet {
    ShadowLimits lim;
    ObjectList net;
  };
  struct ShadowRow {
    ShadowLimits all;
    const Object* range;
    const ShadowNet* nets;
    const ShadowNet* nets_end;
  };

  // --- state (the original's globals) -------------------------------------

  int width_ = 0, height_ = 0;
  int center_[2] = {};
  R scan_pitch_ = 0;
  R screenx_[3] = {}, screeny_[3] = {}, screenz_[3] = {};
  R viewpoint_[3] = {};
  R light_[3] = {};
  R beam_ = 0;

  int n_objects_ = 0;
  Object objects_[limits::kMaxObjects];
  const Object* net_objects_[limits::kMaxAndNetworkDefinitions][limits::kMaxAndNetworkLength + 1];
  OrRow or_rows_[limits::kMaxOrNetworks];
  int n_or_rows_ = 0;

  // For the current diffuse start point and each octant of directions, the
  // OR rows with the AND networks forward culling leaves, in order (see
  // setup_forward_culling); arena tables, live_stride_ entries an octant.
  // A network and how many of its members a ray of the octant solves: all
  // of them, or all but a last box the octant's rays meet only behind the
  // start (see Object::ahead).
  struct LiveNet {
    ObjectList net;
    int32_t solved;
  };
  struct LiveRow {
    const Object* range;
    const LiveNet* nets;  // ends with a null net; null for the end of the list
  };
  LiveRow* live_rows_ = nullptr;
  LiveNet* live_nets_ = nullptr;
  int live_nets_stride_ = 0;
  uint32_t live_built_ = 0;  // bit o: octant o's list is built for this start

  // Arena tables of setup_shadow_culling.
  ShadowRow* shadow_rows_ = nullptr;
  ShadowNet* shadow_nets_ = nullptr;
  int n_shadow_rows_ = 0;

  DirVec dirvecs_[kDirvecGroups][kDirvecsPerGroup];
  DirVec light_dirvec_{};
  Reflection reflections_[kMaxReflections];
  int n_reflections_ = 0;
  Pixel* lines_[3] = {};
  int lines_through_ = -1;  // the last row traced into lines_
  // Rows in bands (band_rows.hpp): for each slot of each pixel of lines_,
  // the row as of which it holds what the one-thread render has there;
  // null unless prepare_bands gave it memory.
  int16_t* slot_rows_ = nullptr;
  uint8_t* row_ = nullptr;  // the finished row, 3 bytes a pixel

  int intsec_rectside_ = 0;
  R tmin_ = 0;
  R intersection_point_[3] = {};
  int intersected_object_id_ = 0;
  R nvector_[3] = {};
  R texture_color_[3] = {};
  R diffuse_ray_[3] = {};
  R rgb_[3] = {};
  R startp_[3] = {};
  R startp_fast_[3] = {};
  // The culling tables of setup_startp<true> and the octant lists are those
  // of startp_fast_ (setup_startp<false> leaves the masks stale).
  bool culled_start_valid_ = false;

  bool toward_light_flip_[3] = {};
};

}  // namespace minrt
