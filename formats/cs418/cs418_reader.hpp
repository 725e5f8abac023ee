// Reader for the UIUC CS418 ray tracer's scene files (SPEC.md 1): one
// keyword per line, fields separated by spaces or tabs. Mode keywords are
// global and may come anywhere (the course's own tests put aa, dof and the
// lenses after the geometry), except up and forward, which are applied in
// file order to the current camera basis. State keywords (colour, texture,
// shininess, ...) are captured by later geometry. The assignment requires
// no error checking, so the reader is as lenient as the course: unknown
// keywords, '#' comment lines and fields after the ones a keyword takes are
// skipped with a warning, and so is odd but usable input (up parallel to
// forward, a light that gives no light, a negative radius). What cannot be
// read (too few fields, a field that is not a number, an undefined vertex,
// a missing texture) stops with a located error.
//
// Streaming from a ByteSource, no heap: geometry goes through SceneBuilder
// into the arena. Textures are resolved by the platform (TextureResolver):
// the host decodes PNG files, the board looks up what host-send sent.
#pragma once

#include <stdint.h>

#include <minrt/limits.hpp>

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/base/number_parse.hpp"
#include "core/base/text_lines.hpp"
#include "core/math/math_policy.hpp"
#include "core/math/vec3.hpp"
#include "formats/cs418/cs418_limits.hpp"
#include "formats/model/scene_builder.hpp"

namespace minrt::cs418 {

// Turns a texture file name into a texture index of the scene; on failure
// fills `error` (its message only; the reader adds the position) and
// returns -1.
struct TextureResolver {
  int32_t (*resolve)(void* ctx, const char* name, Diagnostic& error) = nullptr;
  void* ctx = nullptr;
};

struct Header {
  int width = 0;
  int height = 0;
  char output_name[kMaxFileName + 1] = {};
};

enum class ReadStatus { kOk, kSceneError, kOutOfMemory };

// M is the math policy (the camera basis is normalised as it is read, in
// the precision the tracer will use).
template <class M>
class Reader {
  using R = typename M::real;

 public:
  Reader(ByteSource in, model::SceneBuilder<R>& builder, TextureResolver textures, WarningSink warnings)
      : in_(in), builder_(builder), textures_(textures), warnings_(warnings) {}

  // Reads the whole file; on success fills the header and the scene's
  // settings and camera (the arrays come from builder.finish()).
  ReadStatus read(Header& header, model::Scene<R>& scene, Diagnostic& error) {
    scene_ = &scene;
    header_ = &header;
    error_ = &error;
    bool seen_png = false;
    while (next_line()) {
      if (count_ == 0) continue;  // blank
      if (buf_[words_[0].start] == '#') {
        warn_at(0).text("comment line ignored");
        continue;
      }
      if (!seen_png) {
        if (!word_is(0, "png")) return fail_at(0, "the first line must be 'png WIDTH HEIGHT FILE.png'");
        if (!read_png()) return ReadStatus::kSceneError;
        seen_png = true;
        continue;
      }
      const ReadStatus st = dispatch();
      if (st != ReadStatus::kOk) return st;
    }
    if (status_ != ReadStatus::kOk) return status_;
    if (!seen_png) {
      error.has_pos = false;
      error.text("empty scene: no 'png WIDTH HEIGHT FILE.png' line");
      return ReadStatus::kSceneError;
    }
    return ReadStatus::kOk;
  }

 private:
  using Word = text::Word;
  static constexpr int kMaxWords = 16;
  static constexpr int64_t kIntMax = 2147483647;  // counts are int32 in the scene

  // ---------------------------------------------------------------- lines
  bool next_line() {
    if (status_ != ReadStatus::kOk || at_end_) return false;
    count_ = 0;
    ++line_;
    switch (text::read_line(in_, buf_, kMaxLineBytes, length_, at_end_)) {
      case text::LineRead::kEnd:
        return false;
      case text::LineRead::kNulByte:
        line_error(length_ + 1).text("NUL byte in the scene (not a text file?)");
        return false;
      case text::LineRead::kTooLong:
        line_error(kMaxLineBytes + 1).text("line longer than ").number(kMaxLineBytes).text(" bytes");
        return false;
      case text::LineRead::kLine:
        break;
    }
    int unstored = 0;
    total_ = text::split_words(buf_, length_, words_, kMaxWords, unstored);
    // Words past kMaxWords are never a keyword's fields: they are extra
    // fields, warned about with the others.
    count_ = total_ < kMaxWords ? total_ : kMaxWords;
    return true;
  }
  // A scene error at column `col` of this line, for the message to follow.
  Diagnostic& line_error(int col) {
    error_->pos = SourcePos{line_, col};
    error_->has_pos = true;
    status_ = ReadStatus::kSceneError;
    return *error_;
  }

