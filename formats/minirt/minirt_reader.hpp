// Reader for the 42-school miniRT scene files (`.rt`, SPEC.md 2): one element
// per line, fields separated by spaces or tabs, triples written `x,y,z`.
// Mandatory elements A, C, L, sp, pl, cy with every range check of the
// subject; the bonus elements of the shared scenes: several coloured L, co
// (cone), plc (checkered plane), spt (textured sphere, optional bump map).
//
// Every check stops at the first error, in file order, with a message that
// names the element, the field and the text found (`sphere diameter "3abc"
// is not a number`) and the line; the missing-element checks come after the
// last line. Range checks are made on the decimal text itself, exactly, so
// the double host build and the float board accept the same files.
// Orientation vectors are range-checked per component, then normalised
// (the shared scenes use non-unit ones); a cylinder's point is its centre,
// as the subject says (ReaderOptions::cylinder_point can make it the base).
// ReaderOptions::mandatory keeps to the subject's mandatory part: the bonus
// elements are refused, at most one L, its colour optional and unused.
//
// Streaming from a ByteSource, no heap: objects go through SceneBuilder into
// the arena; texture names go to the platform's TextureResolver.
#pragma once

#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/base/number_parse.hpp"
#include "core/base/text_lines.hpp"
#include "core/math/vec3.hpp"
#include "formats/minirt/minirt_limits.hpp"
#include "formats/model/scene_builder.hpp"

namespace minrt::minirt {

// Turns a texture file name into a texture index of the scene; on failure
// fills `error` with the reason (the reader adds element and line) and
// returns -1.
struct TextureResolver {
  int32_t (*resolve)(void* ctx, const char* name, Diagnostic& error) = nullptr;
  void* ctx = nullptr;
};

// The camera as the file gives it; placed for an image size by
// minirt_camera.hpp once the size is known.
template <class R>
struct View {
  Vec3<R> position{};
  Vec3<R> direction{R(0), R(0), R(-1)};  // normalised
  R fov_degrees = R(70);                 // horizontal
};

enum class ReadStatus { kOk, kSceneError, kOutOfMemory };

// Where a cylinder's point lies on its axis. The subject: "the center of
// the cylinder" (the height extends h/2 either way); the shared scenes were
// written for the centre of the base.
enum class CylinderPoint : uint8_t { kCentre, kBase };

struct ReaderOptions {
  // The subject's mandatory part only (docs/minirt.md, "--mandatory"): A, C,
  // L, sp, pl, cy; A, C and L at most once; L's colour optional and unused
  // (white light); no specular term. A, L and objects may be missing.
  bool mandatory = false;
  CylinderPoint cylinder_point = CylinderPoint::kCentre;
};

// The constants of the bonus shading, defined once (SPEC.md 2.1).
inline constexpr int kMaxConeAngle = 90;  // degrees, exclusive

template <class M>
class Reader {
  using R = typename M::real;

 public:
  Reader(ByteSource in, model::SceneBuilder<R>& builder, TextureResolver textures, ReaderOptions options = {})
      : in_(in), builder_(builder), textures_(textures), options_(options) {}

  // Reads the whole file. On success the scene's ambient and finish are set
  // and `view` holds the camera; the arrays come from builder.finish().
  ReadStatus read(model::Scene<R>& scene, View<R>& view, Diagnostic& error) {
    scene_ = &scene;
    view_ = &view;
    error_ = &error;
    scene.finish = model::Finish::kMinirt;
    scene.specular = !options_.mandatory;
    bool any_element = false;
    while (next_line()) {
      if (count_ == 0) continue;  // blank or white space only
      any_element = true;
      if (!element()) return status_ == ReadStatus::kOk ? ReadStatus::kSceneError : status_;
    }
    if (status_ != ReadStatus::kOk) return status_;
    error.has_pos = false;
    if (!any_element)
      return fail_whole(options_.mandatory ? "the scene is empty: it needs at least a camera 'C X,Y,Z NX,NY,NZ FOV'"
                                           : "the scene is empty: it needs A, C, L and at least one object");
    if (options_.mandatory) {
      // The subject bounds A, C and L (at most once) but asks for none of
      // them, nor for an object; only the camera is needed to make an image.
      if (camera_line_ == 0) return fail_whole("no camera: the scene needs one 'C X,Y,Z NX,NY,NZ FOV' line");
      return ReadStatus::kOk;
    }
    if (ambient_line_ == 0) return fail_whole("no ambient light: the scene needs one 'A RATIO R,G,B' line");
    if (camera_line_ == 0) return fail_whole("no camera: the scene needs one 'C X,Y,Z NX,NY,NZ FOV' line");
    if (builder_.light_count() == 0)
      return fail_whole("no light: the scene needs at least one 'L X,Y,Z BRIGHTNESS R,G,B' line");
    if (builder_.object_count() == 0) return fail_whole("no object: the scene needs at least one sp, pl, cy, co, plc or spt");
    return ReadStatus::kOk;
  }

