// The scene formats: the only list of them in the code base. Each entry says
// how the format is named and recognised, how it travels to the board and
// what comes back; the host (host/format_sides/) and the board (runtime/) keep
// one table each of what they do with a format, indexed by FormatId and
// checked at compile time against this list (docs/architecture.md, "Adding
// a format").
//
// Recognition is one rule, the same on host and board: the file name's
// extension when it names one format, else the first word of the text (a
// UTF-8 byte-order mark and blanks skipped, letters compared without case),
// else, for an extension two formats share, the first of them, else SLD,
// the original program's stdin format (detect_format).
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/limits.hpp>

namespace minrt::formats {

enum class FormatId : uint8_t { kSld, kCs418, kJaworski, kMinirt, kEastray };

enum class ImageKind : uint8_t { kPpm, kPng, kBmp };

// How errors are printed: `FILE:LINE:COL: error: MESSAGE`, or the 42
// subject's "Error" line followed by the message.
enum class ErrorStyle : uint8_t { kLocated, kMinirtError };

// What the first word of a text must look like for a format to claim it.
struct FirstWords {
  const char* const* words;   // lower case; the text's word matches when equal
  const char* const* prefixes; // lower case; the text's word starts with one
};

struct Format {
  FormatId id;
  const char* name;         // --scene-format NAME
  const char* title;        // for messages and docs
  const char* const* extensions;  // lower case, with the dot; null-terminated
  FirstWords first_words;
  // The first word that needs the next non-blank byte to decide (EASTRAY's
  // `color [`, which CS418 also starts a line with); 0 when none.
  const char* word_with_next;
  char next_byte;
  uint32_t wire_tag;        // course and framed uploads' format word
  ImageKind reply;          // the image the board sends back
  int default_width, default_height;  // 0: the scene gives its size
  ErrorStyle errors;
  const char* const* options;  // minrt's options for this format alone (long names); null-terminated
};

namespace registry_detail {
inline constexpr const char* kSldExt[] = {".sld", nullptr};
inline constexpr const char* kCs418Ext[] = {".txt", nullptr};
inline constexpr const char* kJaworskiExt[] = {".txt", nullptr};
inline constexpr const char* kMinirtExt[] = {".rt", nullptr};
inline constexpr const char* kEastrayExt[] = {".ray", nullptr};
inline constexpr const char* kNone[] = {nullptr};
inline constexpr const char* kMinirtOptions[] = {"mandatory", "cylinder-base", nullptr};

inline constexpr const char* kCs418Words[] = {
    "png",   "color", "sphere", "sun",   "expose",    "eye",          "forward", "up",  "fisheye",
    "panorama", "plane", "xyz", "tri",   "trif",  "trit",  "texcoord",  "texture",      "bulb",    "shininess",
    "bounces", "transparency", "ior", "roughness", "aa", "dof", "gi", nullptr};
// Jaworski's header fields may be glued to their values; `#` starts its comments.
inline constexpr const char* kJaworskiPrefixes[] = {"imwidth", "imheight", "canvwidth", "canvheight", "depth",
                                                    "bgcolor", "raydepth", "lights",    "objects",   "#",
                                                    nullptr};
inline constexpr const char* kMinirtWords[] = {"a", "c", "l", "sp", "pl", "cy", "co", "plc", "spt", nullptr};
inline constexpr const char* kEastrayWords[] = {
    "display", "condition", "anti",  "camera", "mist",     "sky",   "env",       "shadow",   "voxel",   "output",
    "rmode",   "e_light",   "p_light", "s_light", "map_data", "obj", "input", "back_mode", "output_mode", "#include",
    "#define", "#undef",   "#ifdef", "#ifndef", "#if",     nullptr};
inline constexpr const char* kEastrayPrefixes[] = {"/*", nullptr};
}  // namespace registry_detail

// In the order the first word is tried: EASTRAY before Jaworski (both use
// `#`), and a CS418 word before a miniRT one. SLD claims no word: numbers.
inline constexpr Format kFormats[] = {
    {FormatId::kSld, "sld", "min-rt SLD", registry_detail::kSldExt, {registry_detail::kNone, registry_detail::kNone},
     nullptr, 0, 0, ImageKind::kPpm, limits::kDefaultImageWidth, limits::kDefaultImageHeight, ErrorStyle::kLocated,
     registry_detail::kNone},
    {FormatId::kCs418, "cs418", "CS418", registry_detail::kCs418Ext,
     {registry_detail::kCs418Words, registry_detail::kNone}, nullptr, 0, 1, ImageKind::kPng, 0, 0,
     ErrorStyle::kLocated, registry_detail::kNone},
    {FormatId::kJaworski, "jaworski", "Jaworski", registry_detail::kJaworskiExt,
     {registry_detail::kNone, registry_detail::kJaworskiPrefixes}, nullptr, 0, 2, ImageKind::kBmp, 0, 0,
     ErrorStyle::kLocated, registry_detail::kNone},
    {FormatId::kMinirt, "minirt", "42 miniRT", registry_detail::kMinirtExt,
     {registry_detail::kMinirtWords, registry_detail::kNone}, nullptr, 0, 3, ImageKind::kPng, 800, 600,
     ErrorStyle::kMinirtError, registry_detail::kMinirtOptions},
    {FormatId::kEastray, "eastray", "EASTRAY", registry_detail::kEastrayExt,
     {registry_detail::kEastrayWords, registry_detail::kEastrayPrefixes}, "color", '[', 4, ImageKind::kPng, 0, 0,
     ErrorStyle::kLocated, registry_detail::kNone},
};
inline constexpr size_t kFormatCount = sizeof kFormats / sizeof kFormats[0];
inline constexpr uint8_t kUtf8Bom[3] = {0xEF, 0xBB, 0xBF};

namespace registry_detail {
inline constexpr bool ids_in_order() {
  for (size_t i = 0; i < kFormatCount; ++i)
    if (static_cast<size_t>(kFormats[i].id) != i) return false;
  return true;
}
static_assert(ids_in_order(), "kFormats is indexed by FormatId");

inline constexpr char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
inline constexpr bool blank(uint8_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// `text[0..n)` equals `word`, or starts with it when `prefix`, letters without case.
inline constexpr bool matches(const char* text, size_t n, const char* word, bool prefix) {
  size_t i = 0;
  for (; word[i] != 0; ++i)
    if (i >= n || lower(text[i]) != word[i]) return false;
  return prefix || i == n;
}

inline constexpr bool any_of(const char* const* list, const char* text, size_t n, bool prefix) {
  for (; *list != nullptr; ++list)
    if (matches(text, n, *list, prefix)) return true;
  return false;
}
}  // namespace registry_detail

inline constexpr const Format& format_of(FormatId id) { return kFormats[static_cast<size_t>(id)]; }

// Whether a side's table of what it does per format (its rows have an `id`)
// has one row per registered format, in the registry's order: each side
// checks its table with it at compile time.
template <class Row, size_t N>
constexpr bool follows_registry(const Row (&rows)[N]) {
  if (N != kFormatCount) return false;
  for (size_t i = 0; i < N; ++i)
    if (rows[i].id != kFormats[i].id) return false;
  return true;
}

// The format named `name` (as --scene-format takes it), or null.
inline constexpr const Format* format_named(const char* name) {
  for (const Format& f : kFormats) {
    size_t n = 0;
    while (name[n] != 0) ++n;
    if (registry_detail::matches(name, n, f.name, false)) return &f;
  }
  return nullptr;
}

// Whether `option` (a long name, "mandatory") is one of `f`'s own options.
inline constexpr bool takes_option(const Format& f, const char* option) {
  size_t n = 0;
  while (option[n] != 0) ++n;
  return registry_detail::any_of(f.options, option, n, false);
}

// The format whose upload carries `tag`, or null.
inline constexpr const Format* format_with_tag(uint32_t tag) {
  for (const Format& f : kFormats)
    if (f.wire_tag == tag) return &f;
  return nullptr;
}

// How many bytes a leading UTF-8 byte-order mark takes (0 or 3).
inline constexpr size_t bom_bytes(const uint8_t* text, size_t n) {
  return n >= 3 && text[0] == kUtf8Bom[0] && text[1] == kUtf8Bom[1] && text[2] == kUtf8Bom[2] ? 3 : 0;
}

// The start of a text, as recognition needs it: the first word (the bytes
// up to a blank, at most kWordBytes of them) after a UTF-8 byte-order mark,
// blanks and `#` comment lines (a `#` word a format lists, EASTRAY's
// `#include`, is a word, not a comment), and the first non-blank byte after
// it (0 if none). Text that is all comments has the word "#". `complete`
// says whether the bytes given were enough to know: a reader of a stream
// (the board) gives more until it is.
struct TextStart {
  static constexpr size_t kWordBytes = 24;
  char word[kWordBytes] = {};
  size_t length = 0;
  char next = 0;
  bool complete = false;
};

namespace registry_detail {
// Whether the `#` word at text[0..n) is one a format lists (a directive).
inline constexpr bool listed_hash_word(const uint8_t* text, size_t n);
}  // namespace registry_detail

inline constexpr TextStart text_start(const uint8_t* text, size_t n) {
  TextStart s;
  size_t i = bom_bytes(text, n);
  bool comment = false;
  for (;;) {
    while (i < n && registry_detail::blank(text[i])) ++i;
    if (i >= n || text[i] != '#') break;
    size_t end = i;
    while (end < n && !registry_detail::blank(text[end])) ++end;
    if (registry_detail::listed_hash_word(text + i, end - i)) break;
    comment = true;
    while (i < n && text[i] != '\n') ++i;
    if (i >= n) {  // the comment may go on
      s.word[0] = '#';
      s.length = 1;
      return s;
    }
  }
  if (i >= n) {  // nothing but blanks and comments so far
    if (comment) {
      s.word[0] = '#';
      s.length = 1;
    }
    return s;
  }
  while (i < n && !registry_detail::blank(text[i])) {
    if (s.length < TextStart::kWordBytes) s.word[s.length++] = static_cast<char>(text[i]);
    ++i;
  }
  while (i < n && registry_detail::blank(text[i])) ++i;
  if (i < n) {
    s.next = static_cast<char>(text[i]);
    s.complete = true;
  }
  return s;
}

namespace registry_detail {
inline constexpr bool listed_hash_word(const uint8_t* text, size_t n) {
  char word[TextStart::kWordBytes] = {};  // a copy as chars: constexpr allows no reinterpret_cast
  if (n > TextStart::kWordBytes) return false;
  for (size_t i = 0; i < n; ++i) word[i] = static_cast<char>(text[i]);
  for (const Format& f : kFormats)
    if (any_of(f.first_words.words, word, n, false)) return true;
  return false;
}
}  // namespace registry_detail

// Whether `f` claims a text that starts with `s`.
inline constexpr bool claims(const Format& f, const TextStart& s) {
  if (s.length == 0) return false;
  // Jaworski's glued tokens ("imWidth=4") and EASTRAY's "/*EASTRAY": a
  // prefix list looks at the word's start; a word list needs the whole word,
  // where a word ends at the first byte that is not a letter, digit, '_' or
  // '#'.
  size_t n = 0;
  while (n < s.length) {
    const char c = registry_detail::lower(s.word[n]);
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '#')) break;
    ++n;
  }
  if (f.word_with_next != nullptr && registry_detail::matches(s.word, n, f.word_with_next, false))
    return s.next == f.next_byte;
  return registry_detail::any_of(f.first_words.words, s.word, n, false) ||
         registry_detail::any_of(f.first_words.prefixes, s.word, s.length, true);
}

