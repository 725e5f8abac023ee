// Reader for EASTRAY scenes (the 1995 manual v1.98; SPEC.md 4 and
// ../shared/formats/eastray/AMBIGUITIES.md; docs/eastray.md says what is
// implemented and every reading chosen). It reads text that the host's
// preprocessor has expanded (no #include / #define left).
//
// Three walks over the text: (1) every statement once, obj bodies checked
// for syntax only and their places remembered; (2) each named part walked
// with its calls followed, which resolves every name and finds recursive
// calls; (3) the unnamed objs walked again with their moves and calls,
// which places the primitives, nodes, triangles and object lights.
#pragma once

#include <stdint.h>

#include "core/base/diagnostic.hpp"
#include "core/base/number_parse.hpp"
#include "core/math/math_policy.hpp"
#include "formats/eastray/eastray_lexer.hpp"
#include "formats/eastray/eastray_scene.hpp"

namespace minrt::eastray {

inline constexpr int kMaxParts = 1024;
inline constexpr int kMaxMainObjs = 64;
inline constexpr int kMaxNesting = 32;        // blocks inside blocks, calls inside calls (the board's stack)
inline constexpr int kMaxDepth = 16;          // condition's ray depth: each level is a stack frame
inline constexpr int kMaxImageWidth = 2048;   // manual line 72
// Line 72 sets no height limit. Ours: 2^25 pixels at the widest, the most
// the host's PNG reader takes back (an existing output a window is rendered
// into, a map), and the framed protocol's 16-bit height holds a stereo pair.
inline constexpr int kMaxImageHeight = 16384;
inline constexpr int64_t kMaxCalls = 1000000; // part calls placed in one scene
inline constexpr int kMaxFaceVertices = 256;

template <class M>
class Reader {
  using R = typename M::real;
  using V = Vec3<R>;

 public:
  // The part table (kMaxParts entries) is taken from the top of `scratch`
  // while reading and given back afterwards.
  Reader(const char* text, size_t size, Scene<R>& scene, Arena& scratch, WarningSink warnings = {})
      : lex_(text, size), scene_(scene), scratch_(scratch), warnings_(warnings) {}

  // Arena bytes the reader needs on top of the scene's arrays.
  static constexpr size_t scratch_bytes() { return Arena::footprint<Part>(kMaxParts); }

  bool read(Diagnostic& error) {
    const size_t mark = scratch_.top_mark();
    const bool ok = read_all(error);
    scratch_.release_top(mark);
    return ok;
  }

 private:
  bool read_all(Diagnostic& error) {
    error_ = &error;
    parts_ = scratch_.template alloc_top<Part>(kMaxParts);
    if (parts_ == nullptr) {
      error.text("no memory for the part table");
      return false;
    }
    advance();
    while (!tok_.end()) {
      if (!statement()) return false;
    }
    first_walk_ = false;
    if (tok_.bad_comment) return fail_here("unterminated comment (no '*/' before the end of the scene)");
    if (main_count_ == 0) return fail_here("no main object: the scene needs an 'obj [ ... ]' without a name");
    // Walk 2: names and recursion, part by part.
    for (int i = 0; i < part_count_; ++i)
      if (parts_[i].state == 0 && !visit_part(i)) return false;
    // Walk 3: place everything.
    scene_.root = new_node(NodeKind::kTop, NodeKind::kTop, kNone);
    if (scene_.root == kNone) return false;
    for (int i = 0; i < main_count_; ++i) {
      lex_.seek(mains_[i]);
      advance();
      Walk w;
      w.emit = true;
      w.follow = true;
      w.resolve = true;
      if (!items(w, Affine<R>{}, scene_.root, ']', mains_[i].pos, 0)) return false;
    }
    finish_vertex_normals();
    // back_mode 1 or 2 with no image to composite (lines 212-216): the sky
    // stands in for the image, and the mode still decides whether the
    // infinite lights' discs are seen (docs/eastray.md, "Statements").
    if (scene_.background != 0 && scene_.input[0] == 0)
      warn_at(back_at_, "warning: back_mode 1 and 2 composite the input image, and the scene names none "
                        "('input FILE ;'): the sky is the background");
    return true;
  }

  struct Part {
    char name[kNameBytes];
    Lexer::Mark body;  // just after its '['
    int state;         // 0 unvisited, 1 being visited, 2 done
  };
  struct Walk {
    bool emit = false;    // place primitives, nodes, lights
    bool follow = false;  // read the bodies of called parts
    bool resolve = false; // names must exist (walks 2 and 3)
  };

  // --------------------------------------------------------------- basics
  void advance() { tok_ = lex_.next(); }

  // A table is full: the host tries again with larger ones.
  bool fail_full(const SourcePos& at, const char* msg) {
    error_->out_of_memory = true;
    return fail_at(at, msg);
  }
  bool fail_at(const SourcePos& at, const char* msg) {
    error_->pos = at;
    error_->has_pos = true;
    error_->text(msg);
    return false;
  }
  bool fail_here(const char* msg) {
    if (tok_.bad_comment) {
      error_->pos = tok_.pos;
      error_->has_pos = true;
      error_->text("unterminated comment (no '*/' before the end of the scene)");
      return false;
    }
    fail_at(tok_.pos, msg);
    if (tok_.end()) error_->text(", found the end of the scene");
    else error_->text(", found ").quoted(tok_.s, tok_.length);
    return false;
  }
  void warn(const char* msg) { warn_at(tok_.pos, msg); }
  void warn_at(const SourcePos& at, const char* msg) {
    Diagnostic d;
    d.pos = at;
    d.has_pos = true;
    d.text(msg);
    warnings_.emit(d);
  }

  static bool number_syntax(const Token& t) {
    int i = 0;
    if (i < t.length && (t.s[i] == '+' || t.s[i] == '-')) ++i;
    int digits = 0;
    while (i < t.length && t.s[i] >= '0' && t.s[i] <= '9') ++i, ++digits;
    if (i < t.length && t.s[i] == '.') {
      ++i;
      while (i < t.length && t.s[i] >= '0' && t.s[i] <= '9') ++i, ++digits;
    }
    if (digits == 0) return false;
    if (i < t.length && (t.s[i] == 'e' || t.s[i] == 'E')) {
      ++i;
      if (i < t.length && (t.s[i] == '+' || t.s[i] == '-')) ++i;
      int e = 0;
      while (i < t.length && t.s[i] >= '0' && t.s[i] <= '9') ++i, ++e;
      if (e == 0) return false;
    }
    return i == t.length;
  }
  bool is_number() const { return number_syntax(tok_); }
  static bool is_name_token(const Token& t) {
    if (t.length == 0) return false;
    const char c = t.s[0];
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  }

