// The board side of the texture preamble a scene's textures travel in ahead
// of its text (include/minrt/serial_protocol.h), plain, compressed or
// sparse (only the tiles host-send's render reads, with their tile mask for
// the render's check): the texels go straight into the arena, and the
// scene reader later finds them by name. The four readers (from the line or
// in memory) share the header readers.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"
#include "core/base/diagnostic.hpp"
#include "core/base/inflate.hpp"
#include "protocol/texel_filter.hpp"

namespace minrt::send::textures {

struct Received {
  char name[256];
  int32_t width;
  int32_t height;
  const uint8_t* rgb;  // in the arena
  // Compressed preamble only: the stream's size and start, the texels' CRC-32.
  uint32_t packed_size;
  uint32_t crc;
  const uint8_t* packed;
  // Sparse preamble only: the form (0: every texel; k: tiles of 2^(k-1)
  // texels a side), the texels sent, and the tile mask (in the arena; null
  // when every texel is there).
  uint8_t form;
  uint32_t sent;
  const uint8_t* tiles;
};

inline bool is_marker(int c) {
  return c == MINRT_TEXTURES_MARKER || c == MINRT_TEXTURES_DEFLATE_MARKER || c == MINRT_TEXTURES_SPARSE_MARKER;
}

struct Table {
  Received items[MINRT_MAX_TEXTURES];
  int count = 0;
  bool sparse = false;  // some texture came without every texel (its `tiles` set)

  // Index of the texture with this name, or -1.
  int32_t find(const char* name) const {
    for (int i = 0; i < count; ++i) {
      int k = 0;
      while (name[k] != 0 && name[k] == items[i].name[k]) ++k;
      if (name[k] == 0 && items[i].name[k] == 0) return i;
    }
    return -1;
  }
};

// The texture count that starts every preamble.
inline bool read_count(ByteSource& in, int& count, Diagnostic& error) {
  count = in.get();
  if (count < 1 || count > MINRT_MAX_TEXTURES) {
    error.text("texture preamble: bad texture count");
    return false;
  }
  return true;
}

namespace detail {

inline uint32_t le32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}

inline bool read_bytes(ByteSource& in, uint8_t* out, size_t n) {
  for (size_t k = 0; k < n; ++k) {
    const int c = in.get();
    if (c < 0) return false;
    out[k] = static_cast<uint8_t>(c);
  }
  return true;
}

inline bool read_le32(ByteSource& in, uint32_t& v) {
  uint8_t b[4];
  if (!read_bytes(in, b, 4)) return false;
  v = le32(b);
  return true;
}

inline size_t texel_bytes(const Received& r) {
  return static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
}

}  // namespace detail

// A texture's name (length byte, bytes) and size (two 16-bit little-endian
// words), the head every preamble gives each texture.
inline bool read_name_and_size(ByteSource& in, Received& r, Diagnostic& error) {
  const int len = in.get();
  if (len < 1) {
    error.text("texture preamble: bad name length");
    return false;
  }
  for (int k = 0; k < len; ++k) {
    const int c = in.get();
    if (c < 0) {
      error.text("texture preamble cut off in a name");
      return false;
    }
    r.name[k] = static_cast<char>(c);
  }
  r.name[len] = 0;
  uint8_t b[4];
  if (!detail::read_bytes(in, b, 4)) {
    error.text("texture preamble cut off in the size of ").text(r.name);
    return false;
  }
  r.width = b[0] | b[1] << 8;
  r.height = b[2] | b[3] << 8;
  if (r.width < 1 || r.height < 1 || r.width > MINRT_MAX_TEXTURE_SIDE || r.height > MINRT_MAX_TEXTURE_SIDE) {
    error.text("texture ").text(r.name).text(": bad size");
    return false;
  }
  return true;
}

// One texture's whole header in a preamble with this marker: name and
// size; compressed: the stream's size and the CRC-32; sparse: the form and
// the texels sent too.
inline bool read_texture_header(ByteSource& in, int marker, Received& r, Diagnostic& error) {
  r.form = 0;
  r.tiles = nullptr;
  if (!read_name_and_size(in, r, error)) return false;
  r.sent = static_cast<uint32_t>(r.width) * static_cast<uint32_t>(r.height);
  if (marker == MINRT_TEXTURES_MARKER) return true;
  uint8_t form = 0;
  if (!detail::read_le32(in, r.packed_size) || !detail::read_le32(in, r.crc) ||
      (marker == MINRT_TEXTURES_SPARSE_MARKER && (!detail::read_bytes(in, &form, 1) || !detail::read_le32(in, r.sent)))) {
    error.text("texture preamble cut off in the header of ").text(r.name);
    return false;
  }
  r.form = form;
  const uint32_t texels = static_cast<uint32_t>(r.width) * static_cast<uint32_t>(r.height);
  if (form > MINRT_TEXTURES_MAX_TILE_FORM || r.sent > texels || (form == 0 && r.sent != texels)) {
    error.text("texture ").text(r.name).text(": bad form");
    return false;
  }
  return true;
}

