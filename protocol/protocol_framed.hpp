// Framed protocol, shared by the host and the board. Freestanding: no heap,
// no exceptions, only <stdint.h>/<stddef.h> and the core's ByteSink, so the
// firmware can include it as is.
//
// Frame: A5 5A | type | seq (u16 LE) | len (u16 LE) | check | payload | CRC-32
// (LE) of type..payload. `check` = type^seq0^seq1^len0^len1^0x55 rejects a
// damaged header before its length is trusted. 12 bytes of overhead, 0.78%
// on a 512-pixel row.
//
// Conversation:
//   host  S(seq=i, 1024-byte chunks of the SLD text)... E(u32 size, u32 crc)
//   board K (scene complete) | N (damaged: host starts over) | X(message)
//   board H(u16 width, u16 height), then D(seq=row, 3*width RGB bytes) per
//         row as it is rendered, then Z(u16 height); for CS418 and Jaworski
//         scenes (protocol/text_scene_upload.hpp) 4*width RGBA bytes, rows
//         numbered in the order rendered, which the host hands to the
//         format's writer (PNG, BMP) in that order
//   host  Q(list of u16 row numbers, 0xFFFF = the header) for rows it lacks
//         or got damaged; the board re-sends them and Z again
//   host  F when it has everything; the board halts.
// Rows carry binary RGB whatever the --format; the host writes P3 or P6.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "core/base/byte_io.hpp"
#include "core/base/crc32.hpp"

namespace minrt::send::framed {

inline constexpr uint8_t kSync0 = 0xA5;
inline constexpr uint8_t kSync1 = 0x5A;
inline constexpr size_t kHeadSize = 8;
inline constexpr size_t kOverhead = kHeadSize + 4;
inline constexpr size_t kSceneChunk = 1024;
inline constexpr uint16_t kHeaderIndex = 0xFFFF;

enum Type : uint8_t {
  kScene = 'S',
  kSceneEnd = 'E',
  kAck = 'K',
  kNak = 'N',
  kHeader = 'H',
  kRow = 'D',
  kEnd = 'Z',
  kRequest = 'Q',
  kFinished = 'F',
  kError = 'X',
};

inline void put_u16(uint8_t* p, uint16_t v) {
  p[0] = static_cast<uint8_t>(v);
  p[1] = static_cast<uint8_t>(v >> 8);
}
inline void put_u32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}
inline uint16_t get_u16(const uint8_t* p) { return static_cast<uint16_t>(p[0] | (p[1] << 8)); }
inline uint32_t get_u32(const uint8_t* p) {
  return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
         (static_cast<uint32_t>(p[3]) << 24);
}

// Sends one frame through `sink` in three pieces (no frame buffer needed).
inline void write_frame(ByteSink sink, uint8_t type, uint16_t seq, const uint8_t* payload, uint16_t len) {
  uint8_t head[kHeadSize];
  head[0] = kSync0;
  head[1] = kSync1;
  head[2] = type;
  put_u16(head + 3, seq);
  put_u16(head + 5, len);
  head[7] = static_cast<uint8_t>(head[2] ^ head[3] ^ head[4] ^ head[5] ^ head[6] ^ 0x55);
  uint32_t crc = crc32_update(crc32_begin(), head + 2, 5);
  crc = crc32_end(crc32_update(crc, payload, len));
  uint8_t tail[4];
  put_u32(tail, crc);
  sink.put(head, kHeadSize);
  if (len != 0) sink.put(payload, len);
  sink.put(tail, 4);
}

// Byte-at-a-time frame parser over a caller-provided payload buffer. After
// a damaged frame it hunts for the next sync pair.
class FrameParser {
 public:
  enum Result { kNone, kFrame, kBad };

  FrameParser(uint8_t* buffer, size_t capacity) : buf_(buffer), cap_(capacity) {}

  Result feed(uint8_t c) {
    switch (state_) {
      case kHunt0:
        if (c == kSync0) state_ = kHunt1;
        return kNone;
      case kHunt1:
        state_ = c == kSync1 ? kHead : (c == kSync0 ? kHunt1 : kHunt0);
        got_ = 0;
        return kNone;
      case kHead:
        head_[got_++] = c;
        if (got_ < 6) return kNone;
        if ((head_[0] ^ head_[1] ^ head_[2] ^ head_[3] ^ head_[4] ^ 0x55) != head_[5] ||
            get_u16(head_ + 3) > cap_)
          return bad();
        len_ = get_u16(head_ + 3);
        got_ = 0;
        state_ = len_ == 0 ? kCrc : kPayload;
        return kNone;
      case kPayload:
        buf_[got_++] = c;
        if (got_ == len_) {
          got_ = 0;
          state_ = kCrc;
        }
        return kNone;
      case kCrc: {
        crc_[got_++] = c;
        if (got_ < 4) return kNone;
        uint32_t crc = crc32_update(crc32_begin(), head_, 5);
        crc = crc32_end(crc32_update(crc, buf_, len_));
        state_ = kHunt0;
        if (crc != get_u32(crc_)) return bad();
        return kFrame;
      }
    }
    return kNone;
  }
  void reset() { state_ = kHunt0; }
  bool idle() const { return state_ == kHunt0; }

  uint8_t type() const { return head_[0]; }
  uint16_t seq() const { return get_u16(head_ + 1); }
  uint16_t length() const { return len_; }
  const uint8_t* payload() const { return buf_; }
  uint32_t bad_frames() const { return bad_frames_; }

