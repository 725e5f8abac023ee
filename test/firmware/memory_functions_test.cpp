// runtime/memory_functions.cpp built for the host under other names (see
// CMakeLists.txt), against byte-by-byte reference loops for every small size
// and alignment, including overlapping moves both ways.
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" {
void* fw_memset(void* dest, int value, size_t n);
void* fw_memcpy(void* dest, const void* src, size_t n);
void* fw_memmove(void* dest, const void* src, size_t n);
int fw_memcmp(const void* a, const void* b, size_t n);
}

namespace {

constexpr size_t kBuffer = 96;

std::vector<uint8_t> pattern() {
  std::vector<uint8_t> v(kBuffer);
  for (size_t i = 0; i < kBuffer; ++i) v[i] = static_cast<uint8_t>(i * 37 + 11);
  return v;
}

}  // namespace

TEST_CASE("firmware memset", "[firmware]") {
  for (size_t offset = 0; offset < 4; ++offset) {
    for (size_t n = 0; n <= 40; ++n) {
      std::vector<uint8_t> got = pattern();
      std::vector<uint8_t> want = pattern();
      for (size_t i = 0; i < n; ++i) want[offset + i] = 0xa5;
      CHECK(fw_memset(got.data() + offset, 0x1a5, n) == got.data() + offset);
      CHECK(got == want);
    }
  }
}

TEST_CASE("firmware memcpy and memmove, every alignment and overlap", "[firmware]") {
  for (size_t from = 0; from < 12; ++from) {
    for (size_t to = 0; to < 12; ++to) {
      for (size_t n = 0; n <= 40; ++n) {
        INFO("from " << from << " to " << to << " n " << n);
        std::vector<uint8_t> want = pattern();
        const std::vector<uint8_t> original = pattern();
        for (size_t i = 0; i < n; ++i) want[to + i] = original[from + i];

        std::vector<uint8_t> moved = pattern();
        CHECK(fw_memmove(moved.data() + to, moved.data() + from, n) == moved.data() + to);
        CHECK(moved == want);

        // memcpy: disjoint buffers only.
        std::vector<uint8_t> copied = pattern();
        const std::vector<uint8_t> source = pattern();
        CHECK(fw_memcpy(copied.data() + to, source.data() + from, n) == copied.data() + to);
        CHECK(copied == want);
      }
    }
  }
}

TEST_CASE("firmware memcmp", "[firmware]") {
  const uint8_t a[] = {1, 2, 3, 200};
  const uint8_t b[] = {1, 2, 4, 100};
  CHECK(fw_memcmp(a, b, 0) == 0);
  CHECK(fw_memcmp(a, b, 2) == 0);
  CHECK(fw_memcmp(a, b, 3) < 0);
  CHECK(fw_memcmp(b, a, 3) > 0);
  CHECK(fw_memcmp(a + 3, b + 3, 1) > 0);  // unsigned bytes
}