  // Reads a number; `what` names it in the message.
  // `mapping`: a mapping `< ... >` may follow (not after a RANGE's kind).
  bool number(R& out, const char* what, bool mapping = true) {
    if (!is_number()) {
      char msg[128] = "expected a number (";
      int n = 19;
      for (const char* p = what; *p != 0 && n < 120; ++p) msg[n++] = *p;
      msg[n++] = ')';
      msg[n] = 0;
      return fail_here(msg);
    }
    const NumberStatus st = parse_real<R>(tok_.s, tok_.length, out);
    if (st != NumberStatus::kOk) {
      // The token has a number's syntax: the parser refuses only values
      // beyond the format (kNonFinite) and tokens longer than it reads.
      fail_at(tok_.pos, st == NumberStatus::kNonFinite ? "number out of range: " : "number has too many digits: ");
      error_->quoted(tok_.s, tok_.length);
      return false;
    }
    advance();
    if (mapping) {
      if (collect_maps_ && tok_.is('<')) {
        if (!mapping_block(last_map_, true, false)) return false;
      } else {
        skip_mapping();
      }
    }
    return ok_;
  }
  bool vec(V& out, const char* what) {
    return number(out.x, what) && number(out.y, what) && number(out.z, what);
  }
  bool integer(int32_t& out, const char* what, int32_t lo, int32_t hi, bool mapping = true) {
    const SourcePos at = tok_.pos;
    R v;
    if (!number(v, what, mapping)) return false;
    if (!(v >= R(lo) && v <= R(hi)) || M::from_int(M::to_int(v)) != v) {
      fail_at(at, "expected a whole number from ");
      error_->number(lo).text(" to ").number(hi).text(" (").text(what).text(")");
      return false;
    }
    out = M::to_int(v);
    return true;
  }
  // The display height: the manual sets no limit (line 72), ours is
  // kMaxImageHeight, named in the message.
  bool height(int32_t& out) {
    const SourcePos at = tok_.pos;
    if (!integer(out, "display height", 1, 1 << 30)) return false;
    if (out <= kMaxImageHeight) return true;
    fail_at(at, "display height ");
    error_->number(out).text(" is above ").number(kMaxImageHeight).text(
        ", the most this program renders (line 72 sets no limit; docs/eastray.md says why)");
    return false;
  }
  // condition's ray depth: the manual sets no limit (line 89), ours is
  // kMaxDepth, named in the message.
  bool depth(int32_t& out) {
    const SourcePos at = tok_.pos;
    if (!integer(out, "condition depth", 0, 1 << 30)) return false;
    if (out <= kMaxDepth) return true;
    fail_at(at, "condition depth ");
    error_->number(out).text(" is above ").number(kMaxDepth).text(
        ", the most this program traces (line 89 sets no limit; docs/eastray.md says why)");
    return false;
  }
  // A switch: the manual's explanations (lines 92, 128, 249) give 1 for on
  // and 0 for off, nothing else.
  bool on_off(bool& out, const char* what) {
    const Token at = tok_;
    R v;
    if (!number(v, what)) return false;
    if (!(v == R(0) || v == R(1))) {
      fail_at(at.pos, what);
      error_->text(" must be 0 or 1, found ").quoted(at.s, at.length);
      return false;
    }
    out = v == R(1);
    return true;
  }
  bool expect(char c, const char* what) {
    if (!tok_.is(c)) {
      char msg[128] = "expected '";
      int n = 10;
      msg[n++] = c;
      msg[n++] = '\'';
      msg[n++] = ' ';
      for (const char* p = what; *p != 0 && n < 120; ++p) msg[n++] = *p;
      msg[n] = 0;
      return fail_here(msg);
    }
    advance();
    return true;
  }

  // A mapping `< ... >` after a value: read over, ignored with a warning.
  void skip_mapping() {
    if (!tok_.is('<') || in_polygon_) return;
    if (!mapping_warned_) {
      warn("warning: a mapping '< ... >' follows only a colour's parameters or an object's colour; ignored");
      mapping_warned_ = true;
    }
    const SourcePos at = tok_.pos;
    advance();
    while (!tok_.end() && !tok_.is('>')) advance();
    if (tok_.end()) {
      fail_at(at, "unterminated mapping: no '>' before the end of the scene");
      ok_ = false;
      return;
    }
    advance();
  }


  // ------------------------------------------------------------- mapping
  // The entries of a mapping block `< [moves] map scale mode params ... >`
  // (lines 597-673), appended to the chain whose head is `head` (kNone:
  // empty). `store`: keep the entries (else only check the form);
  // `number_map`: it maps an object's colour number, where the
  // all-directions modes have no range (SPEC.md 4.5).
  bool mapping_block(int32_t& head, bool store, bool number_map) {
    // A '<' after a number inside the block is no mapping of the colour.
    const bool collecting = collect_maps_;
    collect_maps_ = false;
    const bool ok = mapping_entries(head, store, number_map);
    collect_maps_ = collecting;
    return ok;
  }
  bool mapping_entries(int32_t& head, bool store, bool number_map) {
    const SourcePos open = tok_.pos;
    advance();
    int32_t tail = head;
    while (tail != kNone && scene_.mappings[tail].next != kNone) tail = scene_.mappings[tail].next;
    int entries = 0;
    while (!tok_.is('>')) {
      if (tok_.end()) return fail_at(open, "unterminated mapping: no '>' before the end of the scene");
      model::EastrayMapping<R> e{};
      Affine<R> moves;
      while (tok_.length > 0 && tok_.s[0] == ':')
        if (!move(moves)) return false;
      e.from_map = moves;
      const SourcePos map_at = tok_.pos;
      if (is_number()) {
        if (!integer(e.image, "map_data number", 0, 1 << 30, false)) return false;
        if (e.image >= scene_.map_file_count) {
          fail_at(map_at, "undefined map_data number ");
          error_->number(e.image).text(" (map_data must come first; it has ").number(scene_.map_file_count).text(")");
          return false;
        }
      } else if (is_name_token(tok_)) {
        e.image = kNone;
        for (int32_t i = 0; i < scene_.map_file_count; ++i)
          if (scene_.map_files[i].name[0] != 0 && tok_.is(scene_.map_files[i].name)) e.image = i;
        if (e.image == kNone) {
          fail_at(map_at, "undefined map_data name ");
          error_->quoted(tok_.s, tok_.length).text(" (map_data must come first)");
          return false;
        }
        advance();
      } else {
        return fail_here("expected a map_data number or name in the mapping");
      }
      if (!number(e.scale, "mapping scale", false)) return false;
      const SourcePos mode_at = tok_.pos;
      int32_t mode;
      if (!integer(mode, "mapping mode", 0, 14, false)) return false;
      if (mode % 10 > 4) return fail_at(mode_at, "mapping mode must be 0 to 4 or 10 to 14");
      e.mode = static_cast<model::EastrayMapMode>(mode % 10);
      e.filtered = mode >= 10;
      if (e.filtered && !scene_.map_files[e.image].mip)
        return fail_at(mode_at, "mapping modes 10 to 14 need a map_data entry read with mip-mapping switch 1 (line 398)");
      if (number_map && e.mode == model::EastrayMapMode::kAllDirections)
        return fail_at(mode_at, "a colour-number mapping cannot use the all-directions mode (0 or 10)");
      if (e.mode == model::EastrayMapMode::kAllDirections) {
        if (!number(e.u1, "mapping k", false)) return false;
      } else {
        R* f[8] = {&e.u1, &e.v1, &e.u2, &e.v2, &e.ua1, &e.va1, &e.ua2, &e.va2};
        for (R* x : f)
          if (!number(*x, "mapping corner u1 v1 u2 v2 u1a v1a u2a v2a", false)) return false;
        if (e.u1 == e.u2 || e.v1 == e.v2) return fail_at(mode_at, "the mapped image's corners (u1 v1) and (u2 v2) span no area");
      }
      if (!moves.inverse(e.to_map)) return fail_at(open, "the mapping's moves are singular");
      e.next = kNone;
      ++entries;
      if (!store) continue;
      if (scene_.mapping_count >= scene_.mapping_capacity) return fail_full(map_at, "too many mappings for the memory");
      const int32_t id = scene_.mapping_count++;
      scene_.mappings[id] = e;
      if (tail == kNone) head = id;
      else scene_.mappings[tail].next = id;
      tail = id;
    }
    if (entries == 0) return fail_here("empty mapping: expected a map_data number or name");
    advance();
    return true;
  }

  // The mapping chain read since the last call (and forgets it).
  int32_t take_map() {
    const int32_t h = last_map_;
    last_map_ = kNone;
    return h;
  }

  // The material index a surface stores: the colour itself, or a mapped
  // object (its frame, for the mappings) when the colour or its number is
  // mapped.
  bool surface_material(int32_t mat, int32_t number_map, const Affine<R>& m, const SourcePos& at, int32_t& out) {
    out = mat;
    // The anisotropic models' scratches are in the object's frame too.
    const Specular spec = scene_.materials[mat].specular;
    bool mapped = number_map != kNone || spec == Specular::kAniso1 || spec == Specular::kAniso2;
    for (int i = 0; i < model::kMapSlots && !mapped; ++i) mapped = scene_.materials[mat].map[i] != kNone;
    if (!mapped) return true;
    model::EastrayMappedObject<R> o{};
    o.to_world = m;
    if (!m.inverse(o.to_object)) return fail_at(at, "the object's moves are singular");
    o.material = mat;
    o.number_map = number_map;
    if (scene_.mapped_count >= scene_.mapped_capacity) return fail_full(at, "too many mapped objects for the memory");
    scene_.mapped_objects[scene_.mapped_count] = o;
    out = scene_.material_count + scene_.mapped_count++;  // walk 3: every colour is read
    return true;
  }