 private:
  using Word = text::Word;
  // An exact view of a decimal token: sign, integer part (saturated) and
  // whether any fractional digit is non-zero. Enough to compare against the
  // integer bounds of the subject without rounding.
  struct Decimal {
    bool negative = false;
    uint32_t whole = 0;
    bool fraction = false;
    bool is_zero() const { return whole == 0 && !fraction; }
    // lo <= value <= hi for integer bounds.
    bool within(int32_t lo, int32_t hi) const {
      if (is_zero()) return lo <= 0 && hi >= 0;
      if (negative) {  // value = -(whole + f)
        if (lo >= 0) return false;
        const uint32_t mag = static_cast<uint32_t>(-lo);
        return whole < mag || (whole == mag && !fraction);
      }
      if (hi < 0) return false;
      const uint32_t top = static_cast<uint32_t>(hi);
      const bool le_hi = whole < top || (whole == top && !fraction);
      const bool ge_lo = lo <= 0 || whole > static_cast<uint32_t>(lo) ||
                         (whole == static_cast<uint32_t>(lo));
      return le_hi && ge_lo;
    }
    bool positive() const { return !negative && !is_zero(); }
  };
  struct Element {
    const char* id;
    const char* name;
    int fields;    // required
    int optional;  // may follow
    const char* usage;
    bool bonus;    // refused by ReaderOptions::mandatory
  };
  static constexpr int kMaxNumberBytes = 64;  // longer tokens are refused as numbers

  // ---------------------------------------------------------------- lines
  bool next_line() {
    if (status_ != ReadStatus::kOk || at_end_) return false;
    count_ = 0;
    too_many_ = 0;
    ++line_;
    switch (text::read_line(in_, buf_, kMaxLineBytes, length_, at_end_)) {
      case text::LineRead::kEnd:
        return false;
      case text::LineRead::kNulByte:
        at_column(length_ + 1).text("the scene contains a NUL byte (is it a text file?)");
        return false;
      case text::LineRead::kTooLong:
        at_column(1).text("line longer than ").number(kMaxLineBytes).text(" bytes");
        return false;
      case text::LineRead::kLine:
        break;
    }
    // One word more than any element takes is kept, so that the message
    // can show it; the rest are only counted.
    int unstored = 0;
    const int total = text::split_words(buf_, length_, words_, kMaxFields + 1, unstored);
    count_ = total < kMaxFields + 1 ? total : kMaxFields + 1;
    too_many_ = total - count_;
    return true;
  }

  bool word_is(int i, const char* s) const { return text::word_is(buf_, words_[i], s); }

  // ------------------------------------------------------------ messages
  Diagnostic& at(int word) { return at_column(word < count_ ? words_[word].start + 1 : length_ + 1); }
  Diagnostic& at_column(int col) {
    error_->pos = SourcePos{line_, col};
    error_->has_pos = true;
    status_ = ReadStatus::kSceneError;
    return *error_;
  }
  // "TEXT" with control and non-ASCII bytes escaped, long tokens shortened.
  void quote(const char* s, int n) {
    static constexpr char kHex[] = "0123456789abcdef";
    constexpr int kShown = 40;
    error_->text("\"");
    for (int i = 0; i < n && i < kShown; ++i) {
      const auto c = static_cast<unsigned char>(s[i]);
      if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\') {
        const char one[2] = {static_cast<char>(c), 0};
        error_->text(one);
      } else {
        const char esc[5] = {'\\', 'x', kHex[c >> 4], kHex[c & 15], 0};
        error_->text(esc);
      }
    }
    if (n > kShown) error_->text("...");
    error_->text("\"");
  }
  void quote_word(int i) { quote(buf_ + words_[i].start, words_[i].length); }
  // "sphere diameter "3abc"": the start of most messages.
  Diagnostic& field(int i, const char* what) {
    at(i).text(element_->name).text(" ").text(what).text(" ");
    quote_word(i);
    return *error_;
  }
  ReadStatus fail_whole(const char* msg) {
    error_->has_pos = false;
    error_->text(msg);
    return ReadStatus::kSceneError;
  }
  bool memory(bool ok) {
    if (!ok) {
      at(0).text("the scene does not fit in memory");
      status_ = ReadStatus::kOutOfMemory;
    }
    return ok;
  }

