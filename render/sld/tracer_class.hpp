// The min-rt rendering algorithm: direct rays with mirror recursion, shadow
// tests through the OR/AND networks, highlights, textures and the diffuse
// (indirect) light sampled over 300 precomputed directions, shared between a
// pixel and its four neighbours. Every floating-point expression keeps the
// original program's operand order, so the double/libm build reproduces the
// original's output bit for bit. Quirks of the original that change pixels
// are kept on purpose and marked "original:".
//
// This file declares the class, its data and its small helpers; the member
// functions are defined by seam in the files render/sld/tracer.hpp lists.
#pragma once

#include <stdint.h>

#include "core/base/arena.hpp"
#include "core/math/math_policy.hpp"
#include "core/image/row_sink.hpp"
#include "formats/sld/scene.hpp"
#include "formats/sld/sld_limits.hpp"
#include "render/sld/tracer_state.hpp"

// The innermost solver steps run millions of times per image; keep them in
// their callers' loops.
#define MINRT_INLINE [[gnu::always_inline]] inline

namespace minrt {

// int_of_float then clamp to 0..255, with the original's x86-64 OCaml
// behaviour for huge values: the conversion yields a 64-bit integer and OCaml
// keeps its low 63 bits, so NaN and x >= 2^62 print 0, and -2^63 < x < -2^62
// prints 255.
template <MathPolicy M>
int pixel_channel(typename M::real x) {
  using R = typename M::real;
  constexpr R k2p62 = R(4611686018427387904.0);
  constexpr R k2p63 = R(9223372036854775808.0);
  if (!(x < k2p62)) return 0;  // NaN too
  if (x >= R(256.0)) return 255;
  if (x > -k2p63 && x < -k2p62) return 255;
  if (x < R(1.0)) return 0;
  return M::to_int(x);
}

// Rows that the workers rendering neighbouring bands of one image both
// need traced in full (Tracer::render_rows): the first to ask traces the
// row and gives its state; the other copies that state if it is ready. The
// bytes are what any worker computes for that row, so taking a row only
// saves the work.
struct SharedRows {
  void* ctx = nullptr;
  // True: the row's pixel line and slot rows were copied into `pixels` and
  // `slots`. False: the caller traces the row itself, then calls give.
  bool (*take)(void* ctx, int row, void* pixels, size_t pixel_bytes, void* slots, size_t slot_bytes) = nullptr;
  void (*give)(void* ctx, int row, const void* pixels, size_t pixel_bytes, const void* slots,
               size_t slot_bytes) = nullptr;
};

template <MathPolicy M>
class Tracer : private TracerState<M> {
  using S = TracerState<M>;

 public:
  using typename S::R;
  using S::kDirvecGroups;
  using S::kDirvecsPerGroup;
  using S::kMaxReflections;
  using S::kMaxDepth;
  using S::kLightDirvec;
  using S::kDirvecCount;

  // Arena bytes needed to render `scene` at image width `width`.
  static size_t arena_bytes(const Scene<R>& scene, int width) {
    return Arena::footprint<R>(size_t{kDirvecCount} * consts_total(scene)) +
           live_list_bytes(scene.or_count, or_entries_total(scene)) +
           shadow_list_bytes(scene.or_count, or_entries_total(scene)) + pixel_line_bytes(width);
  }

  // Arena bytes that suffice for any valid scene at this width.
  static constexpr size_t max_arena_bytes(int width) {
    return Arena::footprint<R>(size_t{kDirvecCount} * limits::kMaxObjects * 6) +
           live_list_bytes(limits::kMaxOrNetworks, limits::kMaxOrNetworks * limits::kMaxOrNetworkLength) +
           shadow_list_bytes(limits::kMaxOrNetworks, limits::kMaxOrNetworks * limits::kMaxOrNetworkLength) +
           pixel_line_bytes(width);
  }

  // The per-octant lists of live rows and networks (setup_forward_culling).
  static constexpr size_t live_list_bytes(int rows, int nets) {
    return Arena::footprint<typename S::LiveRow>(8 * static_cast<size_t>(rows + 1)) +
           Arena::footprint<typename S::LiveNet>(8 * static_cast<size_t>(nets + rows));
  }

  // The shadow test's rows and networks (setup_shadow_culling).
  static constexpr size_t shadow_list_bytes(int rows, int nets) {
    return Arena::footprint<typename S::ShadowRow>(static_cast<size_t>(rows)) +
           Arena::footprint<typename S::ShadowNet>(static_cast<size_t>(nets));
  }

