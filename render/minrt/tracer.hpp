// The min-rt rendering algorithm: direct rays with mirror recursion, shadow
// tests through the OR/AND networks, highlights, textures and the diffuse
// (indirect) light sampled over 300 precomputed directions, shared between a
// pixel and its four neighbours. Every floating-point expression keeps the
// original program's operand order, so the double/libm build reproduces the
// original's output bit for bit. Quirks of the original that change pixels
// are kept on purpose and marked "original:".
#pragma once

#include <stdint.h>

#include "formats/sld/sld_limits.hpp"

#include "core/base/arena.hpp"
#include "core/math/math_policy.hpp"
#include "core/image/row_sink.hpp"
#include "formats/sld/scene.hpp"

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

template <MathPolicy M>
class Tracer {
 public:
  using R = typename M::real;

  static constexpr int kDirvecGroups = 5;
  static constexpr int kDirvecsPerGroup = 120;
  static constexpr int kMaxReflections = 3;  // see setup_reflections
  static constexpr int kMaxDepth = 5;        // reflection levels 0..4
  // Direction tables: the diffuse groups, then the light, then the mirrors.
  static constexpr int kLightDirvec = kDirvecGroups * kDirvecsPerGroup;
  static constexpr int kDirvecCount = kLightDirvec + 1 + kMaxReflections;

  // Arena bytes needed to render `scene` at image width `width`.
  static size_t arena_bytes(const Scene<R>& scene, int width) {
    return Arena::footprint<R>(size_t{kDirvecCount} * consts_total(scene)) + pixel_line_bytes(width);
  }

  // Arena bytes that suffice for any valid scene at this width.
  static constexpr size_t max_arena_bytes(int width) {
    return Arena::footprint<R>(size_t{kDirvecCount} * limits::kMaxObjects * 6) + pixel_line_bytes(width);
  }

  // The three rows of per-pixel state the diffuse pass works on, and the
  // finished row handed to the sink.
  static constexpr size_t pixel_line_bytes(int width) {
    return Arena::footprint<Pixel>(3 * static_cast<size_t>(width)) +
           Arena::footprint<uint8_t>(3 * static_cast<size_t>(width));
  }

  // Prepares everything the render needs. Returns false when the arena is
  // too small (arena_bytes tells how much is needed).
  bool init(const Scene<R>& scene, int width, int height, Arena& arena) {
    width_ = width;
    height_ = height;
    center_[0] = width / 2;
    center_[1] = height / 2;
    scan_pitch_ = R(128.0) / M::from_int(width);
    load_environment(scene);
    load_objects(scene);
    build_networks(scene);
    n_reflections_ = 0;

    const int stride = consts_total(scene);
    R* consts = arena.alloc_zeroed<R>(size_t{kDirvecCount} * stride);
    Pixel* pixels = arena.alloc_zeroed<Pixel>(3 * static_cast<size_t>(width));
    row_ = arena.alloc_zeroed<uint8_t>(3 * static_cast<size_t>(width));
    if (consts == nullptr || pixels == nullptr || row_ == nullptr) return false;
    for (int g = 0; g < kDirvecGroups; ++g)
      for (int i = 0; i < kDirvecsPerGroup; ++i)
        dirvecs_[g][i].c = consts + (g * kDirvecsPerGroup + i) * stride;
    light_dirvec_.c = consts + kLightDirvec * stride;
    for (int r = 0; r < kMaxReflections; ++r)
      reflections_[r].dvec.c = consts + (kLightDirvec + 1 + r) * stride;
    for (int l = 0; l < 3; ++l) lines_[l] = pixels + l * width;

    init_dirvecs();
    copy3(light_dirvec_.v, light_);
    setup_dirvec_constants(light_dirvec_);
    setup_shadow_culling();
    setup_reflections(n_objects_ - 1);
    return true;
  }

  // Renders the whole image, handing each row to `out` as it is finished.
  void render(const RowSink& out) {
    out.begin(width_, height_);
    Pixel* prev = lines_[0];
    Pixel* cur = lines_[1];
    Pixel* next = lines_[2];
    pretrace_line(cur, 0, 0);
    int group_id = 2;
    for (int y = 0; y < height_; ++y) {
      if (y < height_ - 1) pretrace_line(next, y + 1, group_id);
      scan_pixels(y, prev, cur, next);
      out.row(y, row_);
      Pixel* old_prev = prev;
      prev = cur;
      cur = next;
      next = old_prev;
      group_id = add_mod5(group_id, 2);
    }
    out.end();
  }

  int reflection_count() const { return n_reflections_; }

 private:
  // Per-direction tables: for each object, the constants its fast solver
  // needs for rays along `v` (6 for boxes, 4 for planes, 6 otherwise).
  struct DirVec {
    R v[3];
    R* c;
    uint32_t code;  // direction_code(v)
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

  // --- small helpers ------------------------------------------------------

