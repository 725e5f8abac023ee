// The board's inflater (core/base/inflate.hpp) on arbitrary bytes: into a
// buffer of exactly its capacity (ASan sees any write past it), and in
// place with the stream above its output, where a finished decode must
// give the same bytes as the plain one and never read past its input.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/base/inflate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const size_t capacity = (static_cast<size_t>(data[0]) | static_cast<size_t>(data[1]) << 8) * 4;
  const uint8_t* stream = data + 2;
  const size_t n = size - 2;

  std::vector<uint8_t> plain(capacity);
  minrt::MemorySource src{stream, n};
  minrt::Inflater inf;
  const minrt::InflateStatus s = inf.run(src.source(), plain.data(), capacity);
  if (inf.produced() > capacity || inf.consumed() > n || src.pos > n) std::abort();
  if (s == minrt::InflateStatus::kOverrun) std::abort();  // only in place

  // In place: the stream `gap` bytes above the output's start.
  const size_t gap = capacity / 2;
  std::vector<uint8_t> mem(gap + n);
  if (n > 0) std::memcpy(mem.data() + gap, stream, n);
  const size_t room = capacity < mem.size() ? capacity : mem.size();
  minrt::MemorySource held{mem.data() + gap, n};
  minrt::Inflater placed;
  const minrt::InflateStatus t = placed.run(held.source(), mem.data(), room, mem.data() + gap);
  if (placed.produced() > room || placed.consumed() > n) std::abort();
  if (t == minrt::InflateStatus::kDone && s == minrt::InflateStatus::kDone && room == capacity) {
    if (placed.produced() != inf.produced()) std::abort();
    if (inf.produced() > 0 && std::memcmp(mem.data(), plain.data(), inf.produced()) != 0) std::abort();
  }
  return 0;
}
