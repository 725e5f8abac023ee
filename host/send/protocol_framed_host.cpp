#include "protocol_framed_host.hpp"

#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/image/bmp_writer.hpp"
#include "core/image/png_writer.hpp"
#include "terminal_text.hpp"
#include "core/image/ppm_writer.hpp"
#include "posix/interrupt.hpp"
#include "protocol/protocol_framed.hpp"
#include "protocol/text_scene_upload.hpp"

namespace minrt::send {

namespace {

using Clock = std::chrono::steady_clock;
int ms_since(Clock::time_point t) {
  return static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t).count());
}

void append_fn(void* ctx, const uint8_t* data, size_t size) {
  static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(data), size);
}

std::string frame_bytes(uint8_t type, uint16_t seq, const uint8_t* payload, uint16_t len) {
  std::string out;
  framed::write_frame(ByteSink{&append_fn, &out}, type, seq, payload, len);
  return out;
}

}  // namespace

std::string framed_upload(const std::string& scene) {
  std::string out;
  const auto* p = reinterpret_cast<const uint8_t*>(scene.data());
  uint16_t seq = 0;
  for (size_t at = 0; at < scene.size() || (at == 0 && scene.empty()); at += framed::kSceneChunk, ++seq) {
    const size_t n = std::min(framed::kSceneChunk, scene.size() - at);
    out += frame_bytes(framed::kScene, seq, p + at, static_cast<uint16_t>(n));
    if (scene.empty()) break;
  }
  uint8_t end[8];
  framed::put_u32(end, static_cast<uint32_t>(scene.size()));
  framed::put_u32(end + 4, crc32(p, scene.size()));
  out += frame_bytes(framed::kSceneEnd, 0, end, 8);
  return out;
}

std::string framed_image(const ImageSpec& spec, const std::vector<std::vector<uint8_t>>& rows) {
  std::string out;
  PpmWriter w(ByteSink{&append_fn, &out}, spec.kind == PpmKind::kP3 ? PpmFormat::kP3 : PpmFormat::kP6);
  w.begin(spec.width, spec.height);
  for (size_t y = 0; y < rows.size(); ++y) w.row(static_cast<int>(y), rows[y].data());
  w.end();
  return out;
}

std::string framed_rgba_image(FramedImage kind, int width, int height, const std::vector<std::vector<uint8_t>>& rows) {
  std::string out;
  const ByteSink sink{&append_fn, &out};
  auto write = [&](auto& writer) {
    writer.begin(width, height);
    for (size_t y = 0; y < rows.size(); ++y) writer.row(static_cast<int>(y), rows[y].data());
    writer.end();
  };
  if (kind == FramedImage::kBmp) {
    BmpWriter w(sink);
    write(w);
  } else {
    PngStoredWriter w(sink);
    write(w);
  }
  return out;
}

