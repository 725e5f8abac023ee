#include "protocol_raw.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include <minrt/serial_protocol.h>

#include "core/base/crc32.hpp"
#include "posix/interrupt.hpp"
#include "protocol/scene_check.hpp"

namespace minrt::send {

namespace {
using Clock = std::chrono::steady_clock;
int ms_since(Clock::time_point t) {
  return static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - t).count());
}
}  // namespace

long long reply_deadline_ms(const Timeouts& t, std::uint64_t image_bytes, std::uint32_t baud) {
  const double line_ms = static_cast<double>(image_bytes) * 10.0 * 1000.0 / (baud != 0 ? baud : 115200);
  return t.first_byte_ms + static_cast<long long>(std::max(20000.0, 8 * line_ms));
}

template <class Receiver>
TransferResult exchange(Exchange& ex, const std::string& out, Receiver& rx) {
  long long reply_ms = ex.timeouts.reply_ms;
  if (reply_ms == 0)
    reply_ms = ex.progress != nullptr ? reply_deadline_ms(ex.timeouts, ex.progress->expected_bytes(), ex.port.applied_baud()) : -1;
  TransferResult r;
  const int fd = ex.port.fd();
  std::size_t sent = 0;
  bool clock_started = false;
  std::size_t trailing = 0;  // bytes after the image in its last read
  Clock::time_point t0 = Clock::now(), last_rx = Clock::now(), last_tx = Clock::now(), t_end = Clock::now();
  if (ex.progress) ex.progress->start();
  std::uint8_t buf[8192];
  auto ended = [&](TransferResult::Status status, std::string msg) {
    r.status = status;
    r.message = std::move(msg);
    r.sent = sent;
    r.received = rx.bytes();
    return r;
  };
  auto fail = [&](std::string msg) { return ended(TransferResult::Status::kLinkError, std::move(msg)); };
  // The board's own error line ends the exchange with its message.
  auto board_error = [&] { return ended(TransferResult::Status::kFirmwareError, rx.message()); };
  for (;;) {
    if (minrt::host::interrupted()) return fail("interrupted");
    // Stop sending once the board has started to answer: it has read all it
    // wants (a rejected scene is answered before the end of the upload).
    const bool sending = sent < out.size() && !rx.started();
    pollfd p{fd, static_cast<short>(POLLIN | (sending ? POLLOUT : 0)), 0};
    int wait = 100;
    ::poll(&p, 1, wait);
    if (sending && (p.revents & POLLOUT)) {
      const ssize_t n = ::write(fd, out.data() + sent, out.size() - sent);
      if (n > 0) {
        if (!clock_started) {
          clock_started = true;
          t0 = Clock::now();
          if (ex.progress) ex.progress->start();
        }
        sent += static_cast<std::size_t>(n);
        last_tx = Clock::now();
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        return fail(std::string("write error on ") + ex.port.device() + ": " + std::strerror(errno));
      }
    }
    if (ex.progress && !rx.started()) ex.progress->sending(sent, out.size());
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n > 0) {
        if (!clock_started) {
          clock_started = true;
          t0 = Clock::now();
        }
        last_rx = Clock::now();
        const std::size_t used = rx.feed(buf, static_cast<std::size_t>(n));
        if (rx.image_bytes()) {
          r.image.append(reinterpret_cast<const char*>(buf), used);
          if (ex.live != nullptr) ex.live->feed(buf, used);
        }
        if (ex.progress) ex.progress->update(rx.bytes(), rx.rows_complete());
        if (rx.done()) {
          t_end = Clock::now();
          trailing = static_cast<std::size_t>(n) - used;
          break;
        }
        if (rx.firmware_error()) return board_error();
        if (rx.failed()) return fail(rx.message());
        continue;
      }
      if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
        rx.finish();
        if (rx.done()) {
          t_end = Clock::now();
          break;
        }
        if (rx.firmware_error()) continue;
        return fail("line closed (" + std::string(n == 0 ? "end of file" : std::strerror(errno)) + "): " +
                    rx.message());
      }
    }
    // Timeouts.
    if (!sending && reply_ms > 0 && ms_since(sent > 0 ? last_tx : t0) > reply_ms) {
      rx.finish();
      if (rx.done()) {
        t_end = last_rx;
        break;
      }
      if (rx.firmware_error()) return board_error();
      return fail("the reply did not end within " + std::to_string(reply_ms / 1000) + " s of the upload (" +
                  std::to_string(rx.bytes()) + " bytes received; --reply-timeout S)");
    }
    if (sending) {
      if (ms_since(last_tx) > ex.timeouts.idle_ms)
        return fail("the board stopped reading the scene (" + std::to_string(sent) + " of " +
                    std::to_string(out.size()) + " bytes sent)");
    } else if (!rx.started()) {
      const auto since = sent > 0 ? last_tx : t0;
      if (ms_since(since) > ex.timeouts.first_byte_ms) {
        rx.finish();
        return fail("no reply within " + std::to_string(ex.timeouts.first_byte_ms / 1000) +
                    " s (first-byte timeout)");
      }
    } else if (ms_since(last_rx) > ex.timeouts.idle_ms) {
      rx.finish();
      if (rx.done()) {
        t_end = last_rx;
        break;
      }
      if (rx.firmware_error()) continue;
      return fail("line idle for " + std::to_string(ex.timeouts.idle_ms / 1000) + " s (idle timeout): " +
                  rx.message());
    }
  }
  // Nothing may follow the image; a byte that does means the line added
  // some (a duplicated byte makes the image complete one byte early).
  if (ex.timeouts.trailing_ms > 0 || trailing > 0) {
    const auto until = Clock::now() + std::chrono::milliseconds(ex.timeouts.trailing_ms);
    std::size_t extra = trailing;
    while (Clock::now() < until) {
      pollfd p{fd, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n <= 0) break;
      extra += static_cast<std::size_t>(n);
    }
    if (extra > 0)
      return fail(std::to_string(extra) + " unexpected bytes after the image: the line damaged it");
  }
  r.status = TransferResult::Status::kOk;
  if constexpr (requires { rx.checked(); }) {
    r.image = rx.image();
    r.crc_checked = rx.checked();
  }
  r.seconds = std::chrono::duration<double>(t_end - t0).count();
  r.sent = sent;
  r.received = rx.bytes();
  return r;
}