  static int consts_count(int32_t form) {
    return form == kFormBox ? 6 : form == kFormPlane ? 4 : 6;
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

  void load_environment(const Scene<R>& s) {
    const R v1 = rad(s.screen_rotation_deg[0]);
    const R cos_v1 = M::cos(v1), sin_v1 = M::sin(v1);
    const R v2 = rad(s.screen_rotation_deg[1]);
    const R cos_v2 = M::cos(v2), sin_v2 = M::sin(v2);
    screenz_[0] = cos_v1 * sin_v2 * R(200.0);
    screenz_[1] = sin_v1 * R(-200.0);
    screenz_[2] = cos_v1 * cos_v2 * R(200.0);
    screenx_[0] = cos_v2;
    screenx_[1] = R(0);
    screenx_[2] = -sin_v2;
    screeny_[0] = -sin_v1 * sin_v2;
    screeny_[1] = -cos_v1;
    screeny_[2] = -sin_v1 * cos_v2;
    for (int i = 0; i < 3; ++i) viewpoint_[i] = s.screen[i] - screenz_[i];

    const R l1 = rad(s.light_rotation_deg[0]);
    light_[1] = -M::sin(l1);
    const R l2 = rad(s.light_rotation_deg[1]);
    const R cl1 = M::cos(l1);
    light_[0] = cl1 * M::sin(l2);
    light_[2] = cl1 * M::cos(l2);
    beam_ = s.beam;
  }

  void load_objects(const Scene<R>& s) {
    n_objects_ = s.object_count;
    int offset = 0;
    for (int i = 0; i < n_objects_; ++i) {
      const SceneObject<R>& in = s.objects[i];
      Object& o = objects_[i];
      o.texture = in.texture;
      o.form = in.form;
      o.reflection = in.reflection;
      o.rotated = in.rotated;
      copy3(o.abc, in.abc);
      copy3(o.center, in.center);
      o.diffuse = in.diffuse;
      o.hilight = in.hilight;
      copy3(o.color, in.color);
      for (int k = 0; k < 3; ++k) o.rot[k] = in.rotated != 0 ? rad(in.rotation_deg[k]) : R(0);
      for (int k = 0; k < 4; ++k) o.start[k] = R(0);
      // Planes always count as inverted; the sign read from the file only
      // orients their normal.
      o.inverted = o.form == kFormPlane ? true : in.inverted;
      if (o.form == kFormQuadric) {
        for (int k = 0; k < 3; ++k) {
          const R a = o.abc[k];
          o.abc[k] = a == R(0) ? R(0) : sgn(a) / sqr(a);
        }
      } else if (o.form == kFormPlane) {
        normalize(o.abc, !in.inverted);
      }
      // original: the rotation is applied to every form, boxes and planes too.
      if (o.rotated != 0) rotate_quadratic_form(o.abc, o.rot);
      setup_slab(o);
      o.consts_offset = offset * static_cast<int>(sizeof(R));
      o.index = i;
      offset += consts_count(o.form);
    }
  }

  // Replaces diag(abc) by R^t diag(abc) R with R = Rz Ry Rx, leaving the
  // diagonal in abc and the doubled off-diagonal terms in rot.
  static void rotate_quadratic_form(R* abc, R* rot) {
    const R cos_x = M::cos(rot[0]), sin_x = M::sin(rot[0]);
    const R cos_y = M::cos(rot[1]), sin_y = M::sin(rot[1]);
    const R cos_z = M::cos(rot[2]), sin_z = M::sin(rot[2]);
    const R m00 = cos_y * cos_z;
    const R m01 = sin_x * sin_y * cos_z - cos_x * sin_z;
    const R m02 = cos_x * sin_y * cos_z + sin_x * sin_z;
    const R m10 = cos_y * sin_z;
    const R m11 = sin_x * sin_y * sin_z + cos_x * cos_z;
    const R m12 = cos_x * sin_y * sin_z - sin_x * cos_z;
    const R m20 = -sin_y;
    const R m21 = sin_x * cos_y;
    const R m22 = cos_x * cos_y;
    const R ao = abc[0], bo = abc[1], co = abc[2];
    abc[0] = ao * sqr(m00) + bo * sqr(m10) + co * sqr(m20);
    abc[1] = ao * sqr(m01) + bo * sqr(m11) + co * sqr(m21);
    abc[2] = ao * sqr(m02) + bo * sqr(m12) + co * sqr(m22);
    rot[0] = R(2.0) * (ao * m01 * m02 + bo * m11 * m12 + co * m21 * m22);
    rot[1] = R(2.0) * (ao * m00 * m02 + bo * m10 * m12 + co * m20 * m22);
    rot[2] = R(2.0) * (ao * m00 * m01 + bo * m10 * m11 + co * m20 * m21);
  }

  // --- quadratic forms ----------------------------------------------------

  MINRT_INLINE static R quadratic(const Object& m, R v0, R v1, R v2) {
    const R diag = sqr(v0) * m.abc[0] + sqr(v1) * m.abc[1] + sqr(v2) * m.abc[2];
    if (m.rotated == 0) return diag;
    return diag + v1 * v2 * m.rot[0] + v2 * v0 * m.rot[1] + v0 * v1 * m.rot[2];
  }
  static R bilinear(const Object& m, R v0, R v1, R v2, R w0, R w1, R w2) {
    const R diag = v0 * w0 * m.abc[0] + v1 * w1 * m.abc[1] + v2 * w2 * m.abc[2];
    if (m.rotated == 0) return diag;
    return diag + ((v2 * w1 + v1 * w2) * m.rot[0] + (v0 * w2 + v2 * w0) * m.rot[1] +
                   (v0 * w1 + v1 * w0) * m.rot[2]) *
                      R(0.5);
  }
  // Quadrics are x'Ax = 1; cones and unknown forms x'Ax = 0.
  static R quadric_constant(const Object& m, R cc0) {
    return m.form == kFormQuadric ? cc0 - R(1.0) : cc0;
  }

  // --- general solvers (ray start in startp_) -----------------------------

  bool solve_box_face(const Object& m, const R* dir, R b0, R b1, R b2, int i0, int i1, int i2) {
    if (dir[i0] == R(0)) return false;
    const R d = fneg_cond(m.inverted != (dir[i0] < R(0)), m.abc[i0]);
    const R d2 = (d - b0) / dir[i0];
    if (fabs(d2 * dir[i1] + b1) < m.abc[i1] && fabs(d2 * dir[i2] + b2) < m.abc[i2]) {
      solver_dist_ = d2;
      return true;
    }
    return false;
  }

  int solver(const Object& m, const R* dir, const R* org) {
    const R b0 = org[0] - m.center[0];
    const R b1 = org[1] - m.center[1];
    const R b2 = org[2] - m.center[2];
    if (m.form == kFormBox) {
      if (solve_box_face(m, dir, b0, b1, b2, 0, 1, 2)) return 1;
      if (solve_box_face(m, dir, b1, b2, b0, 1, 2, 0)) return 2;
      if (solve_box_face(m, dir, b2, b0, b1, 2, 0, 1)) return 3;
      return 0;
    }
    if (m.form == kFormPlane) {
      const R d = dot(dir, m.abc);
      if (d > R(0)) {
        solver_dist_ = -dot(m.abc, b0, b1, b2) / d;
        return 1;
      }
      return 0;
    }
    const R aa = quadratic(m, dir[0], dir[1], dir[2]);
    if (aa == R(0)) return 0;
    const R bb = bilinear(m, dir[0], dir[1], dir[2], b0, b1, b2);
    const R cc = quadric_constant(m, quadratic(m, b0, b1, b2));
    const R d = sqr(bb) - aa * cc;
    if (d > R(0)) {
      const R sd = M::sqrt(d);
      const R t1 = m.inverted ? sd : -sd;
      solver_dist_ = (t1 - bb) / aa;
      return 1;
    }
    return 0;
  }

  // --- table-driven solvers -----------------------------------------------

  // The original also requires the face's 1/v entry to be nonzero; the table
  // stores NaN as that face's coordinate instead (see setup_dirvec_constants),
  // which fails the same comparisons without the extra test.
  MINRT_INLINE int solve_box_fast(const Object& m, const R* v, const R* c, R b0, R b1, R b2) {
    const R d0 = (c[0] - b0) * c[1];
    if (fabs(d0 * v[1] + b1) < m.abc[1] && fabs(d0 * v[2] + b2) < m.abc[2]) {
      solver_dist_ = d0;
      return 1;
    }
    const R d1 = (c[2] - b1) * c[3];
    if (fabs(d1 * v[0] + b0) < m.abc[0] && fabs(d1 * v[2] + b2) < m.abc[2]) {
      solver_dist_ = d1;
      return 2;
    }
    const R d2 = (c[4] - b2) * c[5];
    if (fabs(d2 * v[0] + b0) < m.abc[0] && fabs(d2 * v[1] + b1) < m.abc[1]) {
      solver_dist_ = d2;
      return 3;
    }
    return 0;
  }

  // The original returns 0 when a = 0; the table holds NaN in c[1] then,
  // which makes d NaN and fails d > 0 without the extra test.
  // kAheadOnly: the caller only uses a positive distance. For an outward
  // surface with 1/a > 0 and -b' <= 0, (-b' - sqrt(d)) / a is negative, so the
  // square root is skipped and 0 is reported as the distance; c[5] is 0 for
  // such surfaces and NaN (never skip) for the others.
  template <bool kAheadOnly = false>
  MINRT_INLINE int solve_second_fast(const Object& m, const R* c, R b0, R b1, R b2, R cc) {
    const R aa = c[0];
    const R neg_bb = c[1] * b0 + c[2] * b1 + c[3] * b2;
    const R d = sqr(neg_bb) - aa * cc;
    if (d > R(0)) {
      if (kAheadOnly && neg_bb <= c[5]) {
        solver_dist_ = R(0);
        return 1;
      }
      solver_dist_ = m.inverted ? (neg_bb + M::sqrt(d)) * c[4] : (neg_bb - M::sqrt(d)) * c[4];
      return 1;
    }
    return 0;
  }

  static const R* consts_of(const DirVec& dv, const Object& m) {
    return reinterpret_cast<const R*>(reinterpret_cast<const char*>(dv.c) + m.consts_offset);
  }

  // Ray along dv from an arbitrary point.
  int solver_fast(const Object& m, const DirVec& dv, const R* org) {
    const R b0 = org[0] - m.center[0];
    const R b1 = org[1] - m.center[1];
    const R b2 = org[2] - m.center[2];
    const R* c = consts_of(dv, m);
    if (m.form == kFormBox) return solve_box_fast(m, dv.v, c, b0, b1, b2);
    if (m.form == kFormPlane) {
      if (c[0] < R(0)) {
        solver_dist_ = c[1] * b0 + c[2] * b1 + c[3] * b2;
        return 1;
      }
      return 0;
    }
    return solve_second_fast(m, c, b0, b1, b2, quadric_constant(m, quadratic(m, b0, b1, b2)));
  }

  // Ray along dv from the point given to setup_startp.
  template <bool kAheadOnly = false>
  MINRT_INLINE int solver_fast2(const Object& m, const DirVec& dv) {
    const R* s = m.start;
    const R* c = consts_of(dv, m);
    if (m.form == kFormBox) return solve_box_fast(m, dv.v, c, s[0], s[1], s[2]);
    if (m.form == kFormPlane) {
      if (c[0] < R(0)) {
        solver_dist_ = c[0] * s[3];
        return 1;
      }
      return 0;
    }
    return solve_second_fast<kAheadOnly>(m, c, s[0], s[1], s[2], s[3]);
  }

  // --- direction and start tables -----------------------------------------

  void setup_dirvec_constants(DirVec& dv) {
    const R* v = dv.v;
    dv.code = direction_code(v);
    for (int i = n_objects_ - 1; i >= 0; --i) {
      const Object& m = objects_[i];
      R* c = const_cast<R*>(consts_of(dv, m));
      if (m.form == kFormBox) {
        for (int k = 0; k < 3; ++k) {
          if (v[k] == R(0)) {
            c[2 * k] = R(__builtin_nan(""));
            c[2 * k + 1] = R(0);
          } else {
            c[2 * k] = fneg_cond(m.inverted != (v[k] < R(0)), m.abc[k]);
            c[2 * k + 1] = R(1.0) / v[k];
          }
        }
      } else if (m.form == kFormPlane) {
        const R d = v[0] * m.abc[0] + v[1] * m.abc[1] + v[2] * m.abc[2];
        if (d > R(0)) {
          c[0] = R(-1.0) / d;
          c[1] = -(m.abc[0] / d);
          c[2] = -(m.abc[1] / d);
          c[3] = -(m.abc[2] / d);
        } else {
          c[0] = R(0);
        }
      } else {
        const R aa = quadratic(m, v[0], v[1], v[2]);
        const R c1 = -(v[0] * m.abc[0]);
        const R c2 = -(v[1] * m.abc[1]);
        const R c3 = -(v[2] * m.abc[2]);
        c[0] = aa;
        if (m.rotated != 0) {
          c[1] = c1 - (v[2] * m.rot[1] + v[1] * m.rot[2]) * R(0.5);
          c[2] = c2 - (v[2] * m.rot[0] + v[0] * m.rot[2]) * R(0.5);
          c[3] = c3 - (v[1] * m.rot[0] + v[0] * m.rot[1]) * R(0.5);
        } else {
          c[1] = c1;
          c[2] = c2;
          c[3] = c3;
        }
        if (aa != R(0)) c[4] = R(1.0) / aa;
        else c[1] = R(__builtin_nan(""));
        c[5] = aa != R(0) && !m.inverted && c[4] > R(0) ? R(0) : R(__builtin_nan(""));
      }
    }
  }

  // kCull: also the objects' forward-culling masks (the diffuse rays use
  // them; see direction_code).
  template <bool kCull = false>
  void setup_startp(const R* p) {
    copy3(startp_fast_, p);
    for (int i = n_objects_ - 1; i >= 0; --i) {
      Object& m = objects_[i];
      R* s = m.start;
      s[0] = p[0] - m.center[0];
      s[1] = p[1] - m.center[1];
      s[2] = p[2] - m.center[2];
      if (kCull) {
        uint32_t mask = 0;
        if (m.slab_bounded)
          for (int k = 0; k < 3; ++k)
            mask |= uint32_t{s[k] >= m.slab[k]} << (2 * k) | uint32_t{s[k] <= -m.slab[k]} << (2 * k + 1);
        m.fwd = mask;
      }
      if (m.form == kFormPlane) {
        s[3] = dot(m.abc, s[0], s[1], s[2]);
      } else if (m.form > kFormPlane) {
        s[3] = quadric_constant(m, quadratic(m, s[0], s[1], s[2]));
      }
      // original: forms below 1 keep a stale constant term here.
    }
  }

  // Masks for forward culling from the point given to setup_startp: per
  // network in each OR row, and for each row the bits all its networks
  // share (any of them culls the whole row).
  void setup_forward_culling() {
    for (int r = 0; r < n_or_rows_; ++r) {
      OrRow& row = or_rows_[r];
      uint32_t all = ~0u;
      for (int k = 0; row.nets[k] != nullptr; ++k) {
        uint32_t mask = 0;
        for (ObjectList e = row.nets[k]; *e != nullptr; ++e) mask |= (*e)->fwd;
        row.fwd[k] = mask;
        all &= mask;
      }
      row.fwd_all = all;
    }
  }

  // Forward culling. A ray from the start point along v reaches points q
  // with fl(q_k - center_k) >= start[k] when v_k >= 0 (rounding is
  // monotonic), so when start[k] >= slab[k] no such point is inside the
  // member, and the member's AND network cannot record a hit (record_hit
  // needs the point inside every member). The same holds mirrored for
  // v_k <= 0. Bit 2k of a code: v_k >= 0; bit 2k+1: v_k <= 0; a network is
  // skipped when its mask shares a bit with the ray's code.
  static uint32_t direction_code(const R* v) {
    uint32_t c = 0;
    for (int k = 0; k < 3; ++k) {
      if (v[k] >= R(0)) c |= 1u << (2 * k);
      if (v[k] <= R(0)) c |= 2u << (2 * k);
    }
    return c;
  }

  // slab[] for a non-inverted box is its half-widths (|p_k| < abc_k inside).
  // For an axis-aligned ellipsoid sum abc_k p_k^2 - 1 < 0 inside; every term
  // is >= 0, so |p_k| >= slab_k with fl(fl(slab_k^2) abc_k) > 1 makes the
  // rounded sum exceed 1 too: slab_k is checked in the same arithmetic.
  static void setup_slab(Object& o) {
    o.slab_bounded = false;
    if (o.inverted) return;
    if (o.form == kFormBox) {
      copy3(o.slab, o.abc);
      o.slab_bounded = true;
      return;
    }
    if (o.form != kFormQuadric || o.rotated != 0) return;
    for (int k = 0; k < 3; ++k) {
      const R a = o.abc[k];
      if (!(a > R(0)) || !finite(a)) return;
      R h = R(1.001) / M::sqrt(a);
      for (int tries = 0; !(sqr(h) * a - R(1.0) > R(0)); ++tries) {
        if (tries == 8 || !finite(h)) return;
        h = h * R(1.01);
      }
      o.slab[k] = h;
    }
    o.slab_bounded = true;
  }

  // --- inside/outside -----------------------------------------------------

  MINRT_INLINE static bool is_outside(const Object& m, R q0, R q1, R q2) {
    const R p0 = q0 - m.center[0];
    const R p1 = q1 - m.center[1];
    const R p2 = q2 - m.center[2];
    if (m.form == kFormBox) {
      const bool inside = fabs(p0) < m.abc[0] && fabs(p1) < m.abc[1] && fabs(p2) < m.abc[2];
      return inside ? m.inverted : !m.inverted;
    }
    if (m.form == kFormPlane) return m.inverted == (dot(m.abc, p0, p1, p2) < R(0));
    return m.inverted == (quadric_constant(m, quadratic(m, p0, p1, p2)) < R(0));
  }

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
    uint32_t fwd[limits::kMaxOrNetworkLength];  // see setup_forward_culling
    uint32_t fwd_all;
    ShadowLimits shadow[limits::kMaxOrNetworkLength];  // see setup_shadow_culling
    ShadowLimits shadow_all;
  };