  // The three rows of per-pixel state the diffuse pass works on, and the
  // finished row handed to the sink.
  static constexpr size_t pixel_line_bytes(int width) {
    return Arena::footprint<Pixel>(3 * static_cast<size_t>(width)) +
           Arena::footprint<uint8_t>(3 * static_cast<size_t>(width));
  }

  // Prepares everything the render needs. Returns false when the arena is
  // too small (arena_bytes tells how much is needed).
  bool init(const Scene<R>& scene, int width, int height, Arena& arena);

  // Renders the whole image, handing each row to `out` as it is finished;
  // once per init (the pixel lines start zeroed, as the original's do).
  void render(const RowSink& out);

  // Rows y0..y1-1 to `out` (no begin/end), the same bytes as render gives
  // them. Calls on one tracer must go down the image (y0 above the previous
  // y1 - 1). Workers rendering in parallel each initialise a tracer of their
  // own and call prepare_bands; without it a tracer replays the rows it
  // skips (band_rows.hpp). `shared` needs prepare_bands, and bands of at
  // least two rows except the last.
  void render_rows(int y0, int y1, const RowSink& out, const SharedRows& shared = {});

  // Lets render_rows skip the rows other workers render, keeping track of
  // the pixel slots they could have written; after init, before any row.
  // False when the arena lacks band_bytes(width).
  bool prepare_bands(Arena& arena);
  static constexpr size_t band_bytes(int width) {
    return Arena::footprint<int16_t>(3 * static_cast<size_t>(width) * kMaxDepth);
  }

  int reflection_count() const { return n_reflections_; }

 private:
  using typename S::DirVec;
  using typename S::Object;
  using typename S::Reflection;
  using typename S::Pixel;
  using typename S::ObjectList;
  using typename S::ShadowLimits;
  using typename S::OrRow;
  using S::width_;
  using S::height_;
  using S::center_;
  using S::scan_pitch_;
  using S::screenx_;
  using S::screeny_;
  using S::screenz_;
  using S::viewpoint_;
  using S::light_;
  using S::beam_;
  using S::n_objects_;
  using S::objects_;
  using S::net_objects_;
  using S::or_rows_;
  using S::n_or_rows_;
  using S::live_rows_;
  using S::live_nets_;
  using S::live_nets_stride_;
  using S::shadow_rows_;
  using S::shadow_nets_;
  using S::n_shadow_rows_;
  using typename S::ShadowRow;
  using typename S::ShadowNet;
  using typename S::LiveRow;
  using typename S::LiveNet;
  using S::live_built_;
  using S::dirvecs_;
  using S::light_dirvec_;
  using S::reflections_;
  using S::n_reflections_;
  using S::lines_;
  using S::lines_through_;
  using S::slot_rows_;
  using S::row_;
  using S::intsec_rectside_;
  using S::tmin_;
  using S::intersection_point_;
  using S::intersected_object_id_;
  using S::nvector_;
  using S::texture_color_;
  using S::diffuse_ray_;
  using S::rgb_;
  using S::startp_;
  using S::startp_fast_;
  using S::culled_start_valid_;
  using S::toward_light_flip_;


  // --- small helpers ------------------------------------------------------