  // -------------------------------------------------------------- numbers
  // [+-]digits[.digits], nothing else: no exponent, no hex, no inf or nan,
  // no trailing characters. Fills `dec` exactly and `out` correctly rounded.
  static bool decimal(const char* s, int n, Decimal& dec) {
    int i = 0;
    dec = Decimal{};
    if (n > kMaxNumberBytes) return false;
    if (i < n && (s[i] == '+' || s[i] == '-')) dec.negative = s[i++] == '-';
    const int digits_start = i;
    while (i < n && s[i] >= '0' && s[i] <= '9') {
      const uint32_t d = static_cast<uint32_t>(s[i] - '0');
      dec.whole = dec.whole > 100000000u ? 1000000000u : dec.whole * 10u + d;  // saturates above any bound
      ++i;
    }
    if (i == digits_start) return false;
    if (i < n && s[i] == '.') {
      ++i;
      const int frac_start = i;
      while (i < n && s[i] >= '0' && s[i] <= '9') {
        if (s[i] != '0') dec.fraction = true;
        ++i;
      }
      if (i == frac_start) return false;
    }
    return i == n;
  }
  // Whether a token that is no plain decimal is one with an exponent
  // ("1e308", "2.5E-3"): the subject's numbers have none.
  static bool has_exponent(const char* s, int n) {
    int i = (n > 0 && (s[0] == '-' || s[0] == '+')) ? 1 : 0;
    bool digits = false;
    for (; i < n && ((s[i] >= '0' && s[i] <= '9') || s[i] == '.'); ++i)
      if (s[i] != '.') digits = true;
    if (!digits || i >= n || (s[i] != 'e' && s[i] != 'E')) return false;
    ++i;
    if (i < n && (s[i] == '-' || s[i] == '+')) ++i;
    if (i >= n) return false;
    while (i < n && s[i] >= '0' && s[i] <= '9') ++i;
    return i == n;
  }

  // A real number token (or part of a triple) for `what`; the message
  // quotes `whole` (the field) and, for a triple's part, the part too.
  bool real(const char* s, int n, R& out, Decimal& dec, int word, const char* what, const char* part) {
    if (!decimal(s, n, dec)) {
      field(word, what);
      if (part != nullptr) {
        error_->text(": ").text(part).text(" ");
        quote(s, n);
      }
      error_->text(n > kMaxNumberBytes ? " is too long for a number"
                   : has_exponent(s, n)   ? " has an exponent: write it as a plain decimal (like 0.5)"
                                          : " is not a number");
      return false;
    }
    if (parse_real<R>(s, n, out) != NumberStatus::kOk) {
      field(word, what).text(" is too large");
      return false;
    }
    return true;
  }
  // A scalar field: number, then [lo, hi] when `ranged`, or above 0 when
  // `positive`.
  bool scalar(int word, const char* what, R& out, Decimal& dec) {
    const Word& w = words_[word];
    return real(buf_ + w.start, w.length, out, dec, word, what, nullptr);
  }
  bool scalar_in(int word, const char* what, int32_t lo, int32_t hi, R& out) {
    Decimal dec;
    if (!scalar(word, what, out, dec)) return false;
    if (dec.within(lo, hi)) return true;
    field(word, what).text(" is outside [").number(lo).text(",").number(hi).text("]");
    return false;
  }
  bool scalar_positive(int word, const char* what, R& out) {
    Decimal dec;
    if (!scalar(word, what, out, dec)) return false;
    if (dec.positive()) return true;
    field(word, what).text(" must be greater than 0");
    return false;
  }
  // Splits a triple field at its commas; false (with the message) unless
  // there are exactly three parts.
  bool split3(int word, const char* what, Word parts[3]) {
    const Word& w = words_[word];
    int n = 0, start = w.start;
    for (int i = w.start; i <= w.start + w.length; ++i) {
      if (i == w.start + w.length || buf_[i] == ',') {
        if (n < 3) parts[n] = Word{start, i - start};
        ++n;
        start = i + 1;
      }
    }
    if (n == 3) return true;
    field(word, what).text(" needs 3 comma-separated values, got ").number(n);
    return false;
  }
  static constexpr const char* kAxisNames[3] = {"x", "y", "z"};
  static constexpr const char* kColourNames[3] = {"red", "green", "blue"};