  // ----------------------------------------------------------- statements
  bool end_statement(const char* name) {
    if (!tok_.is(';')) {
      char msg[96] = "expected ';' to end '";
      int n = 21;
      for (const char* p = name; *p != 0 && n < 90; ++p) msg[n++] = *p;
      msg[n++] = '\'';
      msg[n] = 0;
      return fail_here(msg);
    }
    advance();
    return true;
  }

  bool statement() {
    if (tok_.bad_comment) return fail_here("");
    const Token st = tok_;
    advance();
    if (st.is("display")) {
      R aspect;
      if (!integer(scene_.width, "display width", 1, kMaxImageWidth) ||
          !height(scene_.height) ||
          !integer(scene_.x0, "display x0", -1000000, 1000000) || !integer(scene_.y0, "display y0", -1000000, 1000000) ||
          !integer(scene_.x1, "display x1", -1000000, 1000000) || !integer(scene_.y1, "display y1", -1000000, 1000000) ||
          !integer(scene_.step_x, "display step x", 1, 65536) || !integer(scene_.step_y, "display step y", 1, 65536))
        return false;
      const SourcePos at = tok_.pos;
      if (!number(aspect, "display dot aspect")) return false;
      if (!(aspect > R(0))) return fail_at(at, "display dot aspect must be above 0");
      scene_.aspect = aspect;
      // Line 78: a window that breaks these computes nothing; an image of
      // nothing is refused rather than written black.
      if (!(0 <= scene_.x0 && scene_.x0 <= scene_.x1 && scene_.x1 < scene_.width && 0 <= scene_.y0 &&
            scene_.y0 <= scene_.y1 && scene_.y1 < scene_.height))
        return fail_at(st.pos, "display window must satisfy 0 <= x0 <= x1 < width and 0 <= y0 <= y1 < height (line 75)");
      return end_statement("display");
    }
    if (st.is("condition")) {
      if (!depth(scene_.max_depth) || !number(scene_.min_weight, "condition minimum weight") ||
          !number(scene_.eps, "condition eps") || !on_off(scene_.inner, "condition inner switch"))
        return false;
      if (scene_.eps < R(0)) scene_.eps = -scene_.eps;
      return end_statement("condition");
    }
    if (st.is("anti")) {
      if (!integer(scene_.anti, "anti flag", -1, 16) || !number(scene_.anti_level, "anti level")) return false;
      return end_statement("anti");
    }
    if (st.is("camera")) {
      const SourcePos at = tok_.pos;
      if (!vec(scene_.eye, "camera eye") || !vec(scene_.look, "camera look-at") ||
          !vec(scene_.up_point, "camera sub-look-at point"))
        return false;
      const SourcePos fov_at = tok_.pos;
      if (!number(scene_.fov, "camera half angle") || !number(scene_.parallax, "camera parallax")) return false;
      if (!(scene_.fov > R(0) && scene_.fov < R(90))) return fail_at(fov_at, "camera half angle must be between 0 and 90 degrees");
      const V f = scene_.look - scene_.eye, u = scene_.up_point - scene_.look;
      const V c = cross(f, u);
      if (dot(f, f) == R(0)) return fail_at(at, "camera eye and look-at point are the same");
      if (dot(c, c) == R(0)) return fail_at(at, "camera sub-look-at point lies on the line of sight");
      return end_statement("camera");
    }
    if (st.is("mist")) {
      if (!number(scene_.mist_half, "mist half distance") || !on_off(scene_.mist_to_sky, "mist switch")) return false;
      return end_statement("mist");
    }
    if (st.is("sky")) return vec(scene_.sky, "sky colour") && end_statement("sky");
    if (st.is("env")) return vec(scene_.env, "env colour") && end_statement("env");
    if (st.is("shadow")) {
      if (!on_off(scene_.shadows, "shadow switch")) return false;
      if (tok_.is(';')) advance();  // the manual's syntax line has none (line 246)
      return true;
    }
    if (st.is("voxel")) return integer(scene_.voxel, "voxel count", 0, 1024) && end_statement("voxel");
    if (st.is("rmode")) {
      // 0 one image, 1 two with the camera's parallax (lines 56-58).
      if (!on_off(scene_.stereo, "rmode")) return false;
      return end_statement("rmode");
    }
    if (st.is("output")) {
      if (tok_.end() || tok_.length == 1) return fail_here("expected a file name after 'output'");
      if (tok_.length >= kOutputNameBytes) return fail_here("output file name too long");
      for (int i = 0; i < tok_.length; ++i) scene_.output[i] = tok_.s[i];
      scene_.output[tok_.length] = 0;
      advance();
      return end_statement("output");
    }
    if (st.is("output_mode")) {
      const SourcePos at = tok_.pos;
      R bits;
      if (!number(bits, "output_mode bits")) return false;
      if (bits != R(16) && bits != R(24)) return fail_at(at, "output_mode bits must be 16 or 24 (lines 158-159)");
      scene_.output_bits = bits == R(16) ? 16 : 24;
      if (!on_off(scene_.dither, "output_mode dither switch")) return false;
      return end_statement("output_mode");
    }
    if (st.is("input")) {
      if (tok_.end() || tok_.length == 1) return fail_here("expected a file name after 'input'");
      if (tok_.length >= kOutputNameBytes) return fail_here("input file name too long");
      for (int i = 0; i < tok_.length; ++i) scene_.input[i] = tok_.s[i];
      scene_.input[tok_.length] = 0;
      scene_.input_line = tok_.pos.line;
      scene_.input_col = tok_.pos.col;
      advance();
      return end_statement("input");
    }
    if (st.is("back_mode")) {
      back_at_ = st.pos;
      if (!integer(scene_.background, "back_mode background mode 0, 1 or 2", 0, 2) ||
          !on_off(scene_.back_reflect, "back_mode reflection switch") ||
          !on_off(scene_.back_transmit, "back_mode transmission switch"))
        return false;
      const SourcePos alpha_at = tok_.pos;
      if (!on_off(scene_.alpha_pure, "back_mode alpha mode")) return false;
      // The alpha mode shapes the alpha channel of .hpi images (lines
      // 178, 227-230: HyPER Saiko's format on the FM TOWNS), not written.
      if (scene_.alpha_pure)
        warn_at(alpha_at, "warning: back_mode alpha mode 1 applies to the alpha channel of .hpi images, which are not written");
      return end_statement("back_mode");
    }
    if (st.is("e_light") || st.is("p_light") || st.is("s_light")) {
      const LightKind kind = st.is("e_light") ? LightKind::kInfinite : st.is("p_light") ? LightKind::kPoint : LightKind::kSpot;
      if (!expect('[', "to open the light list")) return false;
      while (!tok_.is(']')) {
        if (tok_.end()) return fail_at(st.pos, "unterminated light list: no ']' before the end of the scene");
        if (!light(kind, Affine<R>{}, true)) return false;
      }
      advance();
      return true;
    }
    if (st.is("color")) return colors(st);
    if (st.is("map_data")) return map_data(st);
    if (st.is("obj")) return obj(st);
    fail_at(st.pos, "unknown statement ");
    error_->quoted(st.s, st.length);
    return false;
  }