  static int consts_count(int32_t form) {
    return form == kFormBox ? 6 : form == kFormPlane ? 4 : 6;
  }
  // AND networks listed in the OR rows, all rows together.
  static int or_entries_total(const Scene<R>& scene) {
    int n = 0;
    for (int r = 0; r < scene.or_count; ++r)
      for (int k = 1; scene.or_nets[r][k] != -1; ++k) ++n;
    return n;
  }
  static int consts_total(const Scene<R>& scene) {
    int n = 0;
    for (int i = 0; i < scene.object_count; ++i) n += consts_count(scene.objects[i].form);
    return n;
  }
  static R sgn(R x) {
    if (x == R(0)) return R(0);
    if (x > R(0)) return R(1);
    return R(-1);
  }
  static R fneg_cond(bool cond, R x) { return cond ? x : -x; }
  // Clears the sign bit, like OCaml's abs_float (one instruction on x86 and
  // RISC-V F, a bit operation in soft float).
  static R fabs(R x) {
    if constexpr (sizeof(R) == sizeof(float))
      return __builtin_fabsf(x);
    else
      return __builtin_fabs(x);
  }
  static R sqr(R x) { return x * x; }
  static R rad(R deg) { return deg * R(0.017453293); }
  static int add_mod5(int x, int y) {
    const int s = x + y;
    return s >= 5 ? s - 5 : s;
  }
  static void copy3(R* d, const R* s) {
    d[0] = s[0];
    d[1] = s[1];
    d[2] = s[2];
  }
  static void zero3(R* d) { d[0] = d[1] = d[2] = R(0); }
  // The same three numbers bit for bit (signed zeros and NaNs included).
  static bool same_bits(const R* a, const R* b) {
    using U = __UINT64_TYPE__;
    using V = __UINT32_TYPE__;
    for (int k = 0; k < 3; ++k) {
      if constexpr (sizeof(R) == sizeof(U)) {
        if (__builtin_bit_cast(U, a[k]) != __builtin_bit_cast(U, b[k])) return false;
      } else {
        if (__builtin_bit_cast(V, a[k]) != __builtin_bit_cast(V, b[k])) return false;
      }
    }
    return true;
  }
  static R dot(const R* v, const R* w) { return v[0] * w[0] + v[1] * w[1] + v[2] * w[2]; }
  static R dot(const R* v, R w0, R w1, R w2) { return v[0] * w0 + v[1] * w1 + v[2] * w2; }
  static void accum(R* d, R scale, const R* v) {
    d[0] = d[0] + scale * v[0];
    d[1] = d[1] + scale * v[1];
    d[2] = d[2] + scale * v[2];
  }
  static void accum_product(R* d, const R* v, const R* w) {
    d[0] = d[0] + v[0] * w[0];
    d[1] = d[1] + v[1] * w[1];
    d[2] = d[2] + v[2] * w[2];
  }
  static void add3(R* d, const R* v) {
    d[0] = d[0] + v[0];
    d[1] = d[1] + v[1];
    d[2] = d[2] + v[2];
  }
  // Normalises v, negated when `negate`; a zero vector is left as it is.
  static void normalize(R* v, bool negate) {
    const R l = M::sqrt(sqr(v[0]) + sqr(v[1]) + sqr(v[2]));
    const R il = l == R(0) ? R(1) : negate ? R(-1) / l : R(1) / l;
    v[0] = v[0] * il;
    v[1] = v[1] * il;
    v[2] = v[2] * il;
  }

  // --- scene setup --------------------------------------------------------

  void load_environment(const Scene<R>& s);
  void load_objects(const Scene<R>& s);

  // Replaces diag(abc) by R^t diag(abc) R with R = Rz Ry Rx, leaving the
  // diagonal in abc and the doubled off-diagonal terms in rot.
  static void rotate_quadratic_form(R* abc, R* rot);

  // --- quadratic forms ----------------------------------------------------

  MINRT_INLINE static R quadratic(const Object& m, R v0, R v1, R v2);
  static R bilinear(const Object& m, R v0, R v1, R v2, R w0, R w1, R w2);
  // Quadrics are x'Ax = 1; cones and unknown forms x'Ax = 0.
  static R quadric_constant(const Object& m, R cc0);

  // Every solver's result: the original's return code (0: no hit; boxes:
  // the face's axis + 1) and, unless 0, the distance the original left in
  // its global solver_dist. Returned by value so the ray loops keep it in
  // registers instead of storing it through `this`.
  struct Solved {
    int code;
    R dist;
  };
  // Met at a distance below `limit` (the range and shadow tests).
  static bool met_before(Solved s, R limit) { return s.code != 0 && s.dist < limit; }

  // --- general solvers (any direction, ray start in org) ------------------

  // Face i0 of a box (the two others' coordinates in b1, b2): code i0 + 1.
  Solved solve_box_face(const Object& m, const R* dir, R b0, R b1, R b2, int i0, int i1, int i2);
  Solved solver(const Object& m, const R* dir, const R* org);

  // --- table-driven solvers -----------------------------------------------

  // The original also requires the face's 1/v entry to be nonzero; the table
  // stores NaN as that face's coordinate instead (see setup_dirvec_constants),
  // which fails the same comparisons without the extra test.
  MINRT_INLINE Solved solve_box_fast(const Object& m, const R* v, const R* c, R b0, R b1, R b2);

