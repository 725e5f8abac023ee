// A streaming 8-bit RGBA PNG writer that needs no compressor and no image
// buffer: each row goes out as soon as it arrives, as stored (uncompressed)
// deflate blocks in its own IDAT chunk, so every chunk's length is known
// before its data. CRC-32 per chunk, Adler-32 over the raw rows at the end.
// The board streams this; the host writes compressed PNG through zlib, with
// the same decoded pixels.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"

namespace minrt {

class PngStoredWriter {
 public:
  explicit PngStoredWriter(ByteSink out) : out_(out) {}

  void begin(int width, int height) {
    width_ = width;
    static constexpr uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    out_.put(kSignature, sizeof kSignature);
    uint8_t ihdr[13];
    put_be32(ihdr, static_cast<uint32_t>(width));
    put_be32(ihdr + 4, static_cast<uint32_t>(height));
    ihdr[8] = 8;   // bits per channel
    ihdr[9] = 6;   // colour type: RGBA
    ihdr[10] = 0;  // deflate
    ihdr[11] = 0;  // adaptive filtering (every row uses filter 0)
    ihdr[12] = 0;  // not interlaced
    chunk_begin("IHDR", sizeof ihdr);
    chunk_data(ihdr, sizeof ihdr);
    chunk_end();
    first_row_ = true;
    adler_a_ = 1;
    adler_b_ = 0;
  }

  void row(int /*y*/, const uint8_t* rgba) {
    const size_t raw = 1 + 4 * static_cast<size_t>(width_);  // filter byte + pixels
    const size_t blocks = (raw + kMaxStored - 1) / kMaxStored;
    const size_t length = (first_row_ ? 2 : 0) + raw + 5 * blocks;
    chunk_begin("IDAT", length);
    if (first_row_) {
      static constexpr uint8_t kZlibHeader[2] = {0x78, 0x01};  // deflate, 32K window, no dict
      chunk_data(kZlibHeader, 2);
      first_row_ = false;
    }
    // The filter byte travels with the first block's data.
    const uint8_t filter = 0;
    size_t done = 0;  // bytes of the raw row written, filter byte included
    for (size_t b = 0; b < blocks; ++b) {
      const size_t n = raw - done < kMaxStored ? raw - done : kMaxStored;
      block_header(n, false);
      size_t take = n;
      if (done == 0) {
        raw_data(&filter, 1);
        --take;
        raw_data(rgba, take);
      } else {
        raw_data(rgba + (done - 1), take);
      }
      done += n;
    }
    chunk_end();
  }

  void end() {
    chunk_begin("IDAT", 5 + 4);
    block_header(0, true);  // an empty final stored block closes the stream
    uint8_t adler[4];
    put_be32(adler, (adler_b_ << 16) | adler_a_);
    chunk_data(adler, 4);
    chunk_end();
    chunk_begin("IEND", 0);
    chunk_end();
  }

 private:
  static constexpr size_t kMaxStored = 65535;
  static constexpr uint32_t kAdlerMod = 65521;

  static void put_be32(uint8_t* p, uint32_t v) {
    p[0] = static_cast<uint8_t>(v >> 24);
    p[1] = static_cast<uint8_t>(v >> 16);
    p[2] = static_cast<uint8_t>(v >> 8);
    p[3] = static_cast<uint8_t>(v);
  }

  void chunk_begin(const char* type, size_t length) {
    uint8_t head[8];
    put_be32(head, static_cast<uint32_t>(length));
    for (int i = 0; i < 4; ++i) head[4 + i] = static_cast<uint8_t>(type[i]);
    out_.put(head, 8);
    crc_ = crc32_update(crc32_begin(), head + 4, 4);
  }
  void chunk_data(const uint8_t* p, size_t n) {
    out_.put(p, n);
    crc_ = crc32_update(crc_, p, n);
  }
  void chunk_end() {
    uint8_t c[4];
    put_be32(c, crc32_end(crc_));
    out_.put(c, 4);
  }
  void block_header(size_t n, bool final) {
    const uint8_t h[5] = {static_cast<uint8_t>(final ? 1 : 0), static_cast<uint8_t>(n),
                          static_cast<uint8_t>(n >> 8), static_cast<uint8_t>(~n),
                          static_cast<uint8_t>(~n >> 8)};
    chunk_data(h, 5);
  }
  // Row bytes: into the chunk and the Adler-32 of the zlib stream. The sums
  // are reduced every 5552 bytes, the most that cannot overflow 32 bits.
  void raw_data(const uint8_t* p, size_t n) {
    chunk_data(p, n);
    while (n > 0) {
      size_t k = n < 5552 ? n : 5552;
      n -= k;
      while (k-- > 0) {
        adler_a_ += *p++;
        adler_b_ += adler_a_;
      }
      adler_a_ %= kAdlerMod;
      adler_b_ %= kAdlerMod;
    }
  }

  ByteSink out_;
  int width_ = 0;
  bool first_row_ = true;
  uint32_t crc_ = 0;
  uint32_t adler_a_ = 1;
  uint32_t adler_b_ = 0;
};

}  // namespace minrt