  // x,y,z; with `unit_box`, every component in [-1, 1]; with `nonzero`, not
  // all zero.
  bool triple(int word, const char* what, Vec3<R>& v, bool unit_box, bool nonzero) {
    Word parts[3];
    if (!split3(word, what, parts)) return false;
    R c[3];
    Decimal d[3];
    for (int k = 0; k < 3; ++k)
      if (!real(buf_ + parts[k].start, parts[k].length, c[k], d[k], word, what, kAxisNames[k])) return false;
    if (unit_box) {
      for (int k = 0; k < 3; ++k) {
        if (d[k].within(-1, 1)) continue;
        field(word, what).text(": ").text(kAxisNames[k]).text(" ");
        quote(buf_ + parts[k].start, parts[k].length);
        error_->text(" is outside [-1,1]");
        return false;
      }
    }
    if (nonzero && d[0].is_zero() && d[1].is_zero() && d[2].is_zero()) {
      field(word, what).text(" is the zero vector: it has no direction");
      return false;
    }
    v = Vec3<R>{c[0], c[1], c[2]};
    return true;
  }
  // R,G,B integers in [0, 255], returned divided by 255.
  bool colour(int word, Vec3<R>& out) {
    const char* what = "colour";
    Word parts[3];
    if (!split3(word, what, parts)) return false;
    int32_t c[3];
    for (int k = 0; k < 3; ++k) {
      const char* s = buf_ + parts[k].start;
      const int n = parts[k].length;
      int i = 0;
      bool negative = false;
      if (i < n && (s[i] == '+' || s[i] == '-')) negative = s[i++] == '-';
      int32_t v = 0;
      const int first = i;
      while (i < n && s[i] >= '0' && s[i] <= '9') {
        v = v > 100000 ? 1000000 : v * 10 + (s[i] - '0');
        ++i;
      }
      if (i == first || i != n) {
        field(word, what).text(": ").text(kColourNames[k]).text(" ");
        quote(s, n);
        error_->text(" is not an integer");
        return false;
      }
      if (negative) v = -v;
      if (v < 0 || v > 255) {
        field(word, what).text(": ").text(kColourNames[k]).text(" ");
        quote(s, n);
        error_->text(" is outside [0,255]");
        return false;
      }
      c[k] = v;
    }
    const R scale = R(1) / R(255);
    out = Vec3<R>{M::from_int(c[0]) * scale, M::from_int(c[1]) * scale, M::from_int(c[2]) * scale};
    return true;
  }
  // Unit length without overflow or underflow: scaled by the largest
  // component first (the component checks make it non-zero).
  static Vec3<R> unit(const Vec3<R>& v) {
    auto mag = [](R x) { return x < R(0) ? -x : x; };
    R m = mag(v.x);
    if (mag(v.y) > m) m = mag(v.y);
    if (mag(v.z) > m) m = mag(v.z);
    const Vec3<R> s = v / m;
    return s / M::sqrt(dot(s, s));
  }

  // ------------------------------------------------------------- elements
  static constexpr Element kElements[] = {
      {"A", "ambient light", 2, 0, "A RATIO R,G,B", false},
      {"C", "camera", 3, 0, "C X,Y,Z NX,NY,NZ FOV", false},
      {"L", "light", 3, 0, "L X,Y,Z BRIGHTNESS R,G,B", false},
      {"sp", "sphere", 3, 0, "sp X,Y,Z DIAMETER R,G,B", false},
      {"pl", "plane", 3, 0, "pl X,Y,Z NX,NY,NZ R,G,B", false},
      {"cy", "cylinder", 5, 0, "cy X,Y,Z NX,NY,NZ DIAMETER HEIGHT R,G,B", false},
      {"co", "cone", 5, 0, "co X,Y,Z NX,NY,NZ ANGLE HEIGHT R,G,B", true},
      {"plc", "checkered plane", 3, 0, "plc X,Y,Z NX,NY,NZ R,G,B", true},
      {"spt", "textured sphere", 4, 1, "spt X,Y,Z DIAMETER R,G,B TEXTURE.ppm [BUMP.ppm]", true},
  };