  // The original returns 0 when a = 0; the table holds NaN in c[1] then,
  // which makes d NaN and fails d > 0 without the extra test.
  // kAheadOnly: the caller only uses a positive distance. For an outward
  // surface with 1/a > 0 and -b' <= 0, (-b' - sqrt(d)) / a is negative, so the
  // square root is skipped and 0 is reported as the distance; c[5] is 0 for
  // such surfaces and NaN (never skip) for the others.
  template <bool kAheadOnly = false>
  MINRT_INLINE Solved solve_second_fast(const Object& m, const R* c, R b0, R b1, R b2, R cc);
  static const R* consts_of(const DirVec& dv, const Object& m);

  // Ray along dv from an arbitrary point.
  Solved solver_fast(const Object& m, const DirVec& dv, const R* org);

  // Ray along dv from the point given to setup_startp.
  template <bool kAheadOnly = false>
  MINRT_INLINE Solved solver_fast2(const Object& m, const DirVec& dv);

  // --- direction and start tables -----------------------------------------

  void setup_dirvec_constants(DirVec& dv);

  // kCull: also the objects' forward-culling masks (the diffuse rays use
  // them; see direction_code).
  template <bool kCull = false>
  void setup_startp(const R* p);

  // Masks for forward culling from the point given to setup_startp: per
  // network in each OR row, and for each row the bits all its networks
  // share (any of them culls the whole row). The octants' lists are built
  // when a ray first needs them (build_octant).
  void setup_forward_culling();

  // For octant o of directions, the rows and networks those masks leave: a
  // ray with no zero component walks that list instead of testing every
  // mask.
  void build_octant(int o);

  // Forward culling. A ray from the start point along v reaches points q
  // with fl(q_k - center_k) >= start[k] when v_k >= 0 (rounding is
  // monotonic), so when start[k] >= slab[k] no such point is inside the
  // member, and the member's AND network cannot record a hit (record_hit
  // needs the point inside every member). The same holds mirrored for
  // v_k <= 0. Bit 2k of a code: v_k >= 0; bit 2k+1: v_k <= 0; a network is
  // skipped when its mask shares a bit with the ray's code.
  static uint32_t direction_code(const R* v);

  // slab[] for a non-inverted box is its half-widths (|p_k| < abc_k inside).
  // For an axis-aligned ellipsoid sum abc_k p_k^2 - 1 < 0 inside; every term
  // is >= 0, so |p_k| >= slab_k with fl(fl(slab_k^2) abc_k) > 1 makes the
  // rounded sum exceed 1 too: slab_k is checked in the same arithmetic.
  static void setup_slab(Object& o);

  // --- inside/outside -----------------------------------------------------

  MINRT_INLINE static bool is_outside(const Object& m, R q0, R q1, R q2);

  void build_networks(const Scene<R>& scene);
  static bool all_inside(ObjectList and_net, R q0, R q1, R q2);

  // --- shadows ------------------------------------------------------------

  bool shadow_and_group(ObjectList and_net);
  bool in_shadow();
  void setup_shadow_culling();

  // The least x, as far as a coarse search finds, such that every flipped
  // coordinate >= x is at least `slab` beyond `center` in the rounded
  // subtraction is_outside does (unflipped: fl(x - c) >= slab; flipped, for
  // p = -x: fl(p - c) <= -slab). Rounding is monotonic, so checking x
  // itself covers everything above it. NaN when none is found.
  static R shadow_limit(R center, R slab, bool flipped);

  // The least x, as far as a coarse search finds, with fl(reach + x) >=
  // limit: a start at x or above has every shadow point at `limit` or
  // above (rounding is monotonic). `limit` itself when none is found.
  static R reached_limit(R limit, R reach);

  // A network of one axis-aligned plane casts a shadow only when the
  // plane's distance along the light is below -0.2, which is monotonic in
  // one coordinate of the start: that coordinate's limit goes into `lim`
  // (every axis culls when the plane never meets the light direction).
  void plane_shadow_limit(const Object& m, ShadowLimits& lim);

  // --- nearest intersection -----------------------------------------------

  // A member of AND network and_net solved along v from start: its hit,
  // if any, recorded; false when the rest of the network cannot be hit.
  MINRT_INLINE bool record_hit(ObjectList and_net, const Object& m, Solved s, const R* v, const R* start);
  bool judge_intersection(const R* dir);