namespace {

// The repair phase's shortest deadline and the longest pause between
// requests for missing rows.
constexpr long long kRepairFloorMs = 20000;
constexpr int kMaxRetryMs = 8000;

// The conversation for every kind of image: PPM rows (RGB, the size known
// from --size) or a text-format scene's RGBA rows (the size from H when
// `spec` gives none).
TransferResult run_framed_image(Exchange& ex, const std::string& scene_text, FramedImage kind, const ImageSpec& spec,
                                const FramedHostOptions& options) {
  TransferResult r;
  const int fd = ex.port.fd();
  const size_t pixel_bytes = kind == FramedImage::kPpm ? 3 : 4;
  int width = spec.width, height = spec.height;  // 0: from the H frame
  size_t row_bytes = static_cast<size_t>(width) * pixel_bytes;
  std::vector<uint8_t> payload(0xFFFF);
  framed::FrameParser parser(payload.data(), payload.size());
  std::vector<std::vector<uint8_t>> rows(static_cast<size_t>(height));
  std::vector<bool> have(static_cast<size_t>(height), false);
  int have_count = 0;
  bool have_header = false, acked = false;
  int uploads = 0;
  // A firmware without the framed protocol (or one failing before it starts
  // framing) answers with a plain error line; catch it before any frame.
  std::string plain;
  bool any_frame = false;

  std::string out = framed_upload(scene_text);
  size_t sent = 0;
  uint64_t received = 0;
  const Clock::time_point t0 = Clock::now();
  Clock::time_point last_rx = t0, last_tx = t0, last_request = t0, t_end = t0;
  if (ex.progress) ex.progress->start();
  uint8_t buf[8192];
  int retry_interval = options.retry_ms;

  auto fail = [&](TransferResult::Status st, std::string msg) {
    r.status = st;
    r.message = std::move(msg);
    r.sent = sent;
    r.received = received;
    return r;
  };
  auto queue = [&](const std::string& bytes) {
    if (sent >= out.size()) {
      out.clear();
      sent = 0;
    }
    out += bytes;
  };
  int max_row_seen = -1;
  // Deadlines (docs/reliability.md): no new row for the idle timeout ends
  // the transfer, however many damaged frames still arrive; and once the
  // board has sent every row once (its first Z), the repairs get
  // repair_deadline_ms in all: 8 times the image's time on the line at the
  // port's baud rate, at least kRepairFloorMs.
  Clock::time_point last_new_row = t0, repair_start = t0;
  bool repairing = false;
  auto repair_deadline_ms = [&]() -> long long {
    const std::uint32_t baud = ex.port.applied_baud() != 0 ? ex.port.applied_baud() : 115200;
    const double image_bytes = static_cast<double>(height) * (static_cast<double>(row_bytes) + framed::kOverhead);
    const double line_ms = image_bytes * 10.0 * 1000.0 / baud;
    return std::max<long long>(kRepairFloorMs, static_cast<long long>(8 * line_ms));
  };
  // Z received: ask for every missing row. Silence: ask only for the holes
  // below the last row seen (the rest may still be rendering); an empty
  // request just asks the board for a Z once it is done.
  auto request_missing = [&](bool all) {
    std::vector<uint8_t> list;
    if (!have_header) {
      list.push_back(0xFF);
      list.push_back(0xFF);
    }
    const int limit = all ? height : std::min(max_row_seen, height);
    for (int row = 0; row < limit && list.size() < 2 * 512; ++row) {
      if (have[static_cast<size_t>(row)]) continue;
      list.push_back(static_cast<uint8_t>(row));
      list.push_back(static_cast<uint8_t>(row >> 8));
    }
    queue(frame_bytes(framed::kRequest, 0, list.data(), static_cast<uint16_t>(list.size())));
    last_request = Clock::now();
  };

  for (;;) {
    if (minrt::host::interrupted()) return fail(TransferResult::Status::kLinkError, "interrupted");
    const bool sending = sent < out.size();
    pollfd p{fd, static_cast<short>(POLLIN | (sending ? POLLOUT : 0)), 0};
    ::poll(&p, 1, 50);
    if (sending && (p.revents & POLLOUT)) {
      const ssize_t n = ::write(fd, out.data() + sent, out.size() - sent);
      if (n > 0) {
        sent += static_cast<size_t>(n);
        last_tx = Clock::now();
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        return fail(TransferResult::Status::kLinkError, std::string("write error: ") + std::strerror(errno));
      }
    }
    if (ex.progress && !any_frame) ex.progress->sending(sent, out.size());
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR))
        return fail(TransferResult::Status::kLinkError,
                    "line closed with " + std::to_string(have_count) + " of " + std::to_string(height) + " rows");
      for (ssize_t i = 0; i < n; ++i) {
        ++received;
        if (!any_frame && plain.size() < 4096) {
          plain.push_back(static_cast<char>(buf[i]));
          const std::string marker = MINRT_ERROR_MARKER;
          if (buf[i] == '\n' && plain.compare(0, marker.size(), marker) == 0)
            return fail(TransferResult::Status::kFirmwareError,
                        terminal_safe(plain.substr(marker.size(), plain.size() - marker.size() - 1)));
        }
        if (parser.feed(buf[i]) != framed::FrameParser::kFrame) continue;
        any_frame = true;
        last_rx = Clock::now();
        retry_interval = options.retry_ms;
        switch (parser.type()) {
          case framed::kAck:
            acked = true;
            break;
          case framed::kNak:
            if (acked) break;
            if (++uploads > options.max_uploads)
              return fail(TransferResult::Status::kLinkError, "the board kept rejecting the scene upload as damaged");
            queue(framed_upload(scene_text));
            break;
          case framed::kError:
            return fail(TransferResult::Status::kFirmwareError,
                        terminal_safe(std::string(reinterpret_cast<const char*>(parser.payload()), parser.length())));
          case framed::kHeader: {
            acked = true;
            if (parser.length() != 4) break;
            const int w = framed::get_u16(parser.payload()), h = framed::get_u16(parser.payload() + 2);
            if (width == 0) {
              // The scene gave the size; rows carry at most 0xFFFF bytes.
              if (w < 1 || h < 1 || static_cast<size_t>(w) * pixel_bytes > 0xFFFF)
                return fail(TransferResult::Status::kLinkError,
                            "the board announced a " + std::to_string(w) + "x" + std::to_string(h) +
                                " image, which framed rows cannot carry (at most " +
                                std::to_string(0xFFFF / pixel_bytes) + " pixels wide)");
              width = w;
              height = h;
              row_bytes = static_cast<size_t>(width) * pixel_bytes;
              rows.assign(static_cast<size_t>(height), {});
              have.assign(static_cast<size_t>(height), false);
            }
            if (w != width || h != height)
              return fail(TransferResult::Status::kLinkError, "image is " + std::to_string(w) + "x" + std::to_string(h) +
                                                                  ", expected " + std::to_string(width) + "x" +
                                                                  std::to_string(height));
            have_header = true;
            break;
          }
          case framed::kRow: {
            acked = true;
            const uint16_t row = parser.seq();
            if (row > max_row_seen) max_row_seen = row;
            if (row >= height || parser.length() != row_bytes) break;
            if (!have[row]) {
              rows[row].assign(parser.payload(), parser.payload() + parser.length());
              have[row] = true;
              ++have_count;
              last_new_row = Clock::now();
              if (last_request != t0) ++r.retransmitted_rows;
            }
            if (ex.progress) ex.progress->update(received, have_count);
            break;
          }
          case framed::kEnd:
            acked = true;
            if (have_header && have_count == height) {
              t_end = Clock::now();
              queue(frame_bytes(framed::kFinished, 0, nullptr, 0));
              // Let F go out before returning.
              const size_t left = out.size() - sent;
              if (left > 0 && ex.port.write_all(out.data() + sent, left, 1000)) sent = out.size();
              ex.port.drain();
              r.status = TransferResult::Status::kOk;
              r.image = kind == FramedImage::kPpm ? framed_image(spec, rows)
                                                  : framed_rgba_image(kind, width, height, rows);
              r.seconds = std::chrono::duration<double>(t_end - t0).count();
              r.sent = sent;
              r.received = received;
              return r;
            }
            if (!repairing) {
              repairing = true;
              repair_start = Clock::now();
            }
            request_missing(true);
            break;
          default:
            break;
        }
      }
    }
    // Scene not acknowledged: upload again.
    if (!acked && !sending && ms_since(last_tx) > options.ack_timeout_ms) {
      if (++uploads > options.max_uploads)
        return fail(TransferResult::Status::kLinkError, "no acknowledgement of the scene from the board");
      parser.reset();
      queue(framed_upload(scene_text));
    }
    // Silence after the rows started: a frame (maybe Z) was lost; ask.
    if ((have_header || max_row_seen >= 0) && !sending && ms_since(last_rx) > options.retry_ms &&
        ms_since(last_request) > retry_interval) {
      parser.reset();
      request_missing(false);
      retry_interval = std::min(retry_interval * 2, kMaxRetryMs);
    }
    if (max_row_seen >= 0 && have_count < height && ms_since(last_new_row) > ex.timeouts.idle_ms)
      return fail(TransferResult::Status::kLinkError,
                  "no new row for " + std::to_string(ex.timeouts.idle_ms / 1000) + " s: " +
                      std::to_string(have_count) + " of " + std::to_string(height) +
                      " rows arrived whole (the line damages every frame)");
    if (repairing && ms_since(repair_start) > repair_deadline_ms())
      return fail(TransferResult::Status::kLinkError,
                  "rows still missing " + std::to_string(repair_deadline_ms() / 1000) + " s after the board sent them: " +
                      std::to_string(have_count) + " of " + std::to_string(height) + " rows arrived whole");
    const int silence = ms_since(last_rx);
    if (acked && silence > ex.timeouts.idle_ms)
      return fail(TransferResult::Status::kLinkError, "line idle for " + std::to_string(ex.timeouts.idle_ms / 1000) +
                                                          " s with " + std::to_string(have_count) + " of " +
                                                          std::to_string(height) + " rows (idle timeout)");
    if (!acked && ms_since(t0) > ex.timeouts.first_byte_ms)
      return fail(TransferResult::Status::kLinkError, "no reply within " + std::to_string(ex.timeouts.first_byte_ms / 1000) +
                                                          " s (first-byte timeout)");
  }
}

}  // namespace

TransferResult run_framed(Exchange& ex, const std::string& scene_text, const ImageSpec& spec,
                          const FramedHostOptions& options) {
  return run_framed_image(ex, scene_text, FramedImage::kPpm, spec, options);
}

TransferResult run_framed_text(Exchange& ex, std::uint32_t format, FramedImage kind, const std::string& bytes,
                               int width, int height, const FramedHostOptions& options) {
  std::string upload(text::kHeaderBytes, '\0');
  text::put_header(reinterpret_cast<uint8_t*>(upload.data()), format, static_cast<uint32_t>(bytes.size()),
                   course::Endian::kLittle);
  upload += bytes;
  return run_framed_image(ex, upload, kind, ImageSpec{width, height, PpmKind::kP6}, options);
}

}  // namespace minrt::send