// The format of a text from its start alone (the board's rule): the first
// format that claims it, else SLD.
inline constexpr const Format& format_of_text(const TextStart& s) {
  // EASTRAY first: `#include` and `/*` are its, and Jaworski takes any other `#`.
  const Format& eastray = format_of(FormatId::kEastray);
  if (claims(eastray, s)) return eastray;
  for (const Format& f : kFormats)
    if (&f != &eastray && claims(f, s)) return f;
  return format_of(FormatId::kSld);
}

// Whether `path` ends in `ext`, without case.
inline constexpr bool has_extension(const char* path, const char* ext) {
  size_t n = 0, e = 0;
  while (path[n] != 0) ++n;
  while (ext[e] != 0) ++e;
  if (n <= e) return false;  // ".rt" alone is no name
  for (size_t i = 0; i < e; ++i)
    if (registry_detail::lower(path[n - e + i]) != ext[i]) return false;
  return path[n - e - 1] != '/';
}

// The host's rule: the extension when one format has it; otherwise the
// format the text's start names (a `.txt` file that starts like a miniRT
// scene is one, whose reader then says the name must end in .rt); a text no
// format claims is the first format with the extension (an empty `.txt` is
// CS418's), or SLD without a known extension.
inline constexpr const Format& detect_format(const char* path, const TextStart& s) {
  const Format* first_with_ext = nullptr;
  int with_ext = 0;
  if (path != nullptr)
    for (const Format& f : kFormats)
      for (const char* const* e = f.extensions; *e != nullptr; ++e)
        if (has_extension(path, *e)) {
          if (first_with_ext == nullptr) first_with_ext = &f;
          ++with_ext;
        }
  if (with_ext == 1) return *first_with_ext;
  const Format& by_text = format_of_text(s);
  if (with_ext == 0) return by_text;
  for (const Format& f : kFormats)
    if (claims(f, s)) return by_text;
  return *first_with_ext;
}

}  // namespace minrt::formats