// Every header of a preamble in memory (`data` after the marker byte), the
// table pointing into it: plain texels and compressed streams where they
// lie. `lead`: the compressed preamble's. `used`: the bytes read.
inline bool read_headers(const uint8_t* data, size_t size, int marker, Table& table, uint32_t& lead, size_t& used,
                         Diagnostic& error) {
  MemorySource mem{data, size};
  ByteSource in = mem.source();
  int count = 0;
  if (!read_count(in, count, error)) return false;
  lead = 0;
  if (marker != MINRT_TEXTURES_MARKER && !detail::read_le32(in, lead)) {
    error.text("texture preamble cut off in its header");
    return false;
  }
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (!read_texture_header(in, marker, r, error)) return false;
    const size_t bytes = marker == MINRT_TEXTURES_MARKER ? detail::texel_bytes(r) : r.packed_size;
    if (bytes > size - mem.pos) {
      error.text("texture ").text(r.name).text(" cut off after ").number(static_cast<int64_t>(size - mem.pos)).text(
          " bytes");
      return false;
    }
    r.rgb = marker == MINRT_TEXTURES_MARKER ? data + mem.pos : nullptr;
    r.packed = data + mem.pos;
    mem.pos += bytes;
    table.count = t + 1;
  }
  used = mem.pos;
  return true;
}

// Reads the plain preamble after its marker byte (`in` must pass every byte
// value through). False with the reason: a cut-off preamble, a bad size, or
// a texture that does not fit in the arena.
inline bool receive(ByteSource in, Arena& arena, Table& table, Diagnostic& error) {
  int count = 0;
  if (!read_count(in, count, error)) return false;
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (!read_texture_header(in, MINRT_TEXTURES_MARKER, r, error)) return false;
    const size_t bytes = detail::texel_bytes(r);
    uint8_t* rgb = arena.alloc_zeroed<uint8_t>(bytes);
    if (rgb == nullptr) {
      error.text("texture ").text(r.name).text(" (").number(r.width).text("x").number(r.height).text(
          ") does not fit in the board's memory");
      return false;
    }
    for (size_t i = 0; i < bytes; ++i) {
      const int c = in.get();
      if (c < 0) {
        error.text("texture ").text(r.name).text(" cut off after ").number(static_cast<int64_t>(i)).text(" bytes");
        return false;
      }
      rgb[i] = static_cast<uint8_t>(c);
    }
    r.rgb = rgb;
    table.count = t + 1;
  }
  return true;
}

// The plain preamble already in memory (course and framed protocols: the
// scene upload holds it, protocol/text_scene_upload.hpp): the table points
// into `data`, nothing is copied. `data` starts after the marker byte;
// `used` is the preamble's length from there.
inline bool view(const uint8_t* data, size_t size, Table& table, size_t& used, Diagnostic& error) {
  uint32_t lead = 0;
  return read_headers(data, size, MINRT_TEXTURES_MARKER, table, lead, used, error);
}

namespace detail {

// A ByteSource that ends after `left` bytes of another.
struct Limited {
  ByteSource in;
  size_t left;
  static int read_fn(void* ctx) {
    auto* self = static_cast<Limited*>(ctx);
    if (self->left == 0) return -1;
    --self->left;
    return self->in.get();
  }
  ByteSource source() { return ByteSource{&read_fn, this}; }
};

// Inflates one texture's stream into `out` (its texel bytes), undoes the
// filter and checks the CRC-32. `in_place`: the stream's address when it
// lies in the same memory above `out`. A sparse texture's stream decodes
// into the tail of `out`, its tile mask is copied to the arena's bottom
// end, and its texels are spread out from there (texel_filter.hpp).
inline bool decode(ByteSource stream, Received& r, uint8_t* out, const uint8_t* in_place, Arena& arena,
                   Diagnostic& error) {
  const size_t bytes = texel_bytes(r);
  const int shift = r.form - 1;
  const size_t mask = r.form == 0 ? 0 : tile_mask_bytes(r.width, r.height, shift);
  uint8_t* tiles = mask == 0 ? nullptr : arena.alloc_uninit<uint8_t>(mask);
  if (mask != 0 && tiles == nullptr) {
    error.text("texture ").text(r.name).text(": no room for its tile mask");
    return false;
  }
  const size_t want = r.form == 0 ? bytes : mask + 3 * static_cast<size_t>(r.sent);
  if (want > bytes) {
    error.text("texture ").text(r.name).text(": bad form");
    return false;
  }
  uint8_t* at = out + (bytes - want);
  const size_t mark = arena.top_mark();
  Inflater* inflater = arena.alloc_top<Inflater>(1);
  uint8_t* scratch = arena.alloc_top<uint8_t>(static_cast<size_t>(r.width) * 3);
  if (inflater == nullptr || scratch == nullptr) {
    arena.release_top(mark);
    error.text("texture ").text(r.name).text(": no room to decode it");
    return false;
  }
  const InflateStatus s = inflater->run(stream, at, want, in_place);
  const bool whole = s == InflateStatus::kDone && inflater->produced() == want && inflater->consumed() == r.packed_size;
  bool tiles_match = true;
  if (whole && r.form == 0) texel_filter::unfilter(out, static_cast<size_t>(r.width), static_cast<size_t>(r.height), scratch);
  if (whole && r.form != 0) {
    for (size_t i = 0; i < mask; ++i) tiles[i] = at[i];
    const TileMask m{tiles, tiles_along(static_cast<size_t>(r.width), shift), shift};
    tiles_match = texel_filter::sent_texels(m, static_cast<size_t>(r.width), static_cast<size_t>(r.height)) == r.sent;
    if (tiles_match)
      texel_filter::unfilter_sparse(out, static_cast<size_t>(r.width), static_cast<size_t>(r.height), m, at + mask,
                                    scratch);
    r.tiles = tiles;
  }
  arena.release_top(mark);
  if (!whole) {
    error.text("texture ").text(r.name).text(": ");
    if (s != InflateStatus::kDone) error.text(inflate_message(s));
    else if (inflater->produced() != want)
      error.text("compressed data decodes to ").number(static_cast<int64_t>(inflater->produced())).text(" of ").number(
          static_cast<int64_t>(want)).text(" bytes");
    else error.text("compressed data ends before its stated size");
    return false;
  }
  if (!tiles_match) {
    error.text("texture ").text(r.name).text(": the tile mask does not hold the texels sent");
    return false;
  }
  if (crc32(out, bytes) != r.crc) {
    error.text("texture ").text(r.name).text(": texels damaged (CRC-32 mismatch)");
    return false;
  }
  return true;
}

}  // namespace detail