  bool element() {
    element_ = nullptr;
    for (const Element& e : kElements)
      if (word_is(0, e.id)) element_ = &e;
    if (element_ == nullptr) {
      at(0).text("unknown element ");
      quote_word(0);
      error_->text(options_.mandatory ? " (expected A, C, L, sp, pl or cy)"
                                      : " (expected A, C, L, sp, pl, cy, co, plc or spt)");
      return false;
    }
    if (options_.mandatory && element_->bonus) {
      at(0).text(element_->name).text(" '").text(element_->id).text("' is a bonus element: the mandatory part has ")
          .text("A, C, L, sp, pl and cy only");
      return false;
    }
    // Mandatory L: the colour is "unused in mandatory part", so it may be left out.
    const bool bare_light = options_.mandatory && element_->id[0] == 'L';
    const int fields = bare_light ? element_->fields - 1 : element_->fields;
    const int optional = bare_light ? element_->optional + 1 : element_->optional;
    const char* usage = bare_light ? "L X,Y,Z BRIGHTNESS [R,G,B]" : element_->usage;
    const int got = count_ - 1 + too_many_;
    if (got < fields || got > fields + optional) {
      const bool extra = got > fields;
      at(extra ? fields + optional + 1 : 0)
          .text(element_->name)
          .text(extra ? " has too many fields: " : " has too few fields: ")
          .text("expected '")
          .text(usage)
          .text("', got ")
          .number(got)
          .text(got == 1 ? " field" : " fields");
      return false;
    }
    const char id0 = buf_[words_[0].start];
    const int idlen = words_[0].length;
    if (idlen == 1 && id0 == 'A') return ambient();
    if (idlen == 1 && id0 == 'C') return camera();
    if (idlen == 1 && id0 == 'L') return light();
    if (word_is(0, "sp")) return sphere(false);
    if (word_is(0, "spt")) return sphere(true);
    if (word_is(0, "pl")) return plane(false);
    if (word_is(0, "plc")) return plane(true);
    return solid(word_is(0, "co"));
  }

  bool once(int& seen_line) {
    if (seen_line != 0) {
      at(0).text("second ").text(element_->name).text(" '").text(element_->id).text("': the first is on line ")
          .number(seen_line).text(" and there may be only one");
      return false;
    }
    seen_line = line_;
    return true;
  }

  bool ambient() {
    if (!once(ambient_line_)) return false;
    R ratio;
    Vec3<R> c;
    if (!scalar_in(1, "ratio", 0, 1, ratio) || !colour(2, c)) return false;
    scene_->ambient = c * ratio;
    return true;
  }

  bool camera() {
    if (!once(camera_line_)) return false;
    Vec3<R> pos, dir;
    R fov;
    if (!triple(1, "position", pos, false, false) || !triple(2, "orientation", dir, true, true) ||
        !scalar_in(3, "field of view", 0, 180, fov))
      return false;
    view_->position = pos;
    view_->direction = unit(dir);
    view_->fov_degrees = fov;
    return true;
  }

  bool light() {
    if (options_.mandatory && !once(light_line_)) return false;
    Vec3<R> pos, c{R(1), R(1), R(1)};
    R brightness;
    if (!triple(1, "position", pos, false, false) || !scalar_in(2, "brightness ratio", 0, 1, brightness) ||
        (count_ > 3 && !colour(3, c)))
      return false;
    // Mandatory: the colour is checked when given, and the light is white.
    if (options_.mandatory) c = Vec3<R>{R(1), R(1), R(1)};
    model::Light<R> l{};
    l.kind = model::LightKind::kPoint;
    l.vector = pos;
    l.color = c * brightness;
    return memory(builder_.add_light(l));
  }

