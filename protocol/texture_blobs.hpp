// The board side of the texture preamble a scene's textures travel in ahead
// of its text (include/minrt/serial_protocol.h), plain or compressed: the
// texels go straight into the arena, and the scene reader later finds them
// by name.
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
};

inline bool is_marker(int c) { return c == MINRT_TEXTURES_MARKER || c == MINRT_TEXTURES_DEFLATE_MARKER; }

struct Table {
  Received items[MINRT_MAX_TEXTURES];
  int count = 0;

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

// The texture count that starts either preamble.
inline bool read_count(ByteSource& in, int& count, Diagnostic& error) {
  count = in.get();
  if (count < 1 || count > MINRT_MAX_TEXTURES) {
    error.text("texture preamble: bad texture count");
    return false;
  }
  return true;
}

// A texture's name (length byte, bytes) and size (two 16-bit little-endian
// words), the head both preambles give each texture.
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
  int b[4];
  for (int& v : b)
    if ((v = in.get()) < 0) {
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

// Reads the preamble after its marker byte (`in` must pass every byte value
// through). False with the reason: a cut-off preamble, a bad size, or a
// texture that does not fit in the arena.
inline bool receive(ByteSource in, Arena& arena, Table& table, Diagnostic& error) {
  auto byte = [&](int& v) {
    v = in.get();
    return v >= 0;
  };
  int count = 0;
  if (!read_count(in, count, error)) return false;
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (!read_name_and_size(in, r, error)) return false;
    const size_t bytes = static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
    uint8_t* rgb = arena.alloc_zeroed<uint8_t>(bytes);
    if (rgb == nullptr) {
      error.text("texture ").text(r.name).text(" (").number(r.width).text("x").number(r.height).text(
          ") does not fit in the board's memory");
      return false;
    }
    for (size_t i = 0; i < bytes; ++i) {
      int c = 0;
      if (!byte(c)) {
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

// The same preamble already in memory (course and framed protocols: the
// scene upload holds it, protocol/text_scene_upload.hpp): the table points
// into `data`, nothing is copied. `data` starts after the marker byte;
// `used` is the preamble's length from there.
inline bool view(const uint8_t* data, size_t size, Table& table, size_t& used, Diagnostic& error) {
  size_t at = 0;
  auto cut = [&](size_t need) { return need > size - at; };
  if (cut(1) || data[0] < 1 || data[0] > MINRT_MAX_TEXTURES) {
    error.text("texture preamble: bad texture count");
    return false;
  }
  const int count = data[at++];
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (cut(1) || data[at] < 1) {
      error.text("texture preamble: bad name length");
      return false;
    }
    const size_t len = data[at++];
    if (cut(len)) {
      error.text("texture preamble cut off in a name");
      return false;
    }
    for (size_t k = 0; k < len; ++k) r.name[k] = static_cast<char>(data[at + k]);
    r.name[len] = 0;
    at += len;
    if (cut(4)) {
      error.text("texture preamble cut off in the size of ").text(r.name);
      return false;
    }
    r.width = data[at] | data[at + 1] << 8;
    r.height = data[at + 2] | data[at + 3] << 8;
    at += 4;
    if (r.width < 1 || r.height < 1 || r.width > MINRT_MAX_TEXTURE_SIDE || r.height > MINRT_MAX_TEXTURE_SIDE) {
      error.text("texture ").text(r.name).text(": bad size");
      return false;
    }
    const size_t bytes = static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
    if (cut(bytes)) {
      error.text("texture ").text(r.name).text(" cut off after ").number(static_cast<int64_t>(size - at)).text(" bytes");
      return false;
    }
    r.rgb = data + at;
    at += bytes;
    table.count = t + 1;
  }
  used = at;
  return true;
}

namespace detail {

inline uint32_t le32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | static_cast<uint32_t>(p[1]) << 8 | static_cast<uint32_t>(p[2]) << 16 |
         static_cast<uint32_t>(p[3]) << 24;
}

inline size_t texel_bytes(const Received& r) {
  return static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
}

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
// lies in the same memory above `out`.
inline bool decode(ByteSource stream, const Received& r, uint8_t* out, const uint8_t* in_place, Arena& arena,
                   Diagnostic& error) {
  const size_t bytes = texel_bytes(r);
  const size_t mark = arena.top_mark();
  Inflater* inflater = arena.alloc_top<Inflater>(1);
  uint8_t* scratch = arena.alloc_top<uint8_t>(static_cast<size_t>(r.width) * 3);
  if (inflater == nullptr || scratch == nullptr) {
    arena.release_top(mark);
    error.text("texture ").text(r.name).text(": no room to decode it");
    return false;
  }
  const InflateStatus s = inflater->run(stream, out, bytes, in_place);
  const bool whole = s == InflateStatus::kDone && inflater->produced() == bytes && inflater->consumed() == r.packed_size;
  if (whole) texel_filter::unfilter(out, static_cast<size_t>(r.width), static_cast<size_t>(r.height), scratch);
  arena.release_top(mark);
  if (!whole) {
    error.text("texture ").text(r.name).text(": ");
    if (s != InflateStatus::kDone) error.text(inflate_message(s));
    else if (inflater->produced() != bytes)
      error.text("compressed data decodes to ").number(static_cast<int64_t>(inflater->produced())).text(" of ").number(
          static_cast<int64_t>(bytes)).text(" bytes");
    else error.text("compressed data ends before its stated size");
    return false;
  }
  if (crc32(out, bytes) != r.crc) {
    error.text("texture ").text(r.name).text(": texels damaged (CRC-32 mismatch)");
    return false;
  }
  return true;
}

}  // namespace detail

// Reads a compressed preamble after its marker byte from the line, each
// texture inflated into the arena as its bytes arrive (nothing is held).
inline bool receive_compressed(ByteSource in, Arena& arena, Table& table, Diagnostic& error) {
  auto byte = [&](int& v) {
    v = in.get();
    return v >= 0;
  };
  auto word = [&](uint32_t& v) {
    uint8_t b[4];
    for (uint8_t& x : b) {
      int c = 0;
      if (!byte(c)) return false;
      x = static_cast<uint8_t>(c);
    }
    v = detail::le32(b);
    return true;
  };
  int count = 0;
  uint32_t lead = 0;
  if (!read_count(in, count, error)) return false;
  if (!word(lead)) {
    error.text("texture preamble cut off in its header");
    return false;
  }
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (!read_name_and_size(in, r, error)) return false;
    if (!word(r.packed_size) || !word(r.crc)) {
      error.text("texture preamble cut off in the header of ").text(r.name);
      return false;
    }
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
  }
  return true;
}

// A preamble of either kind already in memory, `data` at its marker byte
// (the course and framed protocols and a checked raw upload hold it,
// protocol/text_scene_upload.hpp): plain texels are pointed at where they
// lie; compressed ones are decoded where they lie when the upload is the
// arena's top block (the lead's bytes below it are free), else into the
// arena. `used` is the preamble's length with its marker.
inline bool unpack(const uint8_t* data, size_t size, Arena& arena, Table& table, size_t& used, Diagnostic& error) {
  if (size == 0 || !is_marker(data[0])) {
    error.text("texture preamble: bad marker");
    return false;
  }
  if (data[0] == MINRT_TEXTURES_MARKER) {
    if (!view(data + 1, size - 1, table, used, error)) return false;
    used += 1;
    return true;
  }
  size_t at = 1;
  auto cut = [&](size_t need) { return need > size - at; };
  if (cut(5) || data[at] < 1 || data[at] > MINRT_MAX_TEXTURES) {
    error.text("texture preamble: bad texture count");
    return false;
  }
  const int count = data[at];
  const uint32_t lead = detail::le32(data + at + 1);
  at += 5;
  size_t total = 0;
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    if (cut(1) || data[at] < 1) {
      error.text("texture preamble: bad name length");
      return false;
    }
    const size_t len = data[at++];
    if (cut(len)) {
      error.text("texture preamble cut off in a name");
      return false;
    }
    for (size_t k = 0; k < len; ++k) r.name[k] = static_cast<char>(data[at + k]);
    r.name[len] = 0;
    at += len;
    if (cut(12)) {
      error.text("texture preamble cut off in the header of ").text(r.name);
      return false;
    }
    r.width = data[at] | data[at + 1] << 8;
    r.height = data[at + 2] | data[at + 3] << 8;
    r.packed_size = detail::le32(data + at + 4);
    r.crc = detail::le32(data + at + 8);
    at += 12;
    if (r.width < 1 || r.height < 1 || r.width > MINRT_MAX_TEXTURE_SIDE || r.height > MINRT_MAX_TEXTURE_SIDE) {
      error.text("texture ").text(r.name).text(": bad size");
      return false;
    }
    if (cut(r.packed_size)) {
      error.text("texture ").text(r.name).text(" cut off after ").number(static_cast<int64_t>(size - at)).text(" bytes");
      return false;
    }
    r.packed = data + at;
    at += r.packed_size;
    total += detail::texel_bytes(r);
  }
  used = at;
  // The upload is the arena's top block when the lead's bytes taken from
  // the top end end just below it, or below the header that came ahead of
  // the preamble (a text-scene upload's 12 bytes, read before this): then
  // the texels start there, else in the bottom end.
  constexpr size_t kMaxHeaderAhead = 16;
  const size_t mark = arena.top_mark();
  uint8_t* below = arena.alloc_top<uint8_t>(lead);
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
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    MemorySource stream{r.packed, r.packed_size};
    // The memory is the arena's; the upload is read-only only to its readers.
    if (!detail::decode(stream.source(), r, out, in_place ? r.packed : nullptr, arena, error)) return false;
    r.rgb = out;
    out += detail::texel_bytes(r);
    table.count = t + 1;
  }
  return true;
}

}  // namespace minrt::send::textures
