// Reads an SLD scene in the original program's order (environment, objects,
// AND networks, OR networks) and checks every cross reference, so a bad file
// is rejected before a single output byte is written. Reading stops right
// after the final terminator: over a serial line nothing more may come.
#pragma once

#include <stdint.h>

#include "formats/sld/sld_limits.hpp"

#include "formats/sld/scene.hpp"
#include "formats/sld/sld_values.hpp"

namespace minrt {

// Values: where the numbers come from (sld_values.hpp); SLD text by default.
template <class R, class Values = SldTextValues<R>>
class SldReader {
 public:
  SldReader(ByteSource in, const WarningSink& warnings) : values_(in), warnings_(warnings) {}
  SldReader(const Values& values, const WarningSink& warnings) : values_(values), warnings_(warnings) {}

  // Returns false with `error` filled when the input is not a valid scene.
  bool read(Scene<R>& scene, Diagnostic& error) {
    error_ = &error;
    return read_environment(scene) && read_objects(scene) && read_and_networks(scene) &&
           read_or_networks(scene);
  }

 private:
  // What is being read, for messages: "<field> of object 3".
  struct What {
    const char* field;
    const char* group = nullptr;
    int index = -1;
  };

  bool read_environment(Scene<R>& s) {
    static constexpr const char* kScreen[3] = {"screen x", "screen y", "screen z"};
    for (int i = 0; i < 3; ++i)
      if (!real(s.screen[i], {kScreen[i]})) return false;
    if (!real(s.screen_rotation_deg[0], {"screen rotation (x axis)"}) ||
        !real(s.screen_rotation_deg[1], {"screen rotation (y axis)"}))
      return false;
    int64_t count = 0;
    if (!integer(count, {"light count"})) return false;
    s.light_count = saturate(count);
    return real(s.light_rotation_deg[0], {"light direction angle 1"}) &&
           real(s.light_rotation_deg[1], {"light direction angle 2"}) &&
           real(s.beam, {"highlight intensity"});
  }

  bool read_objects(Scene<R>& s) {
    for (int n = 0;; ++n) {
      int64_t texture = 0;
      const What what{"texture", "object", n};
      if (!integer(texture, what)) return false;
      if (texture == -1) {
        s.object_count = n;
        return true;
      }
      if (n == limits::kMaxObjects)
        return fail(values_.pos(), Diagnostic{}
                                   .text("too many objects: the format allows at most ")
                                   .number(limits::kMaxObjects)
                                   .text(" (or a missing -1 after the objects)"));
      if (!read_object(s.objects[n], n, texture)) return false;
    }
  }

  bool read_object(SceneObject<R>& o, int n, int64_t texture) {
    o.pos = values_.pos();
    o.texture = saturate(texture);
    int64_t form = 0, refl = 0, rot = 0;
    if (!integer(form, {"form", "object", n}) || !integer(refl, {"reflection type", "object", n}) ||
        !integer(rot, {"rotation flag", "object", n}))
      return false;
    o.form = saturate(form);
    o.reflection = saturate(refl);
    o.rotated = saturate(rot);
    static constexpr const char* kAbc[3] = {"size a", "size b", "size c"};
    static constexpr const char* kXyz[3] = {"center x", "center y", "center z"};
    static constexpr const char* kRgb[3] = {"color red", "color green", "color blue"};
    static constexpr const char* kRot[3] = {"rotation x", "rotation y", "rotation z"};
    for (int i = 0; i < 3; ++i)
      if (!real(o.abc[i], {kAbc[i], "object", n})) return false;
    for (int i = 0; i < 3; ++i)
      if (!real(o.center[i], {kXyz[i], "object", n})) return false;
    R polarity = 0;
    if (!real(polarity, {"polarity", "object", n})) return false;
    o.inverted = polarity < 0;
    if (!real(o.diffuse, {"diffuse", "object", n}) || !real(o.hilight, {"highlight", "object", n}))
      return false;
    for (int i = 0; i < 3; ++i)
      if (!real(o.color[i], {kRgb[i], "object", n})) return false;
    for (int i = 0; i < 3; ++i) o.rotation_deg[i] = 0;
    if (o.rotated != 0)
      for (int i = 0; i < 3; ++i)
        if (!real(o.rotation_deg[i], {kRot[i], "object", n})) return false;
    warn_unknown_codes(o, n);
    return true;
  }