  // One light entry (statement list or object light), ending with ';'.
  bool light(LightKind kind, const Affine<R>& to_world, bool emit) {
    Light<R> l{};
    l.kind = kind;
    l.shadow_range = R(-1);
    const SourcePos at = tok_.pos;
    if (kind == LightKind::kInfinite) {
      if (!vec(l.direction, "e_light direction") || !vec(l.color, "e_light colour") ||
          !number(l.size_deg, "e_light apparent size") || !number(l.concentration, "e_light concentration"))
        return false;
      if (dot(l.direction, l.direction) == R(0)) return fail_at(at, "e_light direction is the zero vector");
    } else if (kind == LightKind::kPoint) {
      if (!vec(l.position, "p_light position") || !vec(l.color, "p_light colour") ||
          !number(l.half_distance, "p_light half distance"))
        return false;
    } else {
      V target;
      if (!vec(l.position, "s_light position") || !vec(target, "s_light target") || !vec(l.color, "s_light colour") ||
          !number(l.spread, "s_light spread") || !number(l.half_distance, "s_light half distance"))
        return false;
      l.direction = target - l.position;
      if (dot(l.direction, l.direction) == R(0)) return fail_at(at, "s_light target is its own position");
    }
    for (;;) {
      if (tok_.is("n")) {
        l.no_shadow = true;
        advance();
      } else if (tok_.is("r") && kind != LightKind::kInfinite) {
        advance();
        if (!number(l.shadow_range, "shadow range after 'r'")) return false;
      } else {
        break;
      }
    }
    if (!end_statement("the light")) return false;
    if (!emit) return true;
    // Into world space: positions and directions through the moves in force.
    l.position = to_world.point(l.position);
    l.direction = to_world.vector(l.direction);
    if (dot(l.direction, l.direction) != R(0)) l.direction = normalize<M>(l.direction);
    if (scene_.light_count >= scene_.light_capacity) return fail_full(at, "too many lights for the memory");
    scene_.lights[scene_.light_count++] = l;
    return true;
  }

  bool colors(const Token& st) {
    if (!expect('[', "to open the colour list")) return false;
    while (!tok_.is(']')) {
      if (tok_.end()) return fail_at(st.pos, "unterminated colour list: no ']' before the end of the scene");
      if (!color()) return false;
    }
    advance();
    return true;
  }

  bool color() {
    Material<R> m{};
    for (int32_t& h : m.map) h = kNone;
    const SourcePos at = tok_.pos;
    if (is_name_token(tok_)) {
      if (tok_.length >= kNameBytes) return fail_here("colour name too long");
      for (int i = 0; i < tok_.length; ++i) m.name[i] = tok_.s[i];
      for (int i = 0; i < scene_.material_count; ++i)
        if (tok_.is(scene_.materials[i].name)) return fail_here("colour name defined twice");
      advance();
    }
    // Mappings after each parameter are collected (number() reads them).
    collect_maps_ = true;
    last_map_ = kNone;
    const bool ok = color_fields(m);
    collect_maps_ = false;
    last_map_ = kNone;
    if (!ok) return false;
    if (!end_statement("the colour")) return false;
    if (scene_.material_count >= scene_.material_capacity) return fail_full(at, "too many colours for the memory");
    scene_.materials[scene_.material_count++] = m;
    return true;
  }

  bool color_fields(Material<R>& m) {
    R alg;
    if (!vec(m.diffuse, "diffuse colour")) return false;
    m.map[model::kMapDiffuse] = take_map();
    if (!vec(m.reflect, "reflectance")) return false;
    m.map[model::kMapReflect] = take_map();
    if (!vec(m.transmit, "transmittance")) return false;
    m.map[model::kMapTransmit] = take_map();
    const SourcePos ior_at = tok_.pos;
    if (!number(m.ior, "index of refraction")) return false;
    m.map[model::kMapIor] = take_map();
    // The index matters only for a transparent body (line 554); there it
    // divides, so 0 or less would bend rays through NaN.
    const bool transparent = m.transmit.x != R(0) || m.transmit.y != R(0) || m.transmit.z != R(0);
    if (transparent && !(m.ior > R(0)) && m.map[model::kMapIor] == kNone)
      return fail_at(ior_at, "index of refraction of a transparent colour must be above 0");
    if (!number(m.half_distance, "transparency half distance")) return false;
    m.map[model::kMapHalf] = take_map();
    if (!number(m.bump, "bump")) return false;
    m.map[model::kMapBump] = take_map();
    const SourcePos alg_at = tok_.pos;
    if (!number(alg, "specular algorithm 0 to 5", false)) return false;
    int count = 0;
    if (alg == R(0)) m.specular = Specular::kBlinn, count = 2;
    else if (alg == R(1)) m.specular = Specular::kBlinnGauss, count = 5;
    else if (alg == R(2)) m.specular = Specular::kAniso1, count = 12;
    else if (alg == R(3)) m.specular = Specular::kAniso2, count = 9;
    else if (alg == R(4)) m.specular = Specular::kCookTorrance, count = 6;
    else if (alg == R(5)) m.specular = Specular::kConstant, count = 7;
    else return fail_at(alg_at, "specular algorithm must be 0, 1, 2, 3, 4 or 5");
    for (int i = 0; i < count; ++i) {
      const SourcePos p_at = tok_.pos;
      if (!number(m.p[i], "specular parameter")) return false;
      const int32_t h = take_map();
      if (h == kNone) continue;
      const int group = specular_group(m.specular, i);
      if (group < 0) return fail_at(p_at, "no mapping may follow a position or direction of the anisotropic model");
      m.map[model::kMapSpecular + group] = h;  // a colour's mapping follows its blue
    }
    return true;
  }

  // The first parameter of the group p[i] belongs to (a colour's three
  // share one mapping); -1 for the anisotropic models' vectors, which the
  // manual does not map.
  static int specular_group(Specular s, int i) {
    switch (s) {
      case Specular::kBlinn: return i;
      case Specular::kAniso1: return i < 3 ? 0 : i < 9 ? -1 : i;
      case Specular::kAniso2: return i < 3 ? 0 : i < 6 ? -1 : i;
      case Specular::kConstant: return i < 3 ? 0 : i < 6 ? 3 : i;
      default: return i < 3 ? 0 : i;
    }
  }

  // map_data [ [name] file mip [;] ... ] (lines 369-398): the files are
  // loaded by the host after reading. The manual shows no ';' after an
  // entry; one is accepted (AMBIGUITIES D1).
  bool map_data(const Token& st) {
    if (!expect('[', "to open the map list")) return false;
    while (!tok_.is(']')) {
      if (tok_.end()) return fail_at(st.pos, "unterminated map_data list: no ']' before the end of the scene");
      model::EastrayMapFile f{};
      auto has_dot = [](const Token& t) {
        for (int i = 0; i < t.length; ++i)
          if (t.s[i] == '.') return true;
        return false;
      };
      // A name starts with a letter and has no '.'; a file name has one (line 388).
      if (is_name_token(tok_) && !has_dot(tok_)) {
        if (tok_.length >= static_cast<int>(sizeof f.name)) return fail_here("map_data name too long");
        for (int i = 0; i < tok_.length; ++i) f.name[i] = tok_.s[i];
        for (int i = 0; i < scene_.map_file_count; ++i)
          if (tok_.is(scene_.map_files[i].name)) return fail_here("map_data name defined twice");
        advance();
      }
      if (tok_.end() || tok_.length == 1 || !has_dot(tok_))
        return fail_here("expected a map_data file name with its extension");
      if (tok_.length >= model::kMapFileBytes) return fail_here("map_data file name too long");
      for (int i = 0; i < tok_.length; ++i) f.file[i] = tok_.s[i];
      f.line = tok_.pos.line;
      f.col = tok_.pos.col;
      advance();
      if (!on_off(f.mip, "mip-mapping switch")) return false;
      if (tok_.is(';')) advance();
      if (scene_.map_file_count >= scene_.map_file_capacity) {
        error_->out_of_memory = true;
        return fail_here("too many map_data entries for the memory");
      }
      scene_.map_files[scene_.map_file_count++] = f;
    }
    advance();
    return true;
  }