  void build_networks(const Scene<R>& scene) {
    for (int n = 0; n < scene.and_count; ++n) {
      int k = 0;
      for (; scene.and_nets[n][k] != -1; ++k) net_objects_[n][k] = &objects_[scene.and_nets[n][k]];
      net_objects_[n][k] = nullptr;
    }
    n_or_rows_ = scene.or_count;
    for (int r = 0; r < scene.or_count; ++r) {
      const int16_t* in = scene.or_nets[r];
      OrRow& row = or_rows_[r];
      row.range = in[0] == limits::kNoRangePrimitive ? nullptr : &objects_[in[0]];
      int k = 1;
      for (; in[k] != -1; ++k) row.nets[k - 1] = net_objects_[in[k]];
      row.nets[k - 1] = nullptr;
    }
  }

  static bool all_inside(ObjectList and_net, R q0, R q1, R q2) {
    for (; *and_net != nullptr; ++and_net)
      if (is_outside(**and_net, q0, q1, q2)) return false;
    return true;
  }

  // --- shadows ------------------------------------------------------------

  bool shadow_and_group(ObjectList and_net) {
    for (ObjectList e = and_net; *e != nullptr; ++e) {
      const Object& obj = **e;
      const int t0 = solver_fast(obj, light_dirvec_, intersection_point_);
      const R t0p = solver_dist_;
      if (t0 != 0 && t0p < R(-0.2)) {
        const R t = t0p + R(0.01);
        const R q0 = light_[0] * t + intersection_point_[0];
        const R q1 = light_[1] * t + intersection_point_[1];
        const R q2 = light_[2] * t + intersection_point_[2];
        if (all_inside(and_net, q0, q1, q2)) return true;
      } else if (!obj.inverted) {
        // No hit on an object whose inside counts: the AND set lies within
        // it, so nothing else of the set can be hit either.
        return false;
      }
    }
    return false;
  }