  void warn_unknown_codes(const SceneObject<R>& o, int n) {
    if (o.texture < kTextureNone || o.texture > kTextureSpots)
      warn(o.pos, Diagnostic{}
                      .text("object ")
                      .number(n)
                      .text(": unknown texture ")
                      .number(o.texture)
                      .text(", drawn untextured as the original does"));
    if (o.form < kFormBox || o.form > kFormCone)
      warn(o.pos, Diagnostic{}
                      .text("object ")
                      .number(n)
                      .text(": unknown form ")
                      .number(o.form)
                      .text(", solved as a second-degree surface as the original does"));
    if (o.reflection < kReflectDiffuse || o.reflection > kReflectMirror)
      warn(o.pos, Diagnostic{}
                      .text("object ")
                      .number(n)
                      .text(": unknown reflection type ")
                      .number(o.reflection)
                      .text(", treated as non-mirror as the original does"));
  }

  bool read_and_networks(Scene<R>& s) {
    for (int n = 0;; ++n) {
      int16_t* net = s.and_nets[n];
      int len = 0;
      for (;; ++len) {
        int64_t v = 0;
        if (!integer(v, {"object index", "AND network", n})) return false;
        if (v == -1) break;
        if (n == limits::kMaxAndNetworkDefinitions)
          return fail(values_.pos(), Diagnostic{}
                                     .text("too many AND networks: at most ")
                                     .number(limits::kMaxAndNetworkDefinitions)
                                     .text(" may be defined"));
        if (n == limits::kMaxAndNetworks && len == 0)
          warn(values_.pos(), Diagnostic{}
                              .text("AND networks from ")
                              .number(n)
                              .text(" on exceed the original's ")
                              .number(limits::kMaxAndNetworks)
                              .text("; no OR network may use them"));
        if (v < 0 || v >= s.object_count)
          return fail(values_.pos(), Diagnostic{}
                                     .text("AND network ")
                                     .number(n)
                                     .text(" refers to object ")
                                     .number(v)
                                     .text(", but only ")
                                     .number(s.object_count)
                                     .text(" objects are defined"));
        if (len == limits::kMaxAndNetworkLength)
          return fail(values_.pos(), Diagnostic{}
                                     .text("AND network ")
                                     .number(n)
                                     .text(" has more than ")
                                     .number(limits::kMaxAndNetworkLength)
                                     .text(" entries"));
        net[len] = static_cast<int16_t>(v);
      }
      net[len] = -1;
      if (len == 0) {
        s.and_count = n;
        return true;
      }
    }
  }