  // ------------------------------------------------------------------ obj
  bool obj(const Token& st) {
    if (tok_.is('[')) {
      if (main_count_ >= kMaxMainObjs) return fail_here("too many unnamed objs");
      advance();
      mains_[main_count_] = Lexer::at(tok_);
      ++main_count_;
    } else {
      if (!is_name_token(tok_)) return fail_here("expected '[' or a part name after 'obj'");
      if (tok_.length >= kNameBytes) return fail_here("part name too long");
      if (find_part(tok_) != kNone) return fail_here("part defined twice");
      if (part_count_ >= kMaxParts) return fail_here("too many named objs");
      Part& p = parts_[part_count_];
      for (int i = 0; i < tok_.length; ++i) p.name[i] = tok_.s[i];
      p.name[tok_.length] = 0;
      p.state = 0;
      advance();
      if (!expect('[', "to open the part's body")) return false;
      p.body = Lexer::at(tok_);
      ++part_count_;
    }
    Walk w;  // syntax only
    return items(w, Affine<R>{}, kNone, ']', st.pos, 0);
  }

  int32_t find_part(const Token& t) const {
    for (int i = 0; i < part_count_; ++i)
      if (t.is(parts_[i].name)) return i;
    return kNone;
  }
  int32_t find_material(const Token& t) const {
    for (int i = 0; i < scene_.material_count; ++i)
      if (scene_.materials[i].name[0] != 0 && t.is(scene_.materials[i].name)) return i;
    return kNone;
  }

  bool visit_part(int i) {
    parts_[i].state = 1;
    const Lexer::Mark back = lex_.mark();
    const Token saved = tok_;
    lex_.seek(parts_[i].body);
    advance();
    Walk w;
    w.follow = true;
    w.resolve = true;
    if (!items(w, Affine<R>{}, kNone, ']', parts_[i].body.pos, 0)) return false;
    lex_.seek(back);
    tok_ = saved;
    parts_[i].state = 2;
    return true;
  }

  int32_t new_node(NodeKind kind, NodeKind mode, int32_t parent) {
    if (scene_.node_count >= scene_.node_capacity) {
      fail_full(tok_.pos, "too many objects for the memory");
      return kNone;
    }
    const int32_t id = scene_.node_count++;
    Node& n = scene_.nodes[id];
    n.kind = kind;
    n.mode = mode;
    n.parent = parent;
    n.first_child = n.last_child = n.next = kNone;
    n.primitive = kNone;
    if (parent != kNone) {
      Node& p = scene_.nodes[parent];
      if (p.last_child == kNone) p.first_child = id;
      else scene_.nodes[p.last_child].next = id;
      p.last_child = id;
    }
    return id;
  }