  bool in_shadow() {
    // The start with each axis signed so that moving towards the light never
    // decreases it (see setup_shadow_culling).
    const R* p = intersection_point_;
    const R x0 = toward_light_flip_[0] ? -p[0] : p[0];
    const R x1 = toward_light_flip_[1] ? -p[1] : p[1];
    const R x2 = toward_light_flip_[2] ? -p[2] : p[2];
    for (int r = 0; r < n_or_rows_; ++r) {
      const OrRow& row = or_rows_[r];
      if (row.shadow_all.culls(x0, x1, x2)) continue;
      if (row.range != nullptr &&
          !(solver_fast(*row.range, light_dirvec_, intersection_point_) != 0 &&
            solver_dist_ < R(-0.1)))
        continue;
      for (int k = 0; row.nets[k] != nullptr; ++k)
        if (!row.shadow[k].culls(x0, x1, x2) && shadow_and_group(row.nets[k])) return true;
    }
    return false;
  }

  void setup_shadow_culling() {
    const R nan = R(__builtin_nan(""));
    for (int k = 0; k < 3; ++k) toward_light_flip_[k] = light_[k] > R(0);
    for (int r = 0; r < n_or_rows_; ++r) {
      OrRow& row = or_rows_[r];
      // The highest limit of the row's networks per axis, NaN when one of
      // them has none; a row without networks shadows nothing at all.
      const R inf = R(__builtin_inf());
      ShadowLimits all{{-inf, -inf, -inf}};
      for (int n = 0; row.nets[n] != nullptr; ++n) {
        ShadowLimits& lim = row.shadow[n];
        lim = ShadowLimits{{nan, nan, nan}};
        for (ObjectList e = row.nets[n]; *e != nullptr; ++e) {
          const Object& m = **e;
          if (!m.slab_bounded) continue;
          for (int k = 0; k < 3; ++k) {
            const R x = shadow_limit(m.center[k], m.slab[k], toward_light_flip_[k]);
            if (!(lim.limit[k] <= x)) lim.limit[k] = x;  // the lowest, NaN replaced
          }
        }
        for (int k = 0; k < 3; ++k)
          if (all.limit[k] < lim.limit[k] || lim.limit[k] != lim.limit[k]) all.limit[k] = lim.limit[k];
      }
      row.shadow_all = all;
    }
  }

