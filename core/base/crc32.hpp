// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, init and final XOR
// 0xFFFFFFFF), as used by the framed protocol and PNG. Freestanding: no heap, no
// exceptions, no library headers beyond <stdint.h>/<stddef.h>, so the
// firmware can include it as is.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace minrt {

namespace crc32_detail {
struct Table {
  uint32_t v[256];
};
constexpr Table make_table() {
  Table t{};
  for (uint32_t i = 0; i < 256; ++i) {
    uint32_t c = i;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? (c >> 1) ^ 0xEDB88320u : (c >> 1);
    t.v[i] = c;
  }
  return t;
}
inline constexpr Table kTable = make_table();
}  // namespace crc32_detail

// Incremental form: state = crc32_begin(); state = crc32_update(state, ...);
// crc = crc32_end(state).
constexpr uint32_t crc32_begin() { return 0xFFFFFFFFu; }
constexpr uint32_t crc32_update(uint32_t state, const uint8_t* data, size_t size) {
  for (size_t i = 0; i < size; ++i)
    state = crc32_detail::kTable.v[(state ^ data[i]) & 0xFFu] ^ (state >> 8);
  return state;
}
constexpr uint32_t crc32_end(uint32_t state) { return state ^ 0xFFFFFFFFu; }

constexpr uint32_t crc32(const uint8_t* data, size_t size) {
  return crc32_end(crc32_update(crc32_begin(), data, size));
}

}  // namespace minrt
