#include <catch2/catch.hpp>

#include <cstring>

#include "core/base/crc32.hpp"

using minrt::crc32;

namespace {
uint32_t crc_of(const char* s) { return crc32(reinterpret_cast<const uint8_t*>(s), std::strlen(s)); }
}  // namespace

TEST_CASE("CRC-32 matches the IEEE check values", "[crc32]") {
  CHECK(crc_of("") == 0x00000000u);
  CHECK(crc_of("a") == 0xE8B7BE43u);
  CHECK(crc_of("123456789") == 0xCBF43926u);
  CHECK(crc_of("The quick brown fox jumps over the lazy dog") == 0x414FA339u);
  const uint8_t zeros[32] = {};
  CHECK(crc32(zeros, sizeof zeros) == 0x190A55ADu);
}

TEST_CASE("CRC-32 in pieces equals CRC-32 at once", "[crc32]") {
  const char* s = "The quick brown fox jumps over the lazy dog";
  const auto* p = reinterpret_cast<const uint8_t*>(s);
  const size_t n = std::strlen(s);
  for (size_t cut = 0; cut <= n; ++cut) {
    uint32_t st = minrt::crc32_begin();
    st = minrt::crc32_update(st, p, cut);
    st = minrt::crc32_update(st, p + cut, n - cut);
    CHECK(minrt::crc32_end(st) == 0x414FA339u);
  }
}

TEST_CASE("CRC-32 is usable at compile time", "[crc32]") {
  constexpr uint8_t data[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  static_assert(crc32(data, sizeof data) == 0xCBF43926u);
}