  // The least x, as far as a coarse search finds, such that every flipped
  // coordinate >= x is at least `slab` beyond `center` in the rounded
  // subtraction is_outside does (unflipped: fl(x - c) >= slab; flipped, for
  // p = -x: fl(p - c) <= -slab). Rounding is monotonic, so checking x
  // itself covers everything above it. NaN when none is found.
  static R shadow_limit(R center, R slab, bool flipped) {
    const R c = flipped ? -center : center;
    R x = c + slab;
    for (int tries = 0; tries < 64; ++tries) {
      const R diff = flipped ? (-x) - center : x - center;
      if (flipped ? diff <= -slab : diff >= slab) return x;
      x = x + (fabs(x) + fabs(c) + fabs(slab)) * R(1.0e-6);
    }
    return R(__builtin_nan(""));
  }

  // --- nearest intersection -----------------------------------------------

  MINRT_INLINE void record_hit(ObjectList and_net, const Object& m, int t0, const R* v,
                               const R* start) {
    const R t0p = solver_dist_;
    if (R(0) < t0p && t0p < tmin_) {
      const R t = t0p + R(0.01);
      const R q0 = v[0] * t + start[0];
      const R q1 = v[1] * t + start[1];
      const R q2 = v[2] * t + start[2];
      if (all_inside(and_net, q0, q1, q2)) {
        tmin_ = t;
        intersection_point_[0] = q0;
        intersection_point_[1] = q1;
        intersection_point_[2] = q2;
        intersected_object_id_ = m.index;
        intsec_rectside_ = t0;
      }
    }
  }

  bool judge_intersection(const R* dir) {
    tmin_ = R(1000000000.0);
    for (int r = 0; r < n_or_rows_; ++r) {
      const OrRow& row = or_rows_[r];
      if (row.range != nullptr && !(solver(*row.range, dir, startp_) != 0 && solver_dist_ < tmin_))
        continue;
      for (const ObjectList* a = row.nets; *a != nullptr; ++a) {
        for (ObjectList e = *a; *e != nullptr; ++e) {
          const Object& m = **e;
          const int t0 = solver(m, dir, startp_);
          if (t0 != 0)
            record_hit(*a, m, t0, dir, startp_);
          else if (!m.inverted)
            break;
        }
      }
    }
    return R(-0.1) < tmin_ && tmin_ < R(100000000.0);
  }

