// Reader for Jaworski's keyword scenes (SPEC.md 3.2 and the notes of
// ../shared/formats/jaworski: the grammar the original program accepts).
// Keywords and colour names in any letter case, `#` comments wherever a
// space may be, the header fields in any order (each at most once), then
// `lights` and `objects`, both required. A number is an optional sign (a
// token of its own), then a decimal, hex (0x) or octal (0o) natural or a
// decimal with a fraction and/or exponent (`.5` and `5.` are refused);
// decimals are rounded correctly. The original's checks (sizes, depth,
// colours, radii, weights >= 0) give located errors here.
#pragma once

#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/base/number_parse.hpp"
#include "core/math/math_policy.hpp"
#include "formats/jaworski/jaworski_scene.hpp"

namespace minrt::jaworski {

inline constexpr int kMaxTokenBytes = 255;
inline constexpr int kMaxMixedDepth = 64;  // nesting of `mixed` (recursion)
inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxRayDepth = 1000;  // reflections recurse: bounded stack
inline constexpr double kMinDepth = 1e-5;  // the original's eps

template <class M>
class Reader {
  using R = typename M::real;

 public:
  Reader(ByteSource in, Scene<R>& scene) : in_(in), scene_(scene) {}

  // False with a located error.
  bool read(Diagnostic& error) {
    error_ = &error;
    advance();
    if (!header()) return false;
    if (!expect_keyword("lights", "'lights' (the light list, may be empty)")) return false;
    while (is_word("directional") || is_word("spherical"))
      if (!light()) return false;
    if (!expect_keyword("objects", "'objects' (the object list, may be empty)")) return false;
    while (is_word("sphere") || is_word("plane"))
      if (!object()) return false;
    if (tok_.kind != Kind::kEnd) return fail("expected 'sphere', 'plane' or the end of the scene");
    return ok_;
  }

 private:
  enum class Kind { kEnd, kWord, kNumber, kSign, kBad };
  struct Token {
    Kind kind = Kind::kEnd;
    char text[kMaxTokenBytes + 1] = {};
    int length = 0;
    SourcePos pos;
  };