  bool material(const Vec3<R>& c, bool checker, int32_t texture, int32_t bump) {
    model::Material<R> m{};
    m.color = c;
    m.checker = checker;
    m.texture = texture;
    m.bump = bump;
    return memory(builder_.add_material(m));
  }

  bool texture(int word, const char* what, int32_t& id) {
    const Word& w = words_[word];
    if (w.length > kMaxPathBytes) {
      field(word, what).text(" is longer than ").number(kMaxPathBytes).text(" bytes");
      return false;
    }
    char name[kMaxPathBytes + 1];
    for (int k = 0; k < w.length; ++k) name[k] = buf_[w.start + k];
    name[w.length] = 0;
    if (textures_.resolve == nullptr) {
      field(word, what).text(": textures are not available here");
      return false;
    }
    Diagnostic why;
    id = textures_.resolve(textures_.ctx, name, why);
    if (id >= 0) return true;
    field(word, what).text(": ").text(why.message);
    return false;
  }

  bool sphere(bool textured) {
    Vec3<R> centre, c;
    R diameter;
    if (!triple(1, "centre", centre, false, false) || !scalar_positive(2, "diameter", diameter) || !colour(3, c))
      return false;
    int32_t tex = model::kNoTexture, bump = model::kNoTexture;
    if (textured) {
      if (!texture(4, "texture", tex)) return false;
      if (count_ > 5 && !texture(5, "bump map", bump)) return false;
    }
    return material(c, false, tex, bump) && memory(builder_.add_sphere(centre, diameter / R(2)));
  }

  bool plane(bool checker) {
    Vec3<R> point, normal, c;
    if (!triple(1, "point", point, false, false) || !triple(2, "normal", normal, true, true) || !colour(3, c))
      return false;
    const Vec3<R> n = unit(normal);
    return material(c, checker, model::kNoTexture, model::kNoTexture) &&
           memory(builder_.add_plane(n, -dot(n, point)));
  }

  // cy: centre (or base centre), axis, diameter, height. co: base centre, axis toward
  // the tip, half-angle in degrees, height (SPEC.md 2.1). The cone's axis
  // is not range-checked: the shared test_bonus.rt uses 0,1.1,0.
  bool solid(bool cone) {
    Vec3<R> base, axis, c;
    R size, height;
    if (!triple(1, cone ? "base centre" : "centre", base, false, false) ||
        !triple(2, "axis", axis, !cone, true))
      return false;
    if (cone) {
      Decimal dec;
      if (!scalar(3, "angle", size, dec)) return false;
      if (!dec.positive() || !dec.within(0, kMaxConeAngle) || dec.whole == static_cast<uint32_t>(kMaxConeAngle)) {
        field(3, "angle").text(" must be above 0 and below ").number(kMaxConeAngle).text(" degrees");
        return false;
      }
    } else if (!scalar_positive(3, "diameter", size)) {
      return false;
    }
    if (!scalar_positive(4, "height", height) || !colour(5, c)) return false;
    model::Solid<R> s{};
    s.axis = unit(axis);
    s.base = base;
    if (!cone && options_.cylinder_point == CylinderPoint::kCentre) s.base = base - s.axis * (height / R(2));
    s.height = height;
    if (cone) {
      constexpr R kDegree = static_cast<R>(3.14159265358979323846 / 180.0);
      const R a = size * kDegree;
      const R t = M::sin(a) / M::cos(a);
      s.radius = height * t;
      s.slope = -t;
    } else {
      s.radius = size / R(2);
      s.slope = R(0);
    }
    return material(c, false, model::kNoTexture, model::kNoTexture) && memory(builder_.add_solid(s));
  }

  ByteSource in_;
  model::SceneBuilder<R>& builder_;
  TextureResolver textures_;
  ReaderOptions options_;
  model::Scene<R>* scene_ = nullptr;
  View<R>* view_ = nullptr;
  Diagnostic* error_ = nullptr;
  const Element* element_ = nullptr;
  ReadStatus status_ = ReadStatus::kOk;
  bool at_end_ = false;
  int line_ = 0;
  int ambient_line_ = 0;
  int camera_line_ = 0;
  int light_line_ = 0;  // with ReaderOptions::mandatory
  int too_many_ = 0;
  char buf_[kMaxLineBytes];
  int length_ = 0;
  Word words_[kMaxFields + 1];
  int count_ = 0;
};

}  // namespace minrt::minirt
