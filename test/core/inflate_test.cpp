// The board's inflater (core/base/inflate.hpp) against zlib's deflate and
// hand-made streams: each block type, corrupt and cut-short input, output
// overflow, and decoding in place.
#include <catch2/catch.hpp>

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/base/inflate.hpp"

using minrt::Inflater;
using minrt::InflateStatus;
using Bytes = std::vector<std::uint8_t>;

namespace {

// A raw deflate stream of `data` by zlib.
Bytes deflate_raw(const Bytes& data, int level, int strategy = Z_DEFAULT_STRATEGY) {
  z_stream z{};
  REQUIRE(deflateInit2(&z, level, Z_DEFLATED, -15, 9, strategy) == Z_OK);
  Bytes out(deflateBound(&z, data.size()) + 16);
  z.next_in = const_cast<Bytef*>(data.data());
  z.avail_in = static_cast<uInt>(data.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  REQUIRE(deflate(&z, Z_FINISH) == Z_STREAM_END);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

struct Decoded {
  InflateStatus status;
  Bytes out;
  std::size_t consumed;
};

Decoded inflate(const Bytes& stream, std::size_t capacity) {
  minrt::MemorySource src{stream.data(), stream.size()};
  Decoded d{InflateStatus::kDone, Bytes(capacity), 0};
  Inflater inf;
  d.status = inf.run(src.source(), d.out.data(), capacity);
  d.out.resize(inf.produced());
  d.consumed = inf.consumed();
  return d;
}

// Text-like bytes with repeats near and far (up to the 32 KiB window) and
// some noise, so zlib uses literals, short and long matches.
Bytes sample(std::size_t n, std::uint32_t seed) {
  Bytes b;
  std::uint32_t x = seed;
  auto next = [&] { return x = x * 1664525u + 1013904223u; };
  while (b.size() < n) {
    const std::uint32_t r = next() >> 24;
    if (r < 60 && b.size() > 300) {  // copy from back to 32768 bytes ago
      const std::size_t dist = 1 + (next() >> 8) % std::min<std::size_t>(b.size(), 32768);
      const std::size_t len = 3 + (next() >> 8) % 300;
      for (std::size_t i = 0; i < len && b.size() < n; ++i) b.push_back(b[b.size() - dist]);
    } else {
      b.push_back(static_cast<std::uint8_t>('a' + r % 23));
    }
  }
  return b;
}

int first_block_type(const Bytes& stream) { return (stream[0] >> 1) & 3; }

// Bits least significant first, as deflate packs them; Huffman codes go
// most significant bit first.
struct BitWriter {
  Bytes bytes;
  int used = 8;
  void bits(std::uint32_t v, int n) {
    for (int i = 0; i < n; ++i) {
      if (used == 8) {
        bytes.push_back(0);
        used = 0;
      }
      bytes.back() |= static_cast<std::uint8_t>(((v >> i) & 1u) << used++);
    }
  }
  void code(std::uint32_t c, int n) {
    for (int i = n - 1; i >= 0; --i) bits((c >> i) & 1u, 1);
  }
};

}  // namespace

TEST_CASE("inflate: a stored block by hand and zlib's stored blocks over 64 KiB", "[core][inflate]") {
  const Bytes hand = {0x01, 0x05, 0x00, 0xFA, 0xFF, 'h', 'e', 'l', 'l', 'o'};
  const Decoded d = inflate(hand, 5);
  CHECK(d.status == InflateStatus::kDone);
  CHECK(std::string(d.out.begin(), d.out.end()) == "hello");
  CHECK(d.consumed == hand.size());

  const Bytes data = sample(150000, 7);
  const Bytes stream = deflate_raw(data, 0);
  REQUIRE(first_block_type(stream) == 0);
  const Decoded z = inflate(stream, data.size());
  CHECK(z.status == InflateStatus::kDone);
  CHECK(z.out == data);
  CHECK(z.consumed == stream.size());
}

TEST_CASE("inflate: fixed-code blocks by hand and by zlib", "[core][inflate]") {
  // 'a', then a match of length 4 at distance 1, then end of block: "aaaaa".
  BitWriter w;
  w.bits(1, 1);              // final block
  w.bits(1, 2);              // fixed codes
  w.code(0x30 + 'a', 8);     // literals 0..143: 8 bits from 00110000
  w.code(258 - 256, 7);      // length code 258 = length 4: 7 bits
  w.code(0, 5);              // distance code 0 = distance 1
  w.code(0, 7);              // end of block
  const Decoded d = inflate(w.bytes, 5);
  CHECK(d.status == InflateStatus::kDone);
  CHECK(std::string(d.out.begin(), d.out.end()) == "aaaaa");

  const Bytes data = sample(40000, 11);
  const Bytes stream = deflate_raw(data, 6, Z_FIXED);
  REQUIRE(first_block_type(stream) == 1);
  const Decoded z = inflate(stream, data.size());
  CHECK(z.status == InflateStatus::kDone);
  CHECK(z.out == data);
}

TEST_CASE("inflate: dynamic-code blocks from zlib at every level, many blocks", "[core][inflate]") {
  const Bytes data = sample(400000, 3);
  for (int level = 1; level <= 9; ++level) {
    INFO("level " << level);
    const Bytes stream = deflate_raw(data, level);
    if (level == 9) REQUIRE(first_block_type(stream) == 2);
    const Decoded z = inflate(stream, data.size());
    CHECK(z.status == InflateStatus::kDone);
    CHECK(z.out == data);
    CHECK(z.consumed == stream.size());
  }
  // Bytes of every value, incompressible: zlib mixes in whatever is smallest.
  Bytes noise(70000);
  std::uint32_t x = 5;
  for (auto& b : noise) b = static_cast<std::uint8_t>((x = x * 1103515245u + 12345u) >> 23);
  const Decoded n = inflate(deflate_raw(noise, 9), noise.size());
  CHECK(n.status == InflateStatus::kDone);
  CHECK(n.out == noise);
}

TEST_CASE("inflate: corrupt streams are refused", "[core][inflate]") {
  // Stored block whose NLEN is not LEN's complement.
  CHECK(inflate({0x01, 0x05, 0x00, 0xFA, 0xFE, 'h', 'e', 'l', 'l', 'o'}, 5).status == InflateStatus::kCorrupt);
  // Block type 3.
  CHECK(inflate({0x07, 0x00}, 5).status == InflateStatus::kCorrupt);
  {  // A match before any output: distance beyond the start.
    BitWriter w;
    w.bits(1, 1);
    w.bits(1, 2);
    w.code(1, 7);  // length 3
    w.code(0, 5);  // distance 1
    w.code(0, 7);
    CHECK(inflate(w.bytes, 10).status == InflateStatus::kCorrupt);
  }
  {  // Fixed length codes 286 and distance code 30 do not exist.
    BitWriter w;
    w.bits(1, 1);
    w.bits(1, 2);
    w.code(0xC0 + (286 - 280), 8);
    CHECK(inflate(w.bytes, 10).status == InflateStatus::kCorrupt);
    BitWriter v;
    v.bits(1, 1);
    v.bits(1, 2);
    v.code(0x30 + 'x', 8);
    v.code(1, 7);
    v.code(30, 5);
    CHECK(inflate(v.bytes, 10).status == InflateStatus::kCorrupt);
  }
  {  // Dynamic header: more than 286 literal/length codes.
    BitWriter w;
    w.bits(1, 1);
    w.bits(2, 2);
    w.bits(30, 5);  // HLIT: 287
    w.bits(0, 5);
    w.bits(0, 4);
    w.bits(0, 32);
    CHECK(inflate(w.bytes, 10).status == InflateStatus::kCorrupt);
  }
  {  // Dynamic header: an over-subscribed code-length code (three 1-bit codes).
    BitWriter w;
    w.bits(1, 1);
    w.bits(2, 2);
    w.bits(0, 5);
    w.bits(0, 5);
    w.bits(0, 4);  // four code-length lengths: for 16, 17, 18, 0
    for (int i = 0; i < 3; ++i) w.bits(1, 3);
    w.bits(0, 3);
    w.bits(0, 32);
    CHECK(inflate(w.bytes, 10).status == InflateStatus::kCorrupt);
  }
  {  // Dynamic header: a repeat (16) with no length before it.
    BitWriter w;
    w.bits(1, 1);
    w.bits(2, 2);
    w.bits(0, 5);
    w.bits(0, 5);
    w.bits(0, 4);
    w.bits(1, 3);  // 16: 1 bit
    w.bits(1, 3);  // 17: 1 bit
    w.bits(0, 3);
    w.bits(0, 3);
    w.code(0, 1);  // 16 first
    w.bits(0, 32);
    CHECK(inflate(w.bytes, 10).status == InflateStatus::kCorrupt);
  }
  // Every single-byte change of a valid stream ends with some status, within
  // the buffer, never past the input (what the fuzz target checks at large);
  // only a change in the last byte's padding bits may go unnoticed.
  const Bytes data = sample(3000, 9);
  const Bytes stream = deflate_raw(data, 9);
  int refused = 0;
  for (std::size_t i = 0; i < stream.size(); ++i) {
    Bytes bad = stream;
    bad[i] ^= 0x5A;
    const Decoded d = inflate(bad, data.size());
    CHECK(d.out.size() <= data.size());
    CHECK(d.consumed <= bad.size());
    if (d.status != InflateStatus::kDone || d.out != data) ++refused;
  }
  CHECK(refused >= static_cast<int>(stream.size()) - 1);
}

TEST_CASE("inflate: output beyond the buffer is an overflow, not a write", "[core][inflate]") {
  const Bytes data = sample(20000, 5);
  for (int level : {0, 9}) {
    const Bytes stream = deflate_raw(data, level);
    Bytes buf(data.size() + 64, 0xEE);
    minrt::MemorySource src{stream.data(), stream.size()};
    Inflater inf;
    CHECK(inf.run(src.source(), buf.data(), data.size() - 1) == InflateStatus::kOverflow);
    CHECK(inf.produced() <= data.size() - 1);
    for (std::size_t i = data.size() - 1; i < buf.size(); ++i) CHECK(buf[i] == 0xEE);
  }
  // A match that would cross the end.
  BitWriter w;
  w.bits(1, 1);
  w.bits(1, 2);
  w.code(0x30 + 'a', 8);
  w.code(9, 7);  // length code 265: 11 and one extra bit
  w.bits(1, 1);  // 12
  w.code(0, 5);
  w.code(0, 7);
  CHECK(inflate(w.bytes, 8).status == InflateStatus::kOverflow);
}

TEST_CASE("inflate: every cut-short stream says so", "[core][inflate]") {
  const Bytes data = sample(5000, 2);
  for (int level : {0, 9}) {
    const Bytes stream = deflate_raw(data, level);
    for (std::size_t n = 0; n < stream.size(); ++n) {
      const Bytes cut(stream.begin(), stream.begin() + static_cast<std::ptrdiff_t>(n));
      INFO("level " << level << ", " << n << " of " << stream.size() << " bytes");
      CHECK(inflate(cut, data.size()).status == InflateStatus::kCut);
    }
  }
  CHECK(inflate({0x02}, 4).status == InflateStatus::kCut);  // a fixed block's first bits, then nothing
}

TEST_CASE("inflate: in place, the stream above its output, needs exactly the lead", "[core][inflate]") {
  // Compressible first, then noise: the output runs ahead of the input in
  // the middle, so the lead is larger than output minus input.
  Bytes data(60000, 'q');
  std::uint32_t x = 1;
  for (std::size_t i = 30000; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>((x = x * 69069u + 1u) >> 24);
  const Bytes stream = deflate_raw(data, 9);
  const Decoded plain = inflate(stream, data.size());
  REQUIRE(plain.status == InflateStatus::kDone);
  minrt::MemorySource measure{stream.data(), stream.size()};
  Inflater probe;
  Bytes scratch(data.size());
  REQUIRE(probe.run(measure.source(), scratch.data(), scratch.size()) == InflateStatus::kDone);
  const long long lead = probe.lead();
  CHECK(lead > static_cast<long long>(data.size()) - static_cast<long long>(stream.size()));
  for (long long gap : {lead, lead - 1}) {
    Bytes mem(static_cast<std::size_t>(gap) + stream.size());
    std::copy(stream.begin(), stream.end(), mem.begin() + gap);
    minrt::MemorySource src{mem.data() + gap, stream.size()};
    Inflater inf;
    const InflateStatus s = inf.run(src.source(), mem.data(), data.size(), mem.data() + gap);
    INFO("gap " << gap << " lead " << lead);
    if (gap == lead) {
      CHECK(s == InflateStatus::kDone);
      CHECK(Bytes(mem.begin(), mem.begin() + static_cast<std::ptrdiff_t>(data.size())) == data);
    } else {
      CHECK(s == InflateStatus::kOverrun);
    }
  }
}