template TransferResult exchange<PpmReceiver>(Exchange&, const std::string&, PpmReceiver&);
template TransferResult exchange<PngReceiver>(Exchange&, const std::string&, PngReceiver&);
template TransferResult exchange<BmpReceiver>(Exchange&, const std::string&, BmpReceiver&);
// The course protocol's checked reply (protocol_course_host.cpp).
template TransferResult exchange<CheckedReply<PpmReceiver>>(Exchange&, const std::string&, CheckedReply<PpmReceiver>&);
template TransferResult exchange<CheckedReply<PngReceiver>>(Exchange&, const std::string&, CheckedReply<PngReceiver>&);
template TransferResult exchange<CheckedReply<BmpReceiver>>(Exchange&, const std::string&, CheckedReply<BmpReceiver>&);

std::string checked_raw_upload(const std::string& scene) {
  const auto* p = reinterpret_cast<const std::uint8_t*>(scene.data());
  std::uint8_t header[scene_check::kRawHeaderSize];
  scene_check::encode_raw_header(static_cast<std::uint32_t>(scene.size()), crc32(p, scene.size()), header);
  std::string out(reinterpret_cast<const char*>(header), sizeof header);
  out += scene;
  out.append(scene_check::kPaddingBytes, static_cast<char>(MINRT_END_OF_INPUT));
  return out;
}

namespace {
// The raw upload: unless --no-check the checked upload (byte count and
// CRC-32 ahead of the scene with any texture preamble, which also asks for
// the reply's trailer), otherwise the scene and the end-of-input byte; the
// reply through CheckedReply around the format's receiver.
template <class Receiver>
TransferResult raw_exchange(Exchange& ex, const std::string& scene, Receiver& inner) {
  std::string out;
  if (ex.check != RawCheck::kOff) {
    out = checked_raw_upload(scene);
  } else {
    out = scene;
    out.push_back(static_cast<char>(MINRT_END_OF_INPUT));
  }
  CheckedReply<Receiver> rx(inner, ex.check);
  if (ex.live != nullptr)
    rx.follow(ByteSink{[](void* c, const std::uint8_t* p, std::size_t n) {
                         static_cast<minrt::host::ImageStreamDecoder*>(c)->feed(p, n);
                       },
                       ex.live});
  return exchange(ex, out, rx);
}
}  // namespace

TransferResult run_raw_bmp(Exchange& ex, const std::string& scene) {
  BmpReceiver rx;
  return raw_exchange(ex, scene, rx);
}

TransferResult run_raw_png(Exchange& ex, const std::string& scene, int width, int height) {
  PngReceiver rx(width, height);
  return raw_exchange(ex, scene, rx);
}

TransferResult run_raw(Exchange& ex, const std::string& scene, const ImageSpec& spec) {
  PpmReceiver rx(spec);
  return raw_exchange(ex, scene, rx);
}

}  // namespace minrt::send