  // ---------------------------------------------------------------- lexer
  int peek() {
    if (!have_) {
      c_ = in_.get();
      have_ = true;
    }
    return c_;
  }
  int take() {
    const int c = peek();
    have_ = false;
    if (c == '\n') {
      ++line_;
      col_ = 1;
    } else if (c >= 0) {
      ++col_;
    }
    return c;
  }
  static bool letter(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
  static bool digit(int c) { return c >= '0' && c <= '9'; }
  static bool space(int c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f'; }

  void push(int c) {
    if (tok_.length < kMaxTokenBytes) tok_.text[tok_.length] = static_cast<char>(c);
    ++tok_.length;
  }

  void advance() {
    for (;;) {
      while (space(peek())) take();
      if (peek() == '#') {
        while (peek() >= 0 && peek() != '\n') take();
        continue;
      }
      break;
    }
    tok_.length = 0;
    tok_.pos = SourcePos{line_, col_};
    const int c = peek();
    if (c < 0) {
      tok_.kind = Kind::kEnd;
    } else if (letter(c)) {
      tok_.kind = Kind::kWord;
      while (letter(peek()) || digit(peek()) || peek() == '_' || peek() == '\'') push(take());
    } else if (c == '+' || c == '-') {
      tok_.kind = Kind::kSign;
      while (peek() == '+' || peek() == '-') push(take());
    } else if (digit(c)) {
      tok_.kind = Kind::kNumber;
      lex_number();
    } else {
      tok_.kind = Kind::kBad;
      push(take());
    }
    if (tok_.length > kMaxTokenBytes) tok_.kind = Kind::kBad;
    tok_.text[tok_.length < kMaxTokenBytes ? tok_.length : kMaxTokenBytes] = 0;
  }

  // A natural (decimal, 0x hex, 0o octal) or a decimal with a fraction
  // and/or an exponent; a fraction needs digits on both sides of the point.
  void lex_number() {
    const int first = take();
    push(first);
    if (first == '0' && (peek() == 'x' || peek() == 'X' || peek() == 'o' || peek() == 'O')) {
      const bool hex = peek() == 'x' || peek() == 'X';
      push(take());
      bool any = false;
      while (hex ? (digit(peek()) || (peek() >= 'a' && peek() <= 'f') || (peek() >= 'A' && peek() <= 'F'))
                 : (peek() >= '0' && peek() <= '7')) {
        push(take());
        any = true;
      }
      if (!any) tok_.kind = Kind::kBad;
      return;
    }
    while (digit(peek())) push(take());
    if (peek() == '.') {
      push(take());
      if (!digit(peek())) {
        tok_.kind = Kind::kBad;
        return;
      }
      while (digit(peek())) push(take());
    }
    if (peek() == 'e' || peek() == 'E') {
      push(take());
      if (peek() == '+' || peek() == '-') push(take());
      if (!digit(peek())) {
        tok_.kind = Kind::kBad;
        return;
      }
      while (digit(peek())) push(take());
    }
  }

  // --------------------------------------------------------------- helpers
  // A table is full: the host tries again with larger ones.
  bool fail_full(const char* msg) {
    if (ok_) error_->out_of_memory = true;
    return fail(msg);
  }
  bool fail(const char* msg) {
    if (!ok_) return false;
    ok_ = false;
    error_->pos = tok_.pos;
    error_->has_pos = true;
    error_->text(msg);
    if (tok_.kind == Kind::kEnd) error_->text(", found the end of the scene");
    else error_->text(", found ").quoted(tok_.text, tok_.length);
    return false;
  }
  bool fail_value(const SourcePos& at, const char* what, const char* rule) {
    if (!ok_) return false;
    ok_ = false;
    error_->pos = at;
    error_->has_pos = true;
    error_->text(what).text(" ");
    if (last_length_ > 0) error_->text(last_number()).text(" ");
    error_->text(rule);
    return false;
  }
  bool is_word(const char* kw) const {
    if (tok_.kind != Kind::kWord) return false;
    int i = 0;
    for (; i < tok_.length; ++i) {
      const char a = tok_.text[i], b = kw[i];
      if (b == 0) return false;
      const char la = a >= 'A' && a <= 'Z' ? static_cast<char>(a - 'A' + 'a') : a;
      if (la != b) return false;
    }
    return kw[i] == 0;
  }
  const char* last_number() {
    last_[last_length_] = 0;
    return last_;
  }
  bool expect_keyword(const char* kw, const char* what) {
    if (!is_word(kw)) {
      char msg[96] = "expected ";
      int n = 9;
      for (const char* p = what; *p != 0 && n < 95; ++p) msg[n++] = *p;
      msg[n] = 0;
      return fail(msg);
    }
    advance();
    return true;
  }
  bool starts_number() const { return tok_.kind == Kind::kNumber || tok_.kind == Kind::kSign; }

  // Optional sign token, then a number token.
  bool number(R& out, bool integer_only, int64_t* as_int = nullptr) {
    bool negative = false;
    if (tok_.kind == Kind::kSign) {
      if (tok_.length != 1) return fail("expected a number");
      negative = tok_.text[0] == '-';
      advance();
    }
    if (tok_.kind != Kind::kNumber) return fail("expected a number");
    const char* s = tok_.text;
    const int n = tok_.length;
    last_length_ = 0;
    if (negative) last_[last_length_++] = '-';
    for (int i = 0; i < n && last_length_ < kMaxTokenBytes; ++i) last_[last_length_++] = s[i];
    bool is_natural = true;
    for (int i = 0; i < n; ++i)
      if (s[i] == '.' || ((s[i] == 'e' || s[i] == 'E') && !(n > 1 && (s[1] == 'x' || s[1] == 'X')))) is_natural = false;
    if (integer_only && !is_natural) return fail("expected an integer");
    R v = R(0);
    if (is_natural) {
      int64_t i = 0;
      if (parse_int(s, n, i) != NumberStatus::kOk || i < 0) return fail("number out of range");
      if (as_int != nullptr) *as_int = negative ? -i : i;
      // Through its decimal digits, so the conversion is correctly rounded
      // without an integer-to-float instruction.
      char digits[24];
      const size_t len = format_decimal(i, digits);
      if (parse_real<R>(digits, static_cast<int>(len), v) != NumberStatus::kOk) return fail("number out of range");
    } else if (parse_real<R>(s, n, v) != NumberStatus::kOk) {
      return fail("number out of range");
    }
    out = negative ? -v : v;
    advance();
    return true;
  }
  bool vector(Vec3<R>& v) { return number(v.x, false) && number(v.y, false) && number(v.z, false); }
  bool color(Vec3<R>& c) {
    struct Named {
      const char* name;
      int r, g, b;
    };
    static constexpr Named kNames[] = {{"black", 0, 0, 0}, {"white", 1, 1, 1}, {"red", 1, 0, 0},
                                       {"green", 0, 1, 0}, {"blue", 0, 0, 1},  {"cyan", 0, 1, 1},
                                       {"magenta", 1, 0, 1}, {"yellow", 1, 1, 0}};
    if (tok_.kind == Kind::kWord) {
      for (const Named& k : kNames)
        if (is_word(k.name)) {
          c = Vec3<R>{k.r != 0 ? R(1) : R(0), k.g != 0 ? R(1) : R(0), k.b != 0 ? R(1) : R(0)};  // no int-to-float conversion
          advance();
          return true;
        }
      return fail("expected a colour (R G B or a colour name)");
    }
    return vector(c);
  }
  static bool nonnegative(const Vec3<R>& c) { return c.x >= R(0) && c.y >= R(0) && c.z >= R(0); }

  // --------------------------------------------------------------- grammar
  bool header() {
    bool seen[7] = {};
    static constexpr const char* kFields[7] = {"imwidth", "imheight", "canvwidth", "canvheight",
                                               "depth",   "bgcolor",  "raydepth"};
    for (;;) {
      int f = -1;
      for (int i = 0; i < 7; ++i)
        if (is_word(kFields[i])) f = i;
      if (f < 0) break;
      if (seen[f]) return fail("header field given twice");
      seen[f] = true;
      advance();
      const SourcePos at = tok_.pos;
      int64_t iv = 0;
      R dv;
      switch (f) {
        case 0:
        case 1:
          if (!number(dv, true, &iv)) return false;
          if (iv < 1 || iv > kMaxImageSide)
            return fail_value(at, f == 0 ? "image width" : "image height", "must be in 1..16384");
          (f == 0 ? scene_.width : scene_.height) = static_cast<int32_t>(iv);
          break;
        case 2:
        case 3:
          if (!number(dv, false)) return false;
          if (!(dv >= R(0))) return fail_value(at, f == 2 ? "canvas width" : "canvas height", "must be >= 0");
          (f == 2 ? scene_.canvas_width : scene_.canvas_height) = dv;
          break;
        case 4:
          if (!number(dv, false)) return false;
          if (!(dv >= static_cast<R>(kMinDepth))) return fail_value(at, "depth", "must be >= 1e-05");
          scene_.depth = dv;
          break;
        case 5:
          if (!color(scene_.background)) return false;
          if (!nonnegative(scene_.background)) {
            last_length_ = 0;
            return fail_value(at, "background colour", "components must be >= 0");
          }
          break;
        case 6:
          if (!number(dv, true, &iv)) return false;
          if (iv < 0 || iv > kMaxRayDepth) return fail_value(at, "ray depth", "must be in 0..1000");
          scene_.ray_depth = static_cast<int32_t>(iv);
          break;
      }
    }
    for (int i = 0; i < 5; ++i)
      if (!seen[i]) {
        char msg[64] = "missing header field '";
        int n = 22;
        for (const char* p = kFields[i]; *p != 0; ++p) msg[n++] = *p;
        msg[n++] = '\'';
        msg[n] = 0;
        return fail(msg);
      }
    return true;
  }

  bool light() {
    const bool directional = is_word("directional");
    advance();
    const SourcePos at = tok_.pos;
    R intensity;
    Vec3<R> c, v;
    if (!number(intensity, false) || !color(c) || !vector(v)) return false;
    if (scene_.light_count == scene_.light_capacity) return fail_full("too many lights");
    Light<R>& l = scene_.lights[scene_.light_count++];
    l.kind = directional ? LightKind::kDirectional : LightKind::kSpherical;
    l.color = c * intensity;
    if (!nonnegative(l.color)) {
      last_length_ = 0;
      return fail_value(at, "light", "intensity x colour must be >= 0 in every component");
    }
    if (directional) {
      const Vec3<R> back = v * R(-1);
      l.vector = back * (R(1) / M::sqrt(dot(back, back)));
    } else {
      l.vector = v;
    }
    return true;
  }

  bool object() {
    const bool sphere = is_word("sphere");
    advance();
    Object<R> o{};
    o.kind = sphere ? ShapeKind::kSphere : ShapeKind::kPlane;
    if (sphere) {
      if (!vector(o.point)) return false;
      const SourcePos at = tok_.pos;
      if (!number(o.radius, false)) return false;
      if (!(o.radius >= R(0))) return fail_value(at, "sphere radius", "must be >= 0");
    } else {
      Vec3<R> n;
      if (!vector(o.point) || !vector(n)) return false;
      // In float a normal whose squared length under- or overflows keeps
      // its direction; double keeps the original's operations.
      if constexpr (sizeof(R) < sizeof(double)) n = squarable_direction(n);
      o.normal = n * (R(1) / M::sqrt(dot(n, n)));
    }
    if (!surface(o.surface, 0)) return false;
    if (scene_.object_count == scene_.object_capacity) return fail_full("too many objects");
    scene_.objects[scene_.object_count++] = o;
    return true;
  }

  bool surface(int32_t& index, int depth) {
    if (depth > kMaxMixedDepth) return fail("'mixed' nested too deeply");
    if (scene_.surface_count == scene_.surface_capacity) return fail_full("too many surfaces");
    index = scene_.surface_count++;
    SurfaceNode<R> node{};
    const SourcePos at = tok_.pos;
    if (is_word("diffusive") || is_word("luminous")) {
      node.s.kind = is_word("diffusive") ? SurfaceKind::kDiffusive : SurfaceKind::kLuminous;
      advance();
      const SourcePos cat = tok_.pos;
      if (!color(node.color)) return false;
      if (!nonnegative(node.color)) {
        last_length_ = 0;
        return fail_value(cat, "surface colour", "components must be >= 0");
      }
    } else if (is_word("reflective")) {
      node.s.kind = SurfaceKind::kReflective;
      advance();
    } else if (is_word("mixed")) {
      node.s.kind = SurfaceKind::kMixed;
      advance();
      if (!starts_number()) return fail("expected a weight after 'mixed'");
      int32_t last = kNone;
      // Greedy, like the original: a nested mixture takes every pair after it.
      while (starts_number()) {
        const SourcePos wat = tok_.pos;
        R w;
        if (!number(w, false)) return false;
        if (!(w >= R(0))) return fail_value(wat, "mixed weight", "must be >= 0");
        if (scene_.part_count == scene_.part_capacity) return fail_full("too many mixed parts");
        const int32_t p = scene_.part_count++;
        int32_t child = kNone;
        if (!surface(child, depth + 1)) return false;
        scene_.parts[p] = Part<R>{w, child, kNone};
        if (last == kNone) node.s.first_part = p;
        else scene_.parts[last].next = p;
        last = p;
      }
    } else {
      (void)at;
      return fail("expected a surface: diffusive, reflective, luminous or mixed");
    }
    scene_.surfaces[index] = node;
    return true;
  }

  ByteSource in_;
  Scene<R>& scene_;
  Diagnostic* error_ = nullptr;
  bool ok_ = true;
  Token tok_;
  int c_ = -1;
  bool have_ = false;
  int line_ = 1, col_ = 1;
  char last_[kMaxTokenBytes + 2] = {};  // the last number read, for messages
  int last_length_ = 0;
};

}  // namespace minrt::jaworski
