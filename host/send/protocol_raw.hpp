// Raw protocol, host side: the SLD text goes out as is (followed by
// MINRT_END_OF_INPUT), the PPM image or one error line comes back
// (include/minrt/serial_protocol.h). The exchange loop sends and receives
// at once, so a board that rejects a scene half-way through is heard.
#pragma once

#include <cstdint>
#include <string>

#include "image_stream_decoder.hpp"
#include "port.hpp"
#include "bmp_receiver.hpp"
#include "checked_reply.hpp"
#include "png_receiver.hpp"
#include "ppm_receiver.hpp"
#include "progress.hpp"

namespace minrt::send {

struct Timeouts {
  int first_byte_ms = 120000;  // from the end of sending to the first reply byte
  int idle_ms = 30000;         // longest silence once the reply has started
  // After the image: listen this long for stray bytes, which mean the line
  // duplicated or inserted some and the image is damaged (0: do not wait).
  int trailing_ms = 250;
  // The whole reply, from the end of sending to its last byte (a board that
  // drips a byte just inside the idle timeout must still end): 0 for
  // reply_deadline_ms() of the image the progress line expects, < 0 none.
  long long reply_ms = 0;
};

// The default bound on a reply: the first-byte timeout (the board's render
// time) plus 8 times the image's time on the line (10 bits a byte at
// `baud`, 115200 when 0), at least 20 s more.
long long reply_deadline_ms(const Timeouts& t, std::uint64_t image_bytes, std::uint32_t baud);

struct TransferResult {
  enum class Status { kOk, kFirmwareError, kSceneError, kLinkError };
  // kSceneError: the host itself found the scene unusable (course conversion).
  Status status = Status::kLinkError;
  std::string message;         // link error text or the firmware's message
  std::string image;           // the image bytes exactly as received (kOk)
  double seconds = 0;          // first byte sent .. last image byte received
  std::uint64_t sent = 0;
  std::uint64_t received = 0;
  int retransmitted_rows = 0;  // framed only
  bool crc_checked = false;    // raw: the CRC-32 trailer came and matched
};

struct Exchange {
  SerialPort& port;
  Timeouts timeouts;
  Progress* progress = nullptr;
  RawCheck check = RawCheck::kAuto;  // raw: the CRC-32 trailer (--check, --no-check)
  // --show: the image bytes also go here, which hands rows to the window.
  minrt::host::ImageStreamDecoder* live = nullptr;
};

// Sends `out` (may be empty), then collects the reply into `rx`. `t0` is the
// moment the transfer clock started (the first byte sent); if null, it
// starts with the first byte written here.
// Receiver: PpmReceiver or PngReceiver (instantiated in protocol_raw.cpp).
template <class Receiver>
TransferResult exchange(Exchange& ex, const std::string& out, Receiver& rx);

// The raw protocol's checked upload of `scene` (texture preamble and text):
// the request byte, byte count and CRC-32 (protocol/scene_check.hpp), the bytes.
std::string checked_raw_upload(const std::string& scene);

TransferResult run_raw(Exchange& ex, const std::string& scene, const ImageSpec& spec);

// A CS418 scene: the reply is a PNG stream of WIDTH x HEIGHT (the scene's
// png line), checked chunk by chunk.
TransferResult run_raw_png(Exchange& ex, const std::string& scene, int width, int height);

// A Jaworski scene: the reply is a 32-bit BMP.
TransferResult run_raw_bmp(Exchange& ex, const std::string& scene);

}  // namespace minrt::send