// Reads a compressed or sparse preamble after its marker byte from the
// line, each texture inflated into the arena as its bytes arrive (nothing
// is held).
inline bool receive_compressed(ByteSource in, Arena& arena, Table& table, Diagnostic& error,
                               int marker = MINRT_TEXTURES_DEFLATE_MARKER) {
  int count = 0;
  uint32_t lead = 0;
  if (!read_count(in, count, error)) return false;
  if (!detail::read_le32(in, lead)) {
    error.text("texture preamble cut off in its header");
    return false;
  }
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (!read_texture_header(in, marker, r, error)) return false;
    uint8_t* rgb = arena.alloc_uninit<uint8_t>(detail::texel_bytes(r));
    if (rgb == nullptr) {
      error.text("texture ").text(r.name).text(" (").number(r.width).text("x").number(r.height).text(
          ") does not fit in the board's memory");
      return false;
    }
    detail::Limited stream{in, r.packed_size};
    if (!detail::decode(stream.source(), r, rgb, nullptr, arena, error)) return false;
    r.rgb = rgb;
    table.count = t + 1;
    table.sparse = table.sparse || r.tiles != nullptr;
  }
  return true;
}

// A preamble of any kind already in memory, `data` at its marker byte
// (the course and framed protocols and a checked raw upload hold it,
// protocol/text_scene_upload.hpp): plain texels are pointed at where they
// lie; compressed ones are decoded where they lie when the upload is the
// arena's top block (the lead's bytes below it are free), else into the
// arena, as are sparse ones. `used` is the preamble's length with its marker.
inline bool unpack(const uint8_t* data, size_t size, Arena& arena, Table& table, size_t& used, Diagnostic& error) {
  if (size == 0 || !is_marker(data[0])) {
    error.text("texture preamble: bad marker");
    return false;
  }
  const int marker = data[0];
  uint32_t lead = 0;
  if (!read_headers(data + 1, size - 1, marker, table, lead, used, error)) return false;
  used += 1;
  if (marker == MINRT_TEXTURES_MARKER) return true;
  size_t total = 0;
  for (int t = 0; t < table.count; ++t) total += detail::texel_bytes(table.items[t]);
  // The upload is the arena's top block when the lead's bytes taken from
  // the top end end just below it, or below the header that came ahead of
  // the preamble (a text-scene upload's 12 bytes, read before this): then
  // the texels start there, else in the bottom end. Sparse textures
  // outgrow their streams, so they always go to the bottom end.
  constexpr size_t kMaxHeaderAhead = 16;
  const size_t mark = arena.top_mark();
  uint8_t* below = marker == MINRT_TEXTURES_SPARSE_MARKER ? nullptr : arena.alloc_top<uint8_t>(lead);
  const bool in_place = below != nullptr && below + lead <= data &&
                        static_cast<size_t>(data - (below + lead)) <= kMaxHeaderAhead;
  uint8_t* out = below;
  if (!in_place) {
    arena.release_top(mark);
    out = arena.alloc_uninit<uint8_t>(total);
    if (out == nullptr) {
      error.text("the textures (").number(static_cast<int64_t>(total)).text(
          " bytes decoded) do not fit in the board's memory");
      return false;
    }
  }
  for (int t = 0; t < table.count; ++t) {
    Received& r = table.items[t];
    MemorySource stream{r.packed, r.packed_size};
    // The memory is the arena's; the upload is read-only only to its readers.
    if (!detail::decode(stream.source(), r, out, in_place ? r.packed : nullptr, arena, error)) return false;
    r.rgb = out;
    out += detail::texel_bytes(r);
    table.sparse = table.sparse || r.tiles != nullptr;
  }
  return true;
}

}  // namespace minrt::send::textures