  // kCull: skip the networks forward culling rules out (the masks must be
  // set up for the current start point).
  template <bool kCull>
  bool judge_intersection_fast(const DirVec& dv) {
    tmin_ = R(1000000000.0);
    const uint32_t code = dv.code;
    for (int r = 0; r < n_or_rows_; ++r) {
      const OrRow& row = or_rows_[r];
      if (kCull && (row.fwd_all & code) != 0) continue;
      if (row.range != nullptr && !(solver_fast2(*row.range, dv) != 0 && solver_dist_ < tmin_))
        continue;
      for (int k = 0; row.nets[k] != nullptr; ++k) {
        if (kCull && (row.fwd[k] & code) != 0) continue;
        const ObjectList net = row.nets[k];
        for (ObjectList e = net; *e != nullptr; ++e) {
          const Object& m = **e;
          const int t0 = solver_fast2<true>(m, dv);
          if (t0 != 0)
            record_hit(net, m, t0, dv.v, startp_fast_);
          else if (!m.inverted)
            break;
        }
      }
    }
    return R(-0.1) < tmin_ && tmin_ < R(100000000.0);
  }

  // --- surface normal and colour ------------------------------------------

  void get_nvector(const Object& m, const R* dir) {
    if (m.form == kFormBox) {
      const int side = intsec_rectside_ - 1;
      zero3(nvector_);
      nvector_[side] = -sgn(dir[side]);
    } else if (m.form == kFormPlane) {
      nvector_[0] = -m.abc[0];
      nvector_[1] = -m.abc[1];
      nvector_[2] = -m.abc[2];
    } else {
      const R p0 = intersection_point_[0] - m.center[0];
      const R p1 = intersection_point_[1] - m.center[1];
      const R p2 = intersection_point_[2] - m.center[2];
      const R d0 = p0 * m.abc[0];
      const R d1 = p1 * m.abc[1];
      const R d2 = p2 * m.abc[2];
      if (m.rotated == 0) {
        nvector_[0] = d0;
        nvector_[1] = d1;
        nvector_[2] = d2;
      } else {
        nvector_[0] = d0 + (p1 * m.rot[2] + p2 * m.rot[1]) * R(0.5);
        nvector_[1] = d1 + (p0 * m.rot[2] + p2 * m.rot[0]) * R(0.5);
        nvector_[2] = d2 + (p0 * m.rot[1] + p1 * m.rot[0]) * R(0.5);
      }
      normalize(nvector_, m.inverted);
    }
  }

  void utexture(const Object& m, const R* p) {
    copy3(texture_color_, m.color);
    switch (m.texture) {
      case kTextureChecker: {
        const R w1 = p[0] - m.center[0];
        const bool flag1 = w1 - M::floor(w1 * R(0.05)) * R(20.0) < R(10.0);
        const R w3 = p[2] - m.center[2];
        const bool flag2 = w3 - M::floor(w3 * R(0.05)) * R(20.0) < R(10.0);
        texture_color_[1] = flag1 == flag2 ? R(255.0) : R(0.0);
        break;
      }
      case kTextureStripes: {
        const R w2 = sqr(M::sin(p[1] * R(0.25)));
        texture_color_[0] = R(255.0) * w2;
        texture_color_[1] = R(255.0) * (R(1.0) - w2);
        break;
      }
      case kTextureRings: {
        const R w1 = p[0] - m.center[0];
        const R w3 = p[2] - m.center[2];
        const R w2 = M::sqrt(sqr(w1) + sqr(w3)) / R(10.0);
        const R w4 = (w2 - M::floor(w2)) * R(3.1415927);
        const R cws = sqr(M::cos(w4));
        texture_color_[1] = cws * R(255.0);
        texture_color_[2] = (R(1.0) - cws) * R(255.0);
        break;
      }
      case kTextureSpots: {
        const R w1 = (p[0] - m.center[0]) * M::sqrt(m.abc[0]);
        const R w3 = (p[2] - m.center[2]) * M::sqrt(m.abc[2]);
        const R w4 = sqr(w1) + sqr(w3);
        const R w7 = fabs(w1) < R(1.0e-4) ? R(15.0)
                                           : M::atan(fabs(w3 / w1)) * R(30.0) / R(3.1415927);
        const R w9 = w7 - M::floor(w7);
        const R w2 = (p[1] - m.center[1]) * M::sqrt(m.abc[1]);
        const R w8 = fabs(w4) < R(1.0e-4) ? R(15.0)
                                           : M::atan(fabs(w2 / w4)) * R(30.0) / R(3.1415927);
        const R w10 = w8 - M::floor(w8);
        const R w11 = R(0.15) - sqr(R(0.5) - w9) - sqr(R(0.5) - w10);
        const R w12 = w11 < R(0) ? R(0.0) : w11;
        texture_color_[2] = R(255.0) * w12 / R(0.3);
        break;
      }
      default:
        break;
    }
  }

  // --- direct light -------------------------------------------------------

  static bool adds_light(R bright, R hilight) { return bright > R(0) || hilight > R(0); }
  static bool finite(R x) { return x - x == R(0); }

  void add_light(R bright, R hilight, R hilight_scale) {
    if (bright > R(0)) accum(rgb_, bright, texture_color_);
    if (hilight > R(0)) {
      const R ihl = sqr(sqr(hilight)) * hilight_scale;
      rgb_[0] = rgb_[0] + ihl;
      rgb_[1] = rgb_[1] + ihl;
      rgb_[2] = rgb_[2] + ihl;
    }
  }

  // Light reaching the point by way of the mirror surfaces.
  void trace_reflections(R diffuse, R hilight_scale, const R* dir) {
    for (int i = n_reflections_ - 1; i >= 0; --i) {
      const Reflection& r = reflections_[i];
      if (!judge_intersection_fast<false>(r.dvec)) continue;
      if (intersected_object_id_ * 4 + intsec_rectside_ != r.surface_id) continue;
      const R p = dot(nvector_, r.dvec.v);
      const R scale = r.bright;
      const R bright = scale * diffuse * p;
      const R hilight = scale * dot(dir, r.dvec.v);
      // add_light adds nothing unless one of them is positive, so the shadow
      // test (pure) is only needed then.
      if (adds_light(bright, hilight) && !in_shadow()) add_light(bright, hilight, hilight_scale);
    }
  }

