// The board side of the texture preamble a CS418 scene's textures travel in
// ahead of its text (include/minrt/serial_protocol.h): the texels go straight
// into the arena, and the scene reader later finds them by name.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <minrt/serial_protocol.h>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"

namespace minrt::send::textures {

struct Received {
  char name[256];
  int32_t width;
  int32_t height;
  const uint8_t* rgb;  // in the arena
};

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

// Reads the preamble after its marker byte (`in` must pass every byte value
// through). False with the reason: a cut-off preamble, a bad size, or a
// texture that does not fit in the arena.
inline bool receive(ByteSource in, Arena& arena, Table& table, Diagnostic& error) {
  auto byte = [&](int& v) {
    v = in.get();
    return v >= 0;
  };
  int count = 0;
  if (!byte(count) || count < 1 || count > MINRT_MAX_TEXTURES) {
    error.text("texture preamble: bad texture count");
    return false;
  }
  for (int t = 0; t < count; ++t) {
    Received& r = table.items[t];
    int len = 0;
    if (!byte(len) || len < 1) {
      error.text("texture preamble: bad name length");
      return false;
    }
    for (int k = 0; k < len; ++k) {
      int c = 0;
      if (!byte(c)) {
        error.text("texture preamble cut off in a name");
        return false;
      }
      r.name[k] = static_cast<char>(c);
    }
    r.name[len] = 0;
    int b[4];
    for (int& v : b)
      if (!byte(v)) {
        error.text("texture preamble cut off in the size of ").text(r.name);
        return false;
      }
    r.width = b[0] | b[1] << 8;
    r.height = b[2] | b[3] << 8;
    if (r.width < 1 || r.height < 1 || r.width > MINRT_MAX_TEXTURE_SIDE || r.height > MINRT_MAX_TEXTURE_SIDE) {
      error.text("texture ").text(r.name).text(": bad size");
      return false;
    }
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

}  // namespace minrt::send::textures