  bool word_is(int i, const char* kw) const { return text::word_is(buf_, words_[i], kw); }

  // A warning at word `word` of this line, for the message to follow;
  // emitted when the returned builder goes out of scope.
  class Warning {
   public:
    Warning(const WarningSink& sink, SourcePos pos) : sink_(sink) {
      d_.pos = pos;
      d_.has_pos = true;
    }
    Warning(const Warning&) = delete;
    Warning& operator=(const Warning&) = delete;
    ~Warning() { sink_.emit(d_); }
    Warning& text(const char* s) {
      d_.text(s);
      return *this;
    }
    Warning& number(int64_t v) {
      d_.number(v);
      return *this;
    }
    Warning& quoted(const char* s, int n) {
      d_.quoted(s, n);
      return *this;
    }

   private:
    const WarningSink& sink_;
    Diagnostic d_;
  };
  Warning warn_at(int word) { return Warning(warnings_, SourcePos{line_, words_[word].start + 1}); }
  // Fields after the `used` ones a keyword takes (the keyword is word 0):
  // ignored, as the course ignores them, with a warning.
  void ignore_extra(int used) {
    const int extra = total_ - 1 - used;
    if (extra <= 0) return;
    if (buf_[words_[used + 1].start] == '#') {
      warn_at(used + 1).text("comment ignored");
    } else {
      warn_at(used + 1).number(extra).text(extra == 1 ? " extra field ignored" : " extra fields ignored");
    }
  }

  ReadStatus fail_at(int word, const char* msg) {
    error_->pos = SourcePos{line_, word < count_ ? words_[word].start + 1 : length_ + 1};
    error_->has_pos = true;
    error_->text(msg);
    return ReadStatus::kSceneError;
  }
  // "KEYWORD needs N numbers" style message for a wrong field count.
  ReadStatus fail_count(const char* usage) {
    const Word& kw = words_[0];
    const int at = count_ > 1 ? count_ - 1 : 0;
    error_->pos = SourcePos{line_, count_ > 1 ? words_[at].start + 1 : kw.start + 1};
    error_->has_pos = true;
    error_->text("expected '").text(usage).text("', got ").number(count_ - 1).text(count_ == 2 ? " field" : " fields");
    return ReadStatus::kSceneError;
  }

  bool real_at(int i, R& out) {
    const Word& w = words_[i];
    const NumberStatus st = parse_real<R>(buf_ + w.start, w.length, out);
    if (st == NumberStatus::kOk) return true;
    error_->pos = SourcePos{line_, w.start + 1};
    error_->has_pos = true;
    error_->text(st == NumberStatus::kNonFinite ? "number out of range: " : "not a number: ")
        .quoted(buf_ + w.start, w.length);
    return false;
  }
  bool int_at(int i, int64_t lo, int64_t hi, int64_t& out, const char* what) {
    const Word& w = words_[i];
    const NumberStatus st = parse_int(buf_ + w.start, w.length, out);
    if (st == NumberStatus::kOk && out >= lo && out <= hi) return true;
    error_->pos = SourcePos{line_, w.start + 1};
    error_->has_pos = true;
    if (st != NumberStatus::kOk) {
      error_->text(what).text(" must be an integer, got ").quoted(buf_ + w.start, w.length);
    } else if (hi == kIntMax && out > hi) {
      error_->text(what).text(" must be at most ").number(hi).text(", got ").number(out);
    } else if (hi == kIntMax) {
      error_->text(what).text(" must be at least ").number(lo).text(", got ").number(out);
    } else {
      error_->text(what).text(" must be in ").number(lo).text("..").number(hi).text(", got ").number(out);
    }
    return false;
  }
  bool vec_at(int i, Vec3<R>& v) { return real_at(i, v.x) && real_at(i + 1, v.y) && real_at(i + 2, v.z); }
  bool name_at(int i, char* out) {
    const Word& w = words_[i];
    if (w.length > kMaxFileName) {
      error_->pos = SourcePos{line_, w.start + 1};
      error_->has_pos = true;
      error_->text("file name longer than ").number(kMaxFileName).text(" bytes");
      return false;
    }
    for (int k = 0; k < w.length; ++k) out[k] = buf_[w.start + k];
    out[w.length] = 0;
    return true;
  }