  bool read_or_networks(Scene<R>& s) {
    for (int n = 0;; ++n) {
      int16_t* net = s.or_nets[n];
      int64_t previous = -2;
      int len = 0;
      for (;; ++len) {
        int64_t v = 0;
        if (!integer(v, {len == 0 ? "range primitive" : "AND network index", "OR network", n}))
          return false;
        if (v == -1) break;
        if (n == limits::kMaxOrNetworks)
          return fail(values_.pos(), Diagnostic{}
                                     .text("too many OR networks: at most ")
                                     .number(limits::kMaxOrNetworks)
                                     .text(" are allowed"));
        if (len == 0 && v != limits::kNoRangePrimitive && (v < 0 || v >= s.object_count))
          return fail(values_.pos(), Diagnostic{}
                                     .text("OR network ")
                                     .number(n)
                                     .text(" has range primitive ")
                                     .number(v)
                                     .text(", but only ")
                                     .number(s.object_count)
                                     .text(" objects are defined (99 means none)"));
        if (len > 0 && v >= s.and_count && v < limits::kMaxAndNetworks && previous == v - 1 &&
            previous >= s.and_count - 1) {
          // Course scenes (lattice.sld) list AND networks 0..N with fewer
          // defined; the original reads the missing ones as empty. Accept such
          // a run past the last defined network; reject any other reference.
          if (previous == s.and_count - 1)
            warn(values_.pos(), Diagnostic{}
                                .text("OR network ")
                                .number(n)
                                .text(" lists undefined AND networks from ")
                                .number(v)
                                .text(" on; they are empty and ignored, as in the original"));
          previous = v;
          --len;
          continue;
        }
        if (len > 0 && v >= limits::kMaxAndNetworks && v < s.and_count)
          return fail(values_.pos(), Diagnostic{}
                                     .text("OR network ")
                                     .number(n)
                                     .text(" refers to AND network ")
                                     .number(v)
                                     .text(", but at most ")
                                     .number(limits::kMaxAndNetworks)
                                     .text(" AND networks (0..")
                                     .number(limits::kMaxAndNetworks - 1)
                                     .text(") can be used, as in the original"));
        if (len > 0 && (v < 0 || v >= s.and_count))
          return fail(values_.pos(), Diagnostic{}
                                     .text("OR network ")
                                     .number(n)
                                     .text(" refers to AND network ")
                                     .number(v)
                                     .text(", but only ")
                                     .number(s.and_count)
                                     .text(" AND networks are defined"));
        if (len == limits::kMaxOrNetworkLength)
          return fail(values_.pos(), Diagnostic{}
                                     .text("OR network ")
                                     .number(n)
                                     .text(" has more than ")
                                     .number(limits::kMaxOrNetworkLength)
                                     .text(" entries"));
        net[len] = static_cast<int16_t>(v);
        if (len > 0) previous = v;
      }
      net[len] = -1;
      if (len == 0) {
        s.or_count = n;
        return true;
      }
    }
  }

  // --- values -------------------------------------------------------------

  // The messages for a value that could not be read; the same whichever
  // source the value came from.
  bool bad_value(ValueStatus st, const What& what, const char* expected) {
    Diagnostic d;
    switch (st) {
      case ValueStatus::kEnd:
        return fail(values_.pos(), describe(d.text("unexpected end of input: expected "), what));
      case ValueStatus::kTooLong:
        return fail(values_.pos(), describe(d.text("token longer than ")
                                                .number(limits::kMaxTokenLength)
                                                .text(" bytes where "),
                                            what)
                                       .text(" was expected"));
      case ValueStatus::kNonFinite:
        describe(d.text("non-finite value for "), what).text(": ").quoted(values_.text(), values_.length());
        return fail(values_.pos(), d);
      default:
        describe(d.text(expected), what).text(", got ").quoted(values_.text(), values_.length());
        if (st == ValueStatus::kOutOfRange) d.text(" (out of range)");
        return fail(values_.pos(), d);
    }
  }

  bool integer(int64_t& out, const What& what) {
    const ValueStatus st = values_.next_int(out);
    return st == ValueStatus::kOk || bad_value(st, what, "expected an integer for ");
  }

  bool real(R& out, const What& what) {
    const ValueStatus st = values_.next_real(out);
    return st == ValueStatus::kOk || bad_value(st, what, "expected a number for ");
  }

  static Diagnostic& describe(Diagnostic& d, const What& what) {
    d.text(what.field);
    if (what.group != nullptr) d.text(" of ").text(what.group).text(" ").number(what.index);
    return d;
  }

  bool fail(SourcePos pos, const Diagnostic& d) {
    *error_ = d;
    error_->pos = pos;
    error_->has_pos = true;
    return false;
  }
  void warn(SourcePos pos, Diagnostic d) {
    d.pos = pos;
    d.has_pos = true;
    warnings_.emit(d);
  }

  static int32_t saturate(int64_t v) {
    if (v > INT32_MAX) return INT32_MAX;
    if (v < INT32_MIN) return INT32_MIN;
    return static_cast<int32_t>(v);
  }

  Values values_;
  WarningSink warnings_;
  Diagnostic* error_ = nullptr;
};

}  // namespace minrt
