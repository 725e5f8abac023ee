// The board's reading of a CS418 or Jaworski scene upload (course and
// framed protocols, protocol/text_scene_upload.hpp) on arbitrary bytes: the
// framed header check, the texture preamble read in place (plain, or
// compressed and decoded into a small arena), and the course read into a
// small arena must never crash or point outside their input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <initializer_list>

#include <minrt/serial_protocol.h>

#include "protocol/text_scene_upload.hpp"
#include "protocol/texture_blobs.hpp"

namespace {

void check_textures(const uint8_t* data, size_t size) {
  using namespace minrt::send;
  static textures::Table table;
  table.count = 0;
  size_t used = 0;
  minrt::Diagnostic error;
  if (!textures::view(data, size, table, used, error)) {
    if (error.length == 0) std::abort();  // a refusal always says why
    return;
  }
  if (used > size || table.count < 1 || table.count > MINRT_MAX_TEXTURES) std::abort();
  for (int i = 0; i < table.count; ++i) {
    const textures::Received& r = table.items[i];
    const size_t bytes = static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
    if (r.rgb < data || r.rgb + bytes > data + used) std::abort();
    if (table.find(r.name) < 0) std::abort();
  }
}

// A compressed or sparse preamble at `data` (its marker byte first),
// decoded into a 64 KiB arena: every texture it accepts, and a sparse
// one's tile mask, lies inside the arena.
void check_packed(const uint8_t* data, size_t size) {
  using namespace minrt::send;
  static textures::Table table;
  table.count = 0;
  alignas(8) static uint8_t mem[65536];
  minrt::Arena arena(mem, sizeof mem);
  size_t used = 0;
  minrt::Diagnostic error;
  if (!textures::unpack(data, size, arena, table, used, error)) {
    if (error.length == 0) std::abort();
    return;
  }
  if (used > size || table.count < 1 || table.count > MINRT_MAX_TEXTURES) std::abort();
  for (int i = 0; i < table.count; ++i) {
    const textures::Received& r = table.items[i];
    const size_t bytes = static_cast<size_t>(r.width) * static_cast<size_t>(r.height) * 3;
    if (r.rgb < mem || r.rgb + bytes > mem + sizeof mem) std::abort();
    if (r.tiles != nullptr && (r.tiles < mem || r.tiles >= mem + sizeof mem || r.form < 1)) std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace minrt::send;
  // Framed: the bytes as the collected upload.
  text::TextScene scene;
  bool ok = false;
  minrt::Diagnostic error;
  if (text::view_framed(data, size, scene, ok, error) && ok) {
    if (scene.bytes + scene.size != data + size || !text::is_text_format(scene.format)) std::abort();
    if (scene.size > 0 && scene.bytes[0] == MINRT_TEXTURES_MARKER) check_textures(scene.bytes + 1, scene.size - 1);
    if (scene.size > 0 && scene.bytes[0] != MINRT_TEXTURES_MARKER && textures::is_marker(scene.bytes[0]))
      check_packed(scene.bytes, scene.size);
  }
  // The bytes as a texture preamble on their own, plain, compressed and sparse.
  if (size > 0) check_textures(data + 1, size - 1);
  if (size > 0 && data[0] != MINRT_TEXTURES_MARKER && textures::is_marker(data[0])) check_packed(data, size);
  // Course: the bytes after the marker word, into a 256-byte arena, both
  // byte orders.
  for (auto endian : {course::Endian::kLittle, course::Endian::kBig}) {
    alignas(8) static uint8_t mem[256];
    minrt::Arena arena(mem, sizeof mem);
    minrt::MemorySource in{data, size};
    bool too_large = false;
    minrt::Diagnostic e;
    if (text::read_course(in.source(), endian, arena, scene, too_large, e)) {
      if (scene.size > sizeof mem || (scene.size > 0 && (scene.bytes < mem || scene.bytes + scene.size > mem + sizeof mem)))
        std::abort();
    } else if (e.length == 0) {
      std::abort();
    }
  }
  return 0;
}