  // record_hit for a member along dv from the start point.
  MINRT_INLINE bool trace_member(ObjectList net, const Object& m, const DirVec& dv);
  // A row's range primitive lets the row through: met along dv, nearer
  // than the nearest hit so far.
  MINRT_INLINE bool range_admits(const Object& range, const DirVec& dv);
  // One AND network's members along dv from the start point (kCull: the
  // box masks of setup_startp<true> are valid).
  template <bool kCull>
  MINRT_INLINE void trace_network(ObjectList net, const DirVec& dv);
  MINRT_INLINE void trace_live_network(const LiveNet& live, const DirVec& dv);

  // kCull: skip the networks forward culling rules out (the masks must be
  // set up for the current start point).
  template <bool kCull>
  bool judge_intersection_fast(const DirVec& dv);

  // --- surface normal and colour ------------------------------------------

  void get_nvector(const Object& m, const R* dir);
  void utexture(const Object& m, const R* p);

  // --- direct light -------------------------------------------------------

  static bool adds_light(R bright, R hilight) { return bright > R(0) || hilight > R(0); }
  static bool finite(R x) { return x - x == R(0); }
  void add_light(R bright, R hilight, R hilight_scale);

  // Light reaching the point by way of the mirror surfaces.
  void trace_reflections(R diffuse, R hilight_scale, const R* dir);

  // Follows the eye ray and its mirror reflections, filling `pixel`.
  // kLight false: only what the pixel keeps (surfaces, points, normals,
  // energies), no light; for the rows a band skipped (band_rows.hpp).
  // Returns the slot after the last it wrote (a surface, or the -1 that
  // ends the list); the later slots keep what earlier rows left there.
  template <bool kLight = true>
  int trace_ray(int nref, R energy, R* dir, Pixel& pixel);

  // --- diffuse light ------------------------------------------------------

  MINRT_INLINE void trace_diffuse_ray(const DirVec& dv, R energy);

  // Samples the 60 directions of one group that face along `normal`.
  void trace_diffuse_rays(const DirVec* group, const R* normal, const R* org);
  void pretrace_diffuse_rays(Pixel& pixel);

  // All 300 directions for one point: its own 60 plus the other 240.
  void diffuse_using_1point(Pixel& pixel, int nref);
  void do_without_neighbors(Pixel& pixel, int nref);

  // Uses the 60-ray results of the four neighbours while they hit the same
  // surface at the same depth; falls back to 300 rays from there on.
  void try_exploit_neighbors(int x, Pixel* prev, Pixel* cur, Pixel* next);

  // --- rows ---------------------------------------------------------------

  // kFull false: the pixels' geometry only (trace_ray<false>).
  template <bool kFull>
  void pretrace_line(Pixel* line, int y, int group_id);
  // The eye ray through pixel x of a row: eye_row gives the row's part.
  void eye_row(int y, R* row) const;
  void eye_ray(const R* row, int x, R* dir) const;
  void scan_pixels(int y, Pixel* prev, Pixel* cur, Pixel* next);

  // --- rows in bands (band_rows.hpp) --------------------------------------

  Pixel* line_of(int y) const { return lines_[(y + 1) % 3]; }
  int16_t* slot_rows_of(int y, int x) const { return slot_rows_ + ((y + 1) % 3 * width_ + x) * kMaxDepth; }
  // After the full trace of row y wrote slots 0..written-1 of `pixel`
  // (column x): the slot rows, and the slots that trace lets the diffuse
  // pass read brought up to date (resolve_slots).
  void track_slots(Pixel& pixel, int x, int y, int written);
  void resolve_slots(Pixel& pixel, int16_t* rows, int x, int y, int n);

  // --- diffuse direction tables -------------------------------------------

  static R adjust_position(R h, R ratio);
  void calc_dirvec(R rx, R ry, int group_id, int index);
  static void set3(R* v, R a, R b, R c);

  // 600 directions: a 10x10 grid on each face of a cube, bent towards a
  // uniform spread on the sphere, dealt out to 5 groups of 120.
  void init_dirvecs();

  // --- mirrors ------------------------------------------------------------

  void add_reflection(int surface_id, R bright, R v0, R v1, R v2);

  // original: only the last object is examined (the function never recurses
  // to the others), so at most one mirror box or plane reflects the light.
  void setup_reflections(int obj_id);

};

}  // namespace minrt