  // Follows the eye ray and its mirror reflections, filling `pixel`.
  void trace_ray(int nref, R energy, R* dir, Pixel& pixel) {
    for (; nref < kMaxDepth; ++nref) {
      if (!judge_intersection(dir)) {
        pixel.surface_ids[nref] = -1;
        if (nref != 0) {
          const R hl = -dot(dir, light_);
          if (hl > R(0)) {
            const R ihl = sqr(hl) * hl * energy * beam_;
            rgb_[0] = rgb_[0] + ihl;
            rgb_[1] = rgb_[1] + ihl;
            rgb_[2] = rgb_[2] + ihl;
          }
        }
        return;
      }
      const int obj_id = intersected_object_id_;
      const Object& obj = objects_[obj_id];
      const R diffuse = obj.diffuse * energy;
      get_nvector(obj, dir);
      copy3(startp_, intersection_point_);
      utexture(obj, intersection_point_);
      pixel.surface_ids[nref] = obj_id * 4 + intsec_rectside_;
      copy3(pixel.points[nref], intersection_point_);
      if (obj.diffuse < R(0.5)) {
        pixel.calc_diffuse[nref] = false;
      } else {
        pixel.calc_diffuse[nref] = true;
        const R s = R(1.0) / R(256.0) * diffuse;
        for (int k = 0; k < 3; ++k) pixel.energy[nref][k] = texture_color_[k] * s;
        copy3(pixel.normals[nref], nvector_);
      }
      const R w = R(-2.0) * dot(dir, nvector_);
      accum(dir, w, nvector_);
      const R hilight_scale = energy * obj.hilight;
      const R bright = -dot(nvector_, light_) * diffuse;
      const R hilight = -dot(dir, light_);
      if (adds_light(bright, hilight) && !in_shadow()) add_light(bright, hilight, hilight_scale);
      setup_startp(intersection_point_);
      trace_reflections(diffuse, hilight_scale, dir);
      // original: below this energy the next slot's surface id is not reset
      // and keeps whatever an earlier row left there.
      if (!(R(0.1) < energy)) return;
      if (nref < kMaxDepth - 1) pixel.surface_ids[nref + 1] = -1;
      if (obj.reflection != kReflectMirror) return;
      energy = energy * (R(1.0) - obj.diffuse);
    }
  }

  // --- diffuse light ------------------------------------------------------

  MINRT_INLINE void trace_diffuse_ray(const DirVec& dv, R energy) {
    if (!judge_intersection_fast<true>(dv)) return;
    const Object& obj = objects_[intersected_object_id_];
    get_nvector(obj, dv.v);
    utexture(obj, intersection_point_);
    const R br = -dot(nvector_, light_);
    const R bright = br > R(0) ? br : R(0.0);
    const R scale = energy * bright * obj.diffuse;
    // Facing away from the light the scale is +-0, and adding +-0 * colour
    // changes nothing (diffuse_ray_ is a sum started at +0, so never -0)
    // unless the colour is not finite; only then does the shadow test matter.
    if (scale == R(0) && finite(texture_color_[0]) && finite(texture_color_[1]) &&
        finite(texture_color_[2]))
      return;
    if (in_shadow()) return;
    accum(diffuse_ray_, scale, texture_color_);
  }

  // Samples the 60 directions of one group that face along `normal`.
  void trace_diffuse_rays(const DirVec* group, const R* normal, const R* org) {
    setup_startp<true>(org);
    setup_forward_culling();
    // Entries 2n and 2n+1 point in opposite directions.
    for (int i = kDirvecsPerGroup - 2; i >= 0; i -= 2) {
      const R p = dot(group[i].v, normal);
      if (p < R(0))
        trace_diffuse_ray(group[i + 1], p / R(-150.0));
      else
        trace_diffuse_ray(group[i], p / R(150.0));
    }
  }

  void pretrace_diffuse_rays(Pixel& pixel) {
    for (int nref = 0; nref < kMaxDepth; ++nref) {
      if (pixel.surface_ids[nref] < 0) return;
      if (!pixel.calc_diffuse[nref]) continue;
      zero3(diffuse_ray_);
      trace_diffuse_rays(dirvecs_[pixel.group_id], pixel.normals[nref], pixel.points[nref]);
      copy3(pixel.received[nref], diffuse_ray_);
    }
  }

  // All 300 directions for one point: its own 60 plus the other 240.
  void diffuse_using_1point(Pixel& pixel, int nref) {
    copy3(diffuse_ray_, pixel.received[nref]);
    for (int g = 0; g < kDirvecGroups; ++g)
      if (pixel.group_id != g) trace_diffuse_rays(dirvecs_[g], pixel.normals[nref], pixel.points[nref]);
    accum_product(rgb_, pixel.energy[nref], diffuse_ray_);
  }

  void do_without_neighbors(Pixel& pixel, int nref) {
    for (; nref < kMaxDepth; ++nref) {
      if (pixel.surface_ids[nref] < 0) return;
      if (pixel.calc_diffuse[nref]) diffuse_using_1point(pixel, nref);
    }
  }

  // Uses the 60-ray results of the four neighbours while they hit the same
  // surface at the same depth; falls back to 300 rays from there on.
  void try_exploit_neighbors(int x, Pixel* prev, Pixel* cur, Pixel* next) {
    Pixel& pixel = cur[x];
    for (int nref = 0; nref < kMaxDepth; ++nref) {
      const int32_t sid = pixel.surface_ids[nref];
      if (sid < 0) return;
      if (prev[x].surface_ids[nref] != sid || next[x].surface_ids[nref] != sid ||
          cur[x - 1].surface_ids[nref] != sid || cur[x + 1].surface_ids[nref] != sid) {
        do_without_neighbors(pixel, nref);
        return;
      }
      if (pixel.calc_diffuse[nref]) {
        copy3(diffuse_ray_, prev[x].received[nref]);
        add3(diffuse_ray_, cur[x - 1].received[nref]);
        add3(diffuse_ray_, pixel.received[nref]);
        add3(diffuse_ray_, cur[x + 1].received[nref]);
        add3(diffuse_ray_, next[x].received[nref]);
        accum_product(rgb_, pixel.energy[nref], diffuse_ray_);
      }
    }
  }