  // ------------------------------------------------------------ keywords
  bool read_png() {
    if (count_ < 4) {
      fail_count("png WIDTH HEIGHT FILE.png");
      return false;
    }
    ignore_extra(3);
    int64_t w = 0, h = 0;
    if (!int_at(1, 1, limits::kMaxImageWidth, w, "image width")) return false;
    if (!int_at(2, 1, limits::kMaxImageHeight, h, "image height")) return false;
    if (!name_at(3, header_->output_name)) return false;
    header_->width = scene_->width = static_cast<int>(w);
    header_->height = scene_->height = static_cast<int>(h);
    return true;
  }

  ReadStatus dispatch() {
    model::Camera<R>& cam = scene_->camera;
    const int n = count_ - 1;  // fields after the keyword
    // At least `k` fields; more are ignored with a warning.
    auto need = [&](int k, const char* usage) -> bool {
      if (n < k) {
        fail_count(usage);
        return false;
      }
      ignore_extra(k);
      return true;
    };
    auto scene_error = [&](bool ok) { return ok ? ReadStatus::kOk : ReadStatus::kSceneError; };
    auto memory = [&](bool ok) {
      if (ok) return ReadStatus::kOk;
      error_->has_pos = true;
      error_->pos = SourcePos{line_, 1};
      error_->text("scene does not fit in memory");
      return ReadStatus::kOutOfMemory;
    };

    if (word_is(0, "png")) return fail_at(0, "a second 'png' line");
    if (word_is(0, "color")) {
      if (!need(3, "color R G B") || !vec_at(1, state_.color)) return ReadStatus::kSceneError;
      state_changed_ = true;
      return ReadStatus::kOk;
    }
    if (word_is(0, "sphere")) {
      Vec3<R> c;
      R r;
      if (!need(4, "sphere X Y Z R") || !vec_at(1, c) || !real_at(4, r)) return ReadStatus::kSceneError;
      if (r < R(0)) {
        // The course's intersection sees only r^2: the same sphere.
        warn_at(4).text("negative radius ").quoted(buf_ + words_[4].start, words_[4].length)
            .text(": the sphere is drawn with its absolute value");
        r = -r;
      }
      if (!flush_material()) return memory(false);
      return memory(builder_.add_sphere(c, r));
    }
    if (word_is(0, "sun") || word_is(0, "bulb")) {
      model::Light<R> light{};
      light.kind = word_is(0, "sun") ? model::LightKind::kSun : model::LightKind::kBulb;
      if (!need(3, light.kind == model::LightKind::kSun ? "sun X Y Z" : "bulb X Y Z") || !vec_at(1, light.vector))
        return ReadStatus::kSceneError;
      light.color = state_.color;
      const Vec3<R> z{};
      if (light.kind == model::LightKind::kSun && light.vector.x == z.x && light.vector.y == z.y &&
          light.vector.z == z.z) {
        warn_at(1).text("sun direction is zero: the sun is left out (it would light nothing)");
        return ReadStatus::kOk;
      }
      // Only its direction counts: one whose square under- or overflows
      // keeps it (normalised at set-up, it would be NaN or zero).
      if (light.kind == model::LightKind::kSun) light.vector = squarable_direction(light.vector);
      if (light.color.x == z.x && light.color.y == z.y && light.color.z == z.z) {
        warn_at(0).text("light colour is zero: the light is left out (it would add nothing)");
        return ReadStatus::kOk;
      }
      return memory(builder_.add_light(light));
    }
    if (word_is(0, "plane")) {
      Vec3<R> abc;
      R d;
      if (!need(4, "plane A B C D") || !vec_at(1, abc) || !real_at(4, d)) return ReadStatus::kSceneError;
      if (abc.x == R(0) && abc.y == R(0) && abc.z == R(0)) return fail_at(1, "plane normal (A, B, C) is zero");
      if (!flush_material()) return memory(false);
      return memory(builder_.add_plane(abc, d));
    }
    if (word_is(0, "xyz")) {
      Vec3<R> p;
      if (!need(3, "xyz X Y Z") || !vec_at(1, p)) return ReadStatus::kSceneError;
      return memory(builder_.add_vertex(p, texcoord_u_, texcoord_v_));
    }
    // tri, and the course's older names: trif (flat: the current colour,
    // never the texture) and trit (textured, as tri is).
    if (word_is(0, "tri") || word_is(0, "trif") || word_is(0, "trit")) {
      const bool flat = word_is(0, "trif");
      if (!need(3, flat ? "trif I1 I2 I3" : word_is(0, "trit") ? "trit I1 I2 I3" : "tri I1 I2 I3"))
        return ReadStatus::kSceneError;
      uint32_t idx[3];
      const int64_t nv = builder_.vertex_count();
      for (int k = 0; k < 3; ++k) {
        int64_t i = 0;
        const Word& w = words_[1 + k];
        if (parse_int(buf_ + w.start, w.length, i) != NumberStatus::kOk)
          return fail_at(1 + k, "vertex index must be an integer");
        if (i == 0 || i > nv || i < -nv) {
          error_->pos = SourcePos{line_, w.start + 1};
          error_->has_pos = true;
          error_->text("vertex ").number(i).text(" is not defined (").number(nv).text(
              nv == 1 ? " vertex so far)" : " vertices so far)");
          return ReadStatus::kSceneError;
        }
        idx[k] = static_cast<uint32_t>(i > 0 ? i - 1 : nv + i);
      }
      if (flat && state_.texture != model::kNoTexture) {
        // The state without its texture for this triangle; the next object
        // takes the state as it is again.
        const int32_t texture = state_.texture;
        state_.texture = model::kNoTexture;
        state_changed_ = true;
        const bool added = flush_material();
        state_.texture = texture;
        state_changed_ = true;
        if (!added) return memory(false);
      } else if (!flush_material()) {
        return memory(false);
      }
      return memory(builder_.add_triangle(idx[0], idx[1], idx[2]));
    }
    if (word_is(0, "texcoord")) {
      if (!need(2, "texcoord U V") || !real_at(1, texcoord_u_) || !real_at(2, texcoord_v_))
        return ReadStatus::kSceneError;
      return ReadStatus::kOk;
    }
    if (word_is(0, "texture")) {
      if (!need(1, "texture FILE.png|none")) return ReadStatus::kSceneError;
      state_changed_ = true;
      if (word_is(1, "none")) {
        state_.texture = model::kNoTexture;
        return ReadStatus::kOk;
      }
      char name[kMaxFileName + 1];
      if (!name_at(1, name)) return ReadStatus::kSceneError;
      if (textures_.resolve == nullptr) return fail_at(1, "textures are not available here");
      Diagnostic why;
      const int32_t id = textures_.resolve(textures_.ctx, name, why);
      if (id < 0) {
        error_->pos = SourcePos{line_, words_[1].start + 1};
        error_->has_pos = true;
        error_->text(why.message);
        return ReadStatus::kSceneError;
      }
      state_.texture = id;
      return ReadStatus::kOk;
    }
    if (word_is(0, "shininess") || word_is(0, "transparency")) {
      const bool shiny = word_is(0, "shininess");
      Vec3<R>& v = shiny ? state_.shininess : state_.transparency;
      if (n == 0) {
        fail_count(shiny ? "shininess S | shininess R G B" : "transparency T | transparency R G B");
        return ReadStatus::kSceneError;
      }
      if (n < 3) {  // one value for all three channels; a second is extra
        R s;
        if (!real_at(1, s)) return ReadStatus::kSceneError;
        ignore_extra(1);
        v = Vec3<R>{s, s, s};
      } else {
        if (!vec_at(1, v)) return ReadStatus::kSceneError;
        ignore_extra(3);
      }
      state_changed_ = true;
      return ReadStatus::kOk;
    }
    if (word_is(0, "ior") || word_is(0, "roughness")) {
      const bool ior = word_is(0, "ior");
      if (!need(1, ior ? "ior ETA" : "roughness SIGMA")) return ReadStatus::kSceneError;
      R v;
      if (!real_at(1, v)) return ReadStatus::kSceneError;
      if (ior && v <= R(0)) return fail_at(1, "ior must be positive");
      if (!ior && v < R(0)) return fail_at(1, "roughness must not be negative");
      (ior ? state_.ior : state_.roughness) = v;
      state_changed_ = true;
      return ReadStatus::kOk;
    }
    if (word_is(0, "eye")) return scene_error(need(3, "eye X Y Z") && vec_at(1, cam.eye));
    if (word_is(0, "forward") || word_is(0, "up")) {
      const bool fwd = word_is(0, "forward");
      Vec3<R> v;
      if (!need(3, fwd ? "forward X Y Z" : "up X Y Z") || !vec_at(1, v)) return ReadStatus::kSceneError;
      if (v.x == R(0) && v.y == R(0) && v.z == R(0)) return fail_at(1, "zero vector");
      // Applied in file order to the current basis (SPEC.md 1.3: deriving
      // it once from the final vectors gives a different image).
      if (fwd) cam.forward = v;
      const Vec3<R> right = fwd ? cross(v, cam.up) : cross(cam.forward, v);
      if (right.x == R(0) && right.y == R(0) && right.z == R(0)) {
        // No right vector from two parallel ones (the course's formula gives
        // NaN): keep the previous right, made perpendicular to forward.
        warn_at(1).text(fwd ? "forward is parallel to up: the camera keeps its right vector"
                            : "up is parallel to forward: the camera keeps its right vector");
        // (squarable_direction: a forward, right or up whose square under-
        // or overflows keeps its direction, not NaN.)
        const Vec3<R> f = squarable_direction(cam.forward);
        cam.right = normalize<M>(cam.right - f * (dot(f, cam.right) / dot(f, f)));
      } else {
        cam.right = normalize<M>(squarable_direction(right));
      }
      cam.up = normalize<M>(squarable_direction(cross(cam.right, cam.forward)));
      return ReadStatus::kOk;
    }
    if (word_is(0, "expose")) {
      if (!need(1, "expose V") || !real_at(1, scene_->exposure_value)) return ReadStatus::kSceneError;
      scene_->exposure = true;
      return ReadStatus::kOk;
    }
    if (word_is(0, "dof")) {
      if (!need(2, "dof FOCUS LENS") || !real_at(1, cam.focus) || !real_at(2, cam.lens))
        return ReadStatus::kSceneError;
      cam.depth_of_field = true;
      return ReadStatus::kOk;
    }
    if (word_is(0, "aa") || word_is(0, "bounces") || word_is(0, "gi")) {
      int64_t v = 0;
      // Any count is taken: the weight cut-off (render.hpp) bounds the work.
      // Only the recursion depth has a bound, the stack's: deeper rays are
      // not traced, with a warning.
      if (word_is(0, "aa")) {
        if (!need(1, "aa N") || !int_at(1, 1, kIntMax, v, "aa samples")) return ReadStatus::kSceneError;
        scene_->samples = static_cast<int32_t>(v);
      } else {
        const bool gi = word_is(0, "gi");
        const int cap = gi ? kMaxGiDepth : kMaxBounces;
        if (!need(1, gi ? "gi D" : "bounces D") || !int_at(1, 0, kIntMax, v, gi ? "gi depth" : "bounces"))
          return ReadStatus::kSceneError;
        if (v > cap) {
          warn_at(1).text(gi ? "gi depth " : "bounces ").number(v).text(" is deeper than the stack holds: ")
              .number(cap).text(" used");
          v = cap;
        }
        (gi ? scene_->gi_depth : scene_->bounces) = static_cast<int32_t>(v);
      }
      return ReadStatus::kOk;
    }
    if (word_is(0, "fisheye") || word_is(0, "panorama")) {
      const bool fish = word_is(0, "fisheye");
      if (!need(0, fish ? "fisheye" : "panorama")) return ReadStatus::kSceneError;
      cam.projection = fish ? model::Projection::kFisheye : model::Projection::kPanorama;
      return ReadStatus::kOk;
    }
    // Unknown keyword: the assignment says to ignore it. Say so once per line.
    Diagnostic w;
    w.pos = SourcePos{line_, words_[0].start + 1};
    w.has_pos = true;
    w.text("unknown keyword ").quoted(buf_ + words_[0].start, words_[0].length).text(" skipped");
    warnings_.emit(w);
    return ReadStatus::kOk;
  }

  // Materials are logged only when the state changed since the last object.
  bool flush_material() {
    if (!state_changed_) return true;
    state_changed_ = false;
    return builder_.add_material(state_);
  }

  ByteSource in_;
  model::SceneBuilder<R>& builder_;
  TextureResolver textures_;
  WarningSink warnings_;
  model::Scene<R>* scene_ = nullptr;
  Header* header_ = nullptr;
  Diagnostic* error_ = nullptr;
  ReadStatus status_ = ReadStatus::kOk;

  char buf_[kMaxLineBytes];
  int length_ = 0;
  Word words_[kMaxWords];
  int count_ = 0;  // words stored (at most kMaxWords)
  int total_ = 0;  // words on the line
  int line_ = 0;
  bool at_end_ = false;

  model::Material<R> state_{};
  bool state_changed_ = false;
  R texcoord_u_ = R(0), texcoord_v_ = R(0);
};

}  // namespace minrt::cs418