  // A move command; composes it after `m` (nearest the object first).
  bool move(Affine<R>& m) {
    const Token t = tok_;
    advance();
    Affine<R> x;
    R v;
    auto axis_rot = [&](int axis, R deg) {
      const R rad = deg * R(3.14159265358979323846 / 180.0);
      const R c = M::cos(rad), s = M::sin(rad);
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;  // right-handed: a -> b
      x.m[a * 3 + a] = c;
      x.m[a * 3 + b] = -s;
      x.m[b * 3 + a] = s;
      x.m[b * 3 + b] = c;
    };
    if (t.is(":mx") || t.is(":my") || t.is(":mz")) {
      if (!number(v, "move distance")) return false;
      const int a = t.s[2] - 'x';
      if (a == 0) x.t.x = v;
      else if (a == 1) x.t.y = v;
      else x.t.z = v;
    } else if (t.is(":rx") || t.is(":ry") || t.is(":rz")) {
      if (!number(v, "rotation angle in degrees")) return false;
      axis_rot(t.s[2] - 'x', v);
    } else if (t.is(":sx") || t.is(":sy") || t.is(":sz")) {
      if (!number(v, "scale factor")) return false;
      const int a = t.s[2] - 'x';
      x.m[a * 4] = v;
    } else if (t.is(":mtx")) {
      R a[16];
      for (R& e : a)
        if (!number(e, ":mtx element")) return false;
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) x.m[r * 3 + c] = a[r * 4 + c];
      }
      x.t = V{a[3], a[7], a[11]};
      // Once per :mtx written: the later walks over the same text stay quiet.
      if (first_walk_ && (a[12] != R(0) || a[13] != R(0) || a[14] != R(0) || a[15] != R(1)))
        warn("warning: the :mtx bottom row is taken as 0 0 0 1 (affine moves only)");
    } else {
      fail_at(t.pos, "unknown move command ");
      error_->quoted(t.s, t.length).text(" (expected :mx :my :mz :rx :ry :rz :sx :sy :sz or :mtx)");
      return false;
    }
    m = m.then_after(x);
    return true;
  }

  // Items up to `close`; `parent` is the node they join (kNone when not
  // placing). `opened` is where the block began, for the unterminated message.
  bool items(const Walk& w, Affine<R> m, int32_t parent, char close, const SourcePos& opened, int depth) {
    if (depth > kMaxNesting) return fail_here("blocks or part calls nested too deeply");
    for (;;) {
      if (tok_.bad_comment) return fail_here("");
      if (tok_.end()) {
        fail_at(opened, "unterminated block: no '");
        const char c[2] = {close, 0};
        error_->text(c).text("' before the end of the scene");
        return false;
      }
      if (tok_.is(close)) {
        advance();
        return true;
      }
      if (tok_.is('[') || tok_.is('{')) {
        const bool is_and = tok_.is('{');
        const SourcePos at = tok_.pos;
        advance();
        int32_t node = kNone;
        if (w.emit && (node = new_node(is_and ? NodeKind::kAnd : NodeKind::kOr, is_and ? NodeKind::kAnd : NodeKind::kOr,
                                       parent)) == kNone)
          return false;
        if (!items(w, m, node, is_and ? '}' : ']', at, depth + 1)) return false;
        if (w.emit) drop_if_empty(node);
      } else if (tok_.is('(')) {
        if (!range(w, m, parent, depth)) return false;
      } else if (tok_.s[0] == ':') {
        if (!move(m)) return false;
      } else if (is_number()) {
        if (!object(w, m, parent)) return false;
      } else if (is_name_token(tok_)) {
        if (!call(w, m, parent, depth)) return false;
      } else {
        return fail_here("expected an object, a move, a block or a part call");
      }
    }
  }

  bool call(const Walk& w, const Affine<R>& m, int32_t parent, int depth) {
    const Token name = tok_;
    advance();
    if (!end_statement("the part call")) return false;
    if (!w.resolve) return true;
    const int32_t p = find_part(name);
    if (p == kNone) {
      fail_at(name.pos, "undefined part ");
      error_->quoted(name.s, name.length);
      return false;
    }
    if (!w.follow) return true;
    if (parts_[p].state == 1) {
      fail_at(name.pos, "recursive call of part ");
      error_->quoted(name.s, name.length).text(" (a part may not call itself, directly or through others)");
      return false;
    }
    if (!w.emit && parts_[p].state == 2) return true;  // already checked
    if (w.emit && ++calls_ > kMaxCalls) return fail_at(name.pos, "too many part calls placed (more than 1000000)");
    const Lexer::Mark back = lex_.mark();
    const Token saved = tok_;
    if (!w.emit) parts_[p].state = 1;
    lex_.seek(parts_[p].body);
    advance();
    // A part's body joins the caller's block: its items combine as the
    // caller's items do (so a call equals its objects written inline).
    if (!items(w, m, parent, ']', parts_[p].body.pos, depth + 1)) return false;
    if (!w.emit) parts_[p].state = 2;
    lex_.seek(back);
    tok_ = saved;
    return true;
  }

  // Parameter counts of kinds 1..16 after the colour and sign.
  static int param_count(int kind) {
    switch (kind) {
      case 1: return 6;
      case 2: return 4;
      case 3: return 6;
      case 4: case 5: return 7;
      case 6: case 7: case 8: case 10: case 11: case 15: return 8;
      case 12: case 13: case 14: return 9;
      case 16: return 6;
      default: return -1;
    }
  }

  bool range(const Walk& w, const Affine<R>& m, int32_t parent, int depth) {
    const SourcePos at = tok_.pos;
    advance();
    const SourcePos kind_at = tok_.pos;
    int32_t kind;
    if (!integer(kind, "RANGE primitive kind 0 to 8", -1000, 1000, false)) return false;
    if (kind < 0 || kind > 8) {
      fail_at(kind_at, "RANGE primitive must be of kind 0 to 8, found kind ");
      error_->number(kind);
      return false;
    }
    R p[13];
    int n = 0;
    if (kind == 0) {
      while (is_number() && n < 13)
        if (!number(p[n++], "quadric coefficient")) return false;
      if (n != 10 && n != 13) return fail_here("RANGE quadric needs 10 coefficients (or l m n and 10)");
    } else {
      const int count = param_count(kind);
      for (; n < count; ++n)
        if (!number(p[n], "RANGE primitive parameter")) return false;
    }
    if (!end_statement("the RANGE primitive")) return false;
    int32_t node = kNone;
    if (w.emit) {
      // A bound combines its items as its parent does.
      const NodeKind mode = scene_.nodes[parent].mode;
      if ((node = new_node(NodeKind::kRange, mode, parent)) == kNone) return false;
      int32_t prim;
      if (!place(kind, m, p, n, kind_at, prim)) return false;
      scene_.primitives[prim].inverted = false;
      scene_.nodes[node].primitive = prim;
    }
    if (!items(w, m, node, ')', at, depth + 1)) return false;
    if (w.emit) drop_if_empty(node);
    return true;
  }

  // A block with nothing drawn in it (empty, or only moves and lights) is
  // no item of its parent, as an empty part call is: otherwise an empty
  // AND or OR would be nothing and empty RANGE inside an AND would hide its
  // siblings, where removing the RANGE (line 1274: only a bound) would not.
  // Nothing was allocated after it, so it is the last node (and a RANGE's
  // bound the last primitive).
  void drop_if_empty(int32_t node) {
    Node& n = scene_.nodes[node];
    if (n.first_child != kNone || node != scene_.node_count - 1) return;
    Node& p = scene_.nodes[n.parent];
    int32_t prev = kNone;
    for (int32_t c = p.first_child; c != node; c = scene_.nodes[c].next) prev = c;
    if (prev == kNone) p.first_child = kNone;
    else scene_.nodes[prev].next = kNone;
    p.last_child = prev;
    if (n.primitive != kNone && n.primitive == scene_.primitive_count - 1) --scene_.primitive_count;
    --scene_.node_count;
  }

  // Object light (-1, -2, -3) or primitive.
  bool object(const Walk& w, Affine<R> m, int32_t parent) {
    const SourcePos at = tok_.pos;
    int32_t kind;
    if (!integer(kind, "object kind", -3, 20)) return false;
    if (kind < 0)
      return light(kind == -1 ? LightKind::kInfinite : kind == -2 ? LightKind::kPoint : LightKind::kSpot, m, w.emit);
    if (kind == 9 || (kind > 16 && kind != 20)) {
      fail_at(at, "unknown object kind ");
      error_->number(kind).text(" (expected 0 to 8, 10 to 16 or 20)");
      return false;
    }
    // Moves for this object only, nearest first like block moves.
    while (tok_.length > 0 && tok_.s[0] == ':')
      if (!move(m)) return false;
    int32_t mat = kNone, mat_map = kNone;
    if (!material_ref(w, mat, mat_map)) return false;
    R sign;
    const SourcePos sign_at = tok_.pos;
    const char* sign_text = tok_.s;
    const int sign_length = tok_.length;
    in_polygon_ = kind == 20;  // the '<' after its sign opens the mesh, not a mapping
    const bool sign_ok = number(sign, "sign 1 or -1");
    in_polygon_ = false;
    if (!sign_ok) return false;
    if (!(sign == R(1) || sign == R(-1))) {  // line 1049 knows only 1 and -1
      fail_at(sign_at, "the sign must be 1 or -1, found ");
      error_->quoted(sign_text, sign_length);
      return false;
    }
    if (kind == 20) {
      if (w.emit && !surface_material(mat, mat_map, m, at, mat)) return false;
      return polygon(w, m, mat, sign < R(0), at);
    }
    R p[13];
    int n = 0;
    if (kind == 0) {
      while (is_number() && n < 13)
        if (!number(p[n++], "quadric coefficient")) return false;
      if (n != 10 && n != 13) return fail_here("quadric (kind 0) needs 10 coefficients a0..a9 (or l m n and a0..a9)");
    } else {
      const int count = param_count(kind);
      for (; n < count; ++n)
        if (!number(p[n], "object parameter")) return false;
    }
    int32_t faces[kFaceCount], face_maps[kFaceCount];
    for (int32_t& f : faces) f = mat;
    for (int32_t& f : face_maps) f = mat_map;
    bool no_shadow = false;
    for (;;) {
      if (tok_.is("n")) {
        no_shadow = true;
        advance();
        continue;
      }
      int face = -1;
      if (tok_.is("r") && kind >= 10 && kind <= 15) face = kFaceSide;
      else if (tok_.is("t") && kind >= 10 && kind <= 15) face = kFaceTop;
      else if (tok_.is("b") && kind >= 10 && kind <= 15) face = kFaceBottom;
      else if (kind == 16 && tok_.length == 1 && tok_.s[0] >= '1' && tok_.s[0] <= '6') face = kFaceBox + tok_.s[0] - '1';
      if (face < 0) break;
      advance();
      int32_t fm = kNone, fmap = kNone;
      if (!material_ref(w, fm, fmap)) return false;
      faces[face] = fm;
      face_maps[face] = fmap;
    }
    if (!end_statement("the object")) return false;
    if (!w.emit) return true;
    int32_t prim;
    if (!place(kind, m, p, n, at, prim)) return false;
    Primitive<R>& q = scene_.primitives[prim];
    q.inverted = sign < R(0);
    q.no_shadow = no_shadow;
    for (int i = 0; i < kFaceCount; ++i) {
      // Faces with the same colour and mapping share one mapped object.
      int j = 0;
      while (j < i && !(faces[j] == faces[i] && face_maps[j] == face_maps[i])) ++j;
      if (j < i) q.material[i] = q.material[j];
      else if (!surface_material(faces[i], face_maps[i], m, at, q.material[i])) return false;
    }
    const int32_t node = new_node(NodeKind::kLeaf, NodeKind::kLeaf, parent);
    if (node == kNone) return false;
    scene_.nodes[node].primitive = prim;
    return true;
  }

  // A colour by number or name (walk 1 only checks the form), and the
  // colour-number mapping after it (kept only when placing).
  bool material_ref(const Walk& w, int32_t& out, int32_t& number_map) {
    number_map = kNone;
    if (is_number()) {
      const SourcePos at = tok_.pos;
      int32_t i;
      if (!integer(i, "colour number", 0, 1 << 30, false)) return false;
      if (w.resolve && i >= scene_.material_count) {
        fail_at(at, "undefined colour number ");
        error_->number(i).text(" (the colour list has ").number(scene_.material_count).text(")");
        return false;
      }
      out = i;
    } else {
      if (!is_name_token(tok_)) return fail_here("expected a colour number or name");
      if (w.resolve) {
        out = find_material(tok_);
        if (out == kNone) {
          fail_at(tok_.pos, "undefined colour ");
          error_->quoted(tok_.s, tok_.length);
          return false;
        }
      }
      advance();
    }
    if (!tok_.is('<')) return true;
    return mapping_block(number_map, w.emit, true);
  }

  // Local frame whose z is `axis` (need not be unit), origin `c`.
  static Affine<R> frame(const V& c, V axis) {
    Affine<R> f;
    const V w = normalize<M>(axis);
    const V helper = (w.x < R(0) ? -w.x : w.x) < R(0.9) ? V{R(1), R(0), R(0)} : V{R(0), R(1), R(0)};
    const V u = normalize<M>(cross(helper, w));
    const V v = cross(w, u);
    f.m[0] = u.x, f.m[1] = v.x, f.m[2] = w.x;
    f.m[3] = u.y, f.m[4] = v.y, f.m[5] = w.y;
    f.m[6] = u.z, f.m[7] = v.z, f.m[8] = w.z;
    f.t = c;
    return f;
  }

  // Builds the primitive of `kind` with parameters p[0..n) under the moves m.
  bool place(int kind, const Affine<R>& m, const R* p, int n, const SourcePos& at, int32_t& out) {
    if (scene_.primitive_count >= scene_.primitive_capacity) return fail_full(at, "too many objects for the memory");
    Primitive<R>& q = scene_.primitives[scene_.primitive_count];
    q = Primitive<R>{};
    q.kind = static_cast<uint8_t>(kind);
    q.shape = kind == 16 ? Shape::kBox : Shape::kQuadric;
    for (R& a : q.q) a = R(0);
    Affine<R> placement;
    const V c{p[0], p[1], p[2]};
    const V axis{p[3], p[4], p[5]};
    auto need_axis = [&]() {
      if (largest_component(axis) == R(0)) {
        fail_at(at, "the object's axis vector is zero");
        return false;
      }
      placement = frame(c, squarable_direction(axis));
      return true;
    };
    auto positive = [&](R v, const char* what) {
      if (v > R(0)) return true;
      fail_at(at, what);
      return false;
    };
    switch (kind) {
      case 0: {
        const R* a = n == 13 ? p + 3 : p;
        if (n == 13) placement.t = c;
        bool any = false;
        for (int i = 0; i < 10; ++i) {
          q.q[i] = a[i];
          any = any || a[i] != R(0);
        }
        // All zero has no surface. Numbers below the precision's least read
        // as 0, so tiny coefficients (the same surface at any scale) would
        // vanish in float alone: say so rather than draw nothing.
        if (!any)
          return fail_at(at, sizeof(R) == 4 ? "the quadric's coefficients all read as 0 (in float, anything below about 1.4e-45 "
                                              "is 0): it has no surface; scaling all ten up keeps its shape"
                                            : "the quadric's coefficients all read as 0 (in double, anything below about 4.9e-324 "
                                              "is 0): it has no surface; scaling all ten up keeps its shape");
        break;
      }
      case 1:
        if (!need_axis()) return false;
        q.q[8] = R(1);  // z < 0 inside: the normal side is outside
        break;
      case 2:
        if (!positive(p[3], "sphere radius must be above 0")) return false;
        placement.t = c;
        q.q[0] = q.q[1] = q.q[2] = R(1);
        q.q[9] = -p[3] * p[3];
        break;
      case 3:
        if (!positive(p[3], "ellipsoid semi-axes must be above 0") || !positive(p[4], "ellipsoid semi-axes must be above 0") ||
            !positive(p[5], "ellipsoid semi-axes must be above 0"))
          return false;
        placement.t = c;
        q.q[0] = R(1) / (p[3] * p[3]);
        q.q[1] = R(1) / (p[4] * p[4]);
        q.q[2] = R(1) / (p[5] * p[5]);
        q.q[9] = R(-1);
        break;
      case 16:
        if (!positive(p[3], "box half sizes must be above 0") || !positive(p[4], "box half sizes must be above 0") ||
            !positive(p[5], "box half sizes must be above 0"))
          return false;
        placement.t = c;
        q.q[0] = p[3], q.q[1] = p[4], q.q[2] = p[5];
        break;
      default: {
        if (!need_axis()) return false;
        const R s = p[6];  // r/t slope, or the radius (5, 15), or q (6)
        switch (kind) {
          case 4: case 10: case 11:  // cone: x2 + y2 - s2 z2
            if (!positive(s, "cone slope r/t must be above 0")) return false;
            q.q[0] = q.q[1] = R(1);
            q.q[2] = -s * s;
            if (kind == 10) q.clip_low = q.clip_high = true, q.z_low = R(0), q.z_high = p[7];
            if (kind == 11) q.clip_low = q.clip_high = true, q.z_low = -p[7], q.z_high = p[7];
            if (kind != 4 && !positive(p[7], "cone height h must be above 0")) return false;
            break;
          case 5: case 15:  // cylinder
            if (!positive(s, "cylinder radius must be above 0")) return false;
            q.q[0] = q.q[1] = R(1);
            q.q[9] = -s * s;
            if (kind == 15) {
              if (!positive(p[7], "cylinder half length h must be above 0")) return false;
              q.clip_low = q.clip_high = true, q.z_low = -p[7], q.z_high = p[7];
            }
            break;
          case 6:  // spheroid: q along the axis, r across
            if (!positive(p[6], "spheroid semi-axes must be above 0") || !positive(p[7], "spheroid semi-axes must be above 0"))
              return false;
            q.q[0] = q.q[1] = R(1) / (p[7] * p[7]);
            q.q[2] = R(1) / (p[6] * p[6]);
            q.q[9] = R(-1);
            break;
          case 7: case 14:  // one sheet: x2 + y2 - s2 z2 - d2
            if (!positive(s, "hyperboloid slope r/t must be above 0") || !positive(p[7], "hyperboloid waist radius must be above 0"))
              return false;
            q.q[0] = q.q[1] = R(1);
            q.q[2] = -s * s;
            q.q[9] = -p[7] * p[7];
            if (kind == 14) {
              if (!positive(p[8], "hyperboloid half length h must be above 0")) return false;
              q.clip_low = q.clip_high = true, q.z_low = -p[8], q.z_high = p[8];
            }
            break;
          case 8: case 12: case 13:  // two sheets: x2 + y2 - s2 (z2 - d2), vertices at +-d
            if (!positive(s, "hyperboloid slope r/t must be above 0") || !positive(p[7], "hyperboloid vertex distance must be above 0"))
              return false;
            q.q[0] = q.q[1] = R(1);
            q.q[2] = -s * s;
            q.q[9] = s * s * p[7] * p[7];
            if (kind == 12) {
              if (!(p[8] > p[7])) return fail_at(at, "hyperboloid cut h must lie beyond the vertex d");
              q.clip_low = q.clip_high = true, q.z_low = R(0), q.z_high = p[8];
            }
            if (kind == 13) {
              if (!(p[8] > p[7])) return fail_at(at, "hyperboloid cut h must lie beyond the vertex d");
              q.clip_low = q.clip_high = true, q.z_low = -p[8], q.z_high = p[8];
            }
            break;
          default: break;
        }
      }
    }
    const Affine<R> to_world = m.then_after(placement);
    if (!to_world.inverse(q.to_local)) return fail_at(at, "the moves make this object flat (a singular transform)");
    out = scene_.primitive_count++;
    return true;
  }

  // A mesh's vertex ids -> their place in scene_.vertices: open addressing
  // over a table from the arena's top, filled once all vertices are read.
  struct VertexIndex {
    int32_t* slots = nullptr;
    uint32_t mask = 0;

    static uint32_t hash(int32_t id) { return static_cast<uint32_t>(id) * 2654435761u; }
    int32_t find(int32_t id, const int32_t* ids) const {
      if (slots == nullptr) return kNone;
      for (uint32_t h = hash(id) & mask;; h = (h + 1) & mask) {
        if (slots[h] == kNone || ids[slots[h]] == id) return slots[h];
      }
    }
  };

  // Fills `index` with the vertices from `first` on; a repeated id is an
  // error at its second definition (found again from the mesh's start).
  bool index_vertices(int32_t first, const Lexer::Mark& body, VertexIndex& index) {
    const uint32_t n = static_cast<uint32_t>(scene_.vertex_count - first);
    uint32_t size = 16;
    while (size < 2 * n) size *= 2;
    index.slots = scratch_.template alloc_top<int32_t>(size);
    if (index.slots == nullptr) {
      error_->out_of_memory = true;
      return fail_here("no memory to index the polygon's vertices");
    }
    index.mask = size - 1;
    for (uint32_t i = 0; i < size; ++i) index.slots[i] = kNone;
    for (int32_t v = first; v < scene_.vertex_count; ++v) {
      const int32_t id = scene_.vertex_ids[v];
      uint32_t h = VertexIndex::hash(id) & index.mask;
      while (index.slots[h] != kNone && scene_.vertex_ids[index.slots[h]] != id) h = (h + 1) & index.mask;
      if (index.slots[h] != kNone) return duplicate_vertex(body, id);
      index.slots[h] = v;
    }
    return true;
  }

  bool duplicate_vertex(const Lexer::Mark& body, int32_t id) {
    lex_.seek(body);
    int seen = 0;
    for (advance(); !tok_.end() && !tok_.is('>'); advance()) {
      if (!tok_.is("p")) continue;
      advance();
      R v;
      if (number_syntax(tok_) && parse_real<R>(tok_.s, tok_.length, v) == NumberStatus::kOk && v == M::from_int(id) &&
          ++seen == 2)
        break;
    }
    fail_at(tok_.pos, "polygon vertex number defined twice: ");
    error_->number(id);
    return false;
  }

  // Kind 20: `< p id x y z ... P i j k ... ; [c col] [s] [k w] [n] ... >` then ';'.
  bool polygon(const Walk& w, const Affine<R>& m, int32_t mat, bool /*inverted*/, const SourcePos& at) {
    if (!tok_.is('<')) return fail_here("expected '<' to open the polygon's vertices and faces");
    const SourcePos open = tok_.pos;
    in_polygon_ = true;
    advance();
    const Lexer::Mark body = Lexer::at(tok_);
    const size_t scratch_mark = scratch_.top_mark();
    VertexIndex index;
    const int32_t first_vertex = scene_.vertex_count;
    const int32_t first_triangle = scene_.triangle_count;
    int32_t mesh_vertices = 0;  // walk 1 counts only
    bool faces_started = false;
    while (!tok_.is('>')) {
      if (tok_.end()) {
        in_polygon_ = false;
        return fail_at(open, "unterminated polygon: no '>' before the end of the scene");
      }
      if (tok_.is("p")) {
        if (faces_started) return fail_here("polygon vertices ('p') must all come before the faces ('P')");
        advance();
        const SourcePos id_at = tok_.pos;
        int32_t id;
        V pos;
        if (!integer(id, "vertex number", 0, 0x7fffffff) || !vec(pos, "vertex position")) return false;
        // Stored in every walk, so faces are checked everywhere; a walk
        // that places nothing drops them again at the end.
        if (scene_.vertex_count >= scene_.vertex_capacity) return fail_full(id_at, "too many vertices for the memory");
        scene_.vertex_ids[scene_.vertex_count] = id;
        scene_.vertices[scene_.vertex_count] = m.point(pos);
        scene_.vertex_normals[scene_.vertex_count] = V{};
        ++scene_.vertex_count;
        ++mesh_vertices;
      } else if (tok_.is("P")) {
        if (!faces_started && !index_vertices(first_vertex, body, index)) return false;
        faces_started = true;
        if (!face(w, mat, index, m)) return false;
      } else {
        in_polygon_ = false;
        return fail_here("expected 'p' (vertex), 'P' (face) or '>' in the polygon");
      }
    }
    in_polygon_ = false;
    if (!faces_started && mesh_vertices > 0 && !index_vertices(first_vertex, body, index)) return false;
    scratch_.release_top(scratch_mark);
    advance();
    if (mesh_vertices == 0) return fail_at(at, "polygon has no vertices");
    if (!w.emit) scene_.vertex_count = first_vertex;
    bool no_shadow = false;
    while (tok_.is("n")) {
      no_shadow = true;
      advance();
    }
    if (no_shadow)
      for (int32_t i = first_triangle; i < scene_.triangle_count; ++i) scene_.faces[i].no_shadow = true;
    return end_statement("the polygon object");
  }

  // `mirrored`: the moves turn space inside out, so the counter-clockwise
  // order seen from outside (line 1220) becomes clockwise.
  bool face(const Walk& w, int32_t mat, const VertexIndex& index, const Affine<R>& m) {
    const bool mirrored = m.det() < R(0);
    const SourcePos at = tok_.pos;  // the 'P'
    advance();
    int32_t idx[kMaxFaceVertices];
    int count = 0;
    while (!tok_.is(';')) {
      const SourcePos id_at = tok_.pos;
      int32_t id;
      if (!integer(id, "vertex number of the face", 0, 0x7fffffff)) return false;
      if (count >= kMaxFaceVertices) return fail_at(id_at, "polygon face has too many vertices");
      const int32_t found = index.find(id, scene_.vertex_ids);
      if (found == kNone) {
        fail_at(id_at, "polygon face uses undefined vertex ");
        error_->number(id);
        return false;
      }
      idx[count++] = found;
    }
    if (count < 3) return fail_at(at, "polygon face needs at least 3 vertices");
    advance();  // ';'
    int32_t fmat = mat;
    bool smooth = false, no_shadow = false;
    R weight = R(1);
    for (;;) {
      if (tok_.is("c")) {
        advance();
        const SourcePos c_at = tok_.pos;
        int32_t fmap = kNone;
        if (!material_ref(w, fmat, fmap)) return false;
        if (w.emit && !surface_material(fmat, fmap, m, c_at, fmat)) return false;
      } else if (tok_.is("s")) {
        smooth = true;
        advance();
      } else if (tok_.is("k")) {
        advance();
        if (!number(weight, "smoothing weight after 'k'")) return false;
      } else if (tok_.is("n")) {
        no_shadow = true;
        advance();
      } else {
        break;
      }
    }
    if (!w.emit) return true;
    // A fan from the first vertex; the face normal (for smoothing) from
    // Newell's sum, so a slightly non-planar face still gets one normal.
    V nsum{};
    for (int i = 0; i < count; ++i) {
      const V& a = scene_.vertices[idx[i]];
      const V& b = scene_.vertices[idx[(i + 1) % count]];
      nsum += V{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    if (mirrored) nsum = -nsum;
    if (dot(nsum, nsum) > R(0) && smooth) {
      const V fn = normalize<M>(nsum) * weight;
      for (int i = 0; i < count; ++i) scene_.vertex_normals[idx[i]] += fn;
    }
    for (int i = 1; i + 1 < count; ++i) {
      if (scene_.triangle_count >= scene_.triangle_capacity) return fail_full(at, "too many polygons for the memory");
      Triangle<R>& t = scene_.triangles[scene_.triangle_count];
      t = Triangle<R>{};  // whole: the array is not zeroed (Scene::allocate)
      t.p0 = scene_.vertices[idx[0]];
      t.p1 = scene_.vertices[idx[i]];
      t.p2 = scene_.vertices[idx[i + 1]];
      const V n = cross(t.p1 - t.p0, t.p2 - t.p0);
      if (dot(n, n) == R(0)) continue;  // a degenerate sliver hides nothing
      t.normal = mirrored ? -normalize<M>(n) : normalize<M>(n);
      t.material = static_cast<uint32_t>(fmat);
      t.order = static_cast<uint32_t>(scene_.triangle_count);
      MeshFace& f = scene_.faces[scene_.triangle_count];
      f = MeshFace{};
      f.vertex[0] = idx[0], f.vertex[1] = idx[i], f.vertex[2] = idx[i + 1];
      f.smooth = smooth;
      f.no_shadow = no_shadow;
      ++scene_.triangle_count;
    }
    return true;
  }

  void finish_vertex_normals() {
    for (int32_t i = 0; i < scene_.vertex_count; ++i) {
      const V n = scene_.vertex_normals[i];
      if (dot(n, n) > R(0)) scene_.vertex_normals[i] = normalize<M>(n);
    }
  }

  Lexer lex_;
  Token tok_;
  Scene<R>& scene_;
  Arena& scratch_;
  WarningSink warnings_;
  Diagnostic* error_ = nullptr;
  bool ok_ = true;
  bool mapping_warned_ = false;
  SourcePos back_at_{};          // the back_mode statement
  bool first_walk_ = true;       // walk 1: the text is read for the first time
  bool collect_maps_ = false;     // reading a colour: number() keeps mappings
  int32_t last_map_ = kNone;      // the chain read since take_map()
  bool in_polygon_ = false;
  Part* parts_ = nullptr;
  int part_count_ = 0;
  Lexer::Mark mains_[kMaxMainObjs];
  int main_count_ = 0;
  int64_t calls_ = 0;
};

}  // namespace minrt::eastray