 private:
  Result bad() {
    ++bad_frames_;
    state_ = kHunt0;
    return kBad;
  }
  enum State { kHunt0, kHunt1, kHead, kPayload, kCrc };
  uint8_t* buf_;
  size_t cap_;
  State state_ = kHunt0;
  uint8_t head_[6] = {};
  uint8_t crc_[4] = {};
  size_t got_ = 0;
  uint16_t len_ = 0;
  uint32_t bad_frames_ = 0;
};

// Board side, step 1: collects the scene from S/E frames into `buffer`.
class SceneCollector {
 public:
  enum Result { kMore, kComplete, kDamaged, kTooLarge };

  SceneCollector(uint8_t* buffer, size_t capacity) : buf_(buffer), cap_(capacity) {}

  // Hand every good frame to it; kDamaged means: send N (host starts over).
  Result frame(const FrameParser& p) {
    if (p.type() == kScene) {
      if (p.seq() == 0) {
        size_ = 0;
        next_ = 0;
        broken_ = false;
      }
      if (p.seq() != next_) {
        broken_ = true;
        return kMore;
      }
      if (size_ + p.length() > cap_) return kTooLarge;
      for (uint16_t i = 0; i < p.length(); ++i) buf_[size_ + i] = p.payload()[i];
      size_ += p.length();
      ++next_;
      return kMore;
    }
    if (p.type() == kSceneEnd && p.length() == 8) {
      const bool ok = !broken_ && get_u32(p.payload()) == size_ && get_u32(p.payload() + 4) == crc32(buf_, size_);
      if (ok) return kComplete;
      size_ = 0;
      next_ = 0;
      broken_ = false;
      return kDamaged;
    }
    return kMore;
  }
  const uint8_t* data() const { return buf_; }
  size_t size() const { return size_; }
  size_t capacity() const { return cap_; }

 private:
  uint8_t* buf_;
  size_t cap_;
  size_t size_ = 0;
  uint16_t next_ = 0;
  bool broken_ = false;
};

// Board side, step 2: a row sink (begin, row, end; core/image/row_sink.hpp)
// that sends the H frame, then one D frame per finished row, keeping the
// pixels in `store` (3*width*height bytes) to answer Q requests. Rows are
// numbered in the order they arrive (a bottom-up tracer's first row is 0).
// With 4 bytes a pixel it carries the general tracer's RGBA rows (CS418
// and Jaworski scenes); a store can then be attached once the size is known.
class RowFramer {
 public:
  RowFramer(ByteSink link, uint8_t* store, size_t capacity) : link_(link), store_(store), cap_(capacity) {}

  // Before begin(): where the rows are kept (nullptr: sent once only), and
  // the bytes of a pixel (3 RGB, 4 RGBA).
  void attach_store(uint8_t* store, size_t capacity) {
    store_ = store;
    cap_ = store == nullptr ? 0 : capacity;
  }
  void set_pixel_bytes(int n) { pixel_bytes_ = n; }

  void begin(int width, int height) {
    width_ = width;
    height_ = height;
    row_bytes_ = static_cast<size_t>(width) * static_cast<size_t>(pixel_bytes_);
    fits_ = row_bytes_ * static_cast<size_t>(height) <= cap_ && row_bytes_ <= 0xFFFF;
    send_header();
  }
  void row(int /*y*/, const uint8_t* pixels) {
    if (fits_) {
      uint8_t* dst = store_ + static_cast<size_t>(rows_) * row_bytes_;
      for (size_t i = 0; i < row_bytes_; ++i) dst[i] = pixels[i];
      send_row(static_cast<uint16_t>(rows_));
    } else if (row_bytes_ <= 0xFFFF) {
      write_frame(link_, kRow, static_cast<uint16_t>(rows_), pixels, static_cast<uint16_t>(row_bytes_));
    }
    ++rows_;
  }
  void end() {}
  // False if the image did not fit `store` (rows were still sent once).
  bool stored() const { return fits_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int rows_sent() const { return rows_; }

  void send_header() {
    uint8_t p[4];
    put_u16(p, static_cast<uint16_t>(width_));
    put_u16(p + 2, static_cast<uint16_t>(height_));
    write_frame(link_, kHeader, 0, p, 4);
  }
  void send_row(uint16_t row) {
    if (!fits_ || row >= height_) return;
    write_frame(link_, kRow, row, store_ + row_bytes_ * row, static_cast<uint16_t>(row_bytes_));
  }
  void send_end() {
    uint8_t p[2];
    put_u16(p, static_cast<uint16_t>(rows_));
    write_frame(link_, kEnd, 0, p, 2);
  }
  // Answers one Q frame: the listed rows (and header), then Z.
  void answer_request(const FrameParser& p) {
    for (uint16_t i = 0; i + 2 <= p.length(); i += 2) {
      const uint16_t row = get_u16(p.payload() + i);
      if (row == kHeaderIndex) send_header();
      else send_row(row);
    }
    send_end();
  }

 private:
  ByteSink link_;
  uint8_t* store_;
  size_t cap_;
  int pixel_bytes_ = 3;
  int width_ = 0, height_ = 0;
  size_t row_bytes_ = 0;
  int rows_ = 0;
  bool fits_ = false;
};

}  // namespace minrt::send::framed