  // --- rows ---------------------------------------------------------------

  void pretrace_line(Pixel* line, int y, int group_id) {
    const R ydisp = scan_pitch_ * M::from_int(y - center_[1]);
    const R lc0 = ydisp * screeny_[0] + screenz_[0];
    const R lc1 = ydisp * screeny_[1] + screenz_[1];
    const R lc2 = ydisp * screeny_[2] + screenz_[2];
    for (int x = width_ - 1; x >= 0; --x) {
      const R xdisp = scan_pitch_ * M::from_int(x - center_[0]);
      R dir[3] = {xdisp * screenx_[0] + lc0, xdisp * screenx_[1] + lc1, xdisp * screenx_[2] + lc2};
      normalize(dir, false);
      zero3(rgb_);
      copy3(startp_, viewpoint_);
      trace_ray(0, R(1.0), dir, line[x]);
      copy3(line[x].rgb, rgb_);
      line[x].group_id = group_id;
      pretrace_diffuse_rays(line[x]);
      group_id = add_mod5(group_id, 1);
    }
  }

  void scan_pixels(int y, Pixel* prev, Pixel* cur, Pixel* next) {
    uint8_t* rgb = row_;
    for (int x = 0; x < width_; ++x, rgb += 3) {
      copy3(rgb_, cur[x].rgb);
      if (y + 1 < height_ && y > 0 && x + 1 < width_ && x > 0)
        try_exploit_neighbors(x, prev, cur, next);
      else
        do_without_neighbors(cur[x], 0);
      rgb[0] = static_cast<uint8_t>(pixel_channel<M>(rgb_[0]));
      rgb[1] = static_cast<uint8_t>(pixel_channel<M>(rgb_[1]));
      rgb[2] = static_cast<uint8_t>(pixel_channel<M>(rgb_[2]));
    }
  }

  // --- diffuse direction tables -------------------------------------------

  static R adjust_position(R h, R ratio) {
    const R l = M::sqrt(h * h + R(0.1));
    const R tan_h = R(1.0) / l;
    const R theta_h = M::atan(tan_h);
    const R a = theta_h * ratio;
    const R tan_m = M::sin(a) / M::cos(a);
    return tan_m * l;
  }

  void calc_dirvec(R rx, R ry, int group_id, int index) {
    R x = R(0.0), y = R(0.0);
    for (int i = 0; i < 5; ++i) {
      x = adjust_position(y, rx);
      y = adjust_position(x, ry);
    }
    const R l = M::sqrt(sqr(x) + sqr(y) + R(1.0));
    const R vx = x / l, vy = y / l, vz = R(1.0) / l;
    DirVec* g = dirvecs_[group_id];
    set3(g[index].v, vx, vy, vz);
    set3(g[index + 40].v, vx, vz, -vy);
    set3(g[index + 80].v, vz, -vx, -vy);
    set3(g[index + 1].v, -vx, -vy, -vz);
    set3(g[index + 41].v, -vx, -vz, vy);
    set3(g[index + 81].v, -vz, vx, vy);
  }
  static void set3(R* v, R a, R b, R c) {
    v[0] = a;
    v[1] = b;
    v[2] = c;
  }

  // 600 directions: a 10x10 grid on each face of a cube, bent towards a
  // uniform spread on the sphere, dealt out to 5 groups of 120.
  void init_dirvecs() {
    int group_id = 0, index = 0;
    for (int row = 9; row >= 0; --row) {
      const R ry = M::from_int(row) * R(0.2) - R(0.9);
      int g = group_id;
      for (int col = 4; col >= 0; --col) {
        calc_dirvec(M::from_int(col) * R(0.2) - R(0.9), ry, g, index);
        calc_dirvec(M::from_int(col) * R(0.2) + R(0.1), ry, g, index + 2);
        g = add_mod5(g, 1);
      }
      group_id = add_mod5(group_id, 2);
      index += 4;
    }
    for (int g = kDirvecGroups - 1; g >= 0; --g)
      for (int i = kDirvecsPerGroup - 1; i >= 0; --i) setup_dirvec_constants(dirvecs_[g][i]);
  }

  // --- mirrors ------------------------------------------------------------

  void add_reflection(int surface_id, R bright, R v0, R v1, R v2) {
    Reflection& r = reflections_[n_reflections_++];
    r.surface_id = surface_id;
    r.bright = bright;
    set3(r.dvec.v, v0, v1, v2);
    setup_dirvec_constants(r.dvec);
  }

  // original: only the last object is examined (the function never recurses
  // to the others), so at most one mirror box or plane reflects the light.
  void setup_reflections(int obj_id) {
    if (obj_id < 0) return;
    const Object& obj = objects_[obj_id];
    if (obj.reflection != kReflectMirror || !(obj.diffuse < R(1.0))) return;
    const R br = R(1.0) - obj.diffuse;
    if (obj.form == kFormBox) {
      const int sid = obj_id * 4;
      const R n0 = -light_[0], n1 = -light_[1], n2 = -light_[2];
      add_reflection(sid + 1, br, light_[0], n1, n2);
      add_reflection(sid + 2, br, n0, light_[1], n2);
      add_reflection(sid + 3, br, n0, n1, light_[2]);
    } else if (obj.form == kFormPlane) {
      const R p = dot(light_, obj.abc);
      add_reflection(obj_id * 4 + 1, br, R(2.0) * obj.abc[0] * p - light_[0],
                     R(2.0) * obj.abc[1] * p - light_[1], R(2.0) * obj.abc[2] * p - light_[2]);
    }
  }

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

  DirVec dirvecs_[kDirvecGroups][kDirvecsPerGroup];
  DirVec light_dirvec_{};
  Reflection reflections_[kMaxReflections];
  int n_reflections_ = 0;
  Pixel* lines_[3] = {};
  uint8_t* row_ = nullptr;  // the finished row, 3 bytes a pixel

  R solver_dist_ = 0;
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

  bool toward_light_flip_[3] = {};
};

}  // namespace minrt
