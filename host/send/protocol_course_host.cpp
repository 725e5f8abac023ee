#include "protocol_course_host.hpp"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "core/base/crc32.hpp"
#include "posix/interrupt.hpp"
#include "protocol/protocol_course_board.hpp"
#include "protocol/scene_check.hpp"

namespace minrt::send {

namespace {

// Waits for `want`; other bytes before it are an error (an error line is
// handed to `rx` so its message comes through).
template <class Receiver>
bool wait_for(Exchange& ex, uint8_t want, int timeout_ms, Receiver& rx, TransferResult& r, const char* what) {
  // In slices, so that the progress line shows the wait (a board may take
  // seconds to boot).
  constexpr int kSliceMs = 200;
  uint8_t c = 0;
  long n = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int waited = 0; n == 0 && waited < timeout_ms; waited += kSliceMs) {
    if (ex.progress)
      ex.progress->handshake(what, timeout_ms / 1000,
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    n = ex.port.read_some(&c, 1, std::min(kSliceMs, timeout_ms - waited));
  }
  if (n == 1 && c == want) return true;
  if (n == 1) {
    rx.feed(&c, 1);
    // The rest of a possible error line.
    r = exchange(ex, std::string(), rx);
    if (r.status == TransferResult::Status::kOk) {
      r.status = TransferResult::Status::kLinkError;
      r.message = std::string("unexpected image instead of ") + what;
    }
    return false;
  }
  r.status = TransferResult::Status::kLinkError;
  r.message = n == 0 ? std::string("the board did not send ") + what + " within " + std::to_string(timeout_ms / 1000) + " s"
                     : std::string("line closed while waiting for ") + what;
  return false;
}

// Sends the program's length and bytes while listening: a board that
// refuses the program (too large for its program region) answers at once
// and may stop reading, and its error line must not sit unread behind a
// blocked write. Returns false with `r` set on a link error; true when all
// is sent or the board spoke first (wait_for then reads what it said).
bool send_program(Exchange& ex, const std::string& out, TransferResult& r) {
  using Clock = std::chrono::steady_clock;
  const int fd = ex.port.fd();
  std::size_t sent = 0;
  auto last_tx = Clock::now();
  while (sent < out.size()) {
    if (minrt::host::interrupted()) {
      r.message = "interrupted";
      return false;
    }
    pollfd p{fd, POLLIN | POLLOUT, 0};
    ::poll(&p, 1, 100);
    if (p.revents & (POLLIN | POLLHUP | POLLERR)) return true;
    if (p.revents & POLLOUT) {
      const ssize_t n = ::write(fd, out.data() + sent, out.size() - sent);
      if (n > 0) {
        sent += static_cast<std::size_t>(n);
        last_tx = Clock::now();
        if (ex.progress) ex.progress->sending_program(sent, out.size());
      } else if (n < 0 && errno != EAGAIN && errno != EINTR) {
        r.message = "cannot send the program: " + std::string(std::strerror(errno));
        return false;
      }
    }
    if (Clock::now() - last_tx > std::chrono::milliseconds(ex.timeouts.idle_ms)) {
      r.message = "the board stopped reading the program (" + std::to_string(sent) + " of " +
                  std::to_string(out.size()) + " bytes sent)";
      return false;
    }
  }
  return true;
}

}  // namespace

template <class Receiver>
TransferResult run_course_words(Exchange& ex, const std::string& words, const std::string& program,
                                const CourseHostOptions& options, Receiver& rx) {
  TransferResult r;
  const course::Endian endian = options.big_endian ? course::Endian::kBig : course::Endian::kLittle;
  if (!wait_for(ex, course::kProgramRequest, options.handshake_timeout_ms, rx, r, "0x99 (program request)")) return r;
  // Checked (unless --no-check): the program's length word carries the tag
  // and its CRC-32 follows it; the scene words go behind their byte count and
  // CRC-32 and the reply comes with raw's trailer (protocol/scene_check.hpp).
  const bool checked = ex.check != RawCheck::kOff;
  std::string out(4, '\0');
  const auto size = static_cast<uint32_t>(program.size());
  course::put_u32(reinterpret_cast<uint8_t*>(out.data()), checked ? size | course::kCheckedProgramTag << 24 : size,
                  endian);
  out += program;
  if (checked) {
    std::uint8_t sum[4];
    course::put_u32(sum, crc32(reinterpret_cast<const std::uint8_t*>(program.data()), program.size()), endian);
    out.append(reinterpret_cast<const char*>(sum), 4);
  }
  // No padding after the program: the board answers 0xaa next and reads the
  // scene after it, so stray bytes would shift the scene; a dropped program
  // byte shows as the scene's first word taken for the program's CRC.
  if (!send_program(ex, out, r)) return r;
  CheckedReply<Receiver> reply(rx, ex.check);
  if (ex.live != nullptr)
    reply.follow(ByteSink{[](void* c, const std::uint8_t* p, std::size_t n) {
                            static_cast<minrt::host::ImageStreamDecoder*>(c)->feed(p, n);
                          },
                          ex.live});
  if (!wait_for(ex, course::kSceneRequest, options.handshake_timeout_ms, reply, r, "0xaa (scene request)")) return r;
  if (checked) {
    std::uint8_t header[scene_check::kCourseHeaderSize];
    scene_check::encode_course_header(static_cast<uint32_t>(words.size()),
                                      crc32(reinterpret_cast<const std::uint8_t*>(words.data()), words.size()),
                                      endian, header);
    r = exchange(ex,
                 std::string(reinterpret_cast<const char*>(header), sizeof header) + words +
                     std::string(scene_check::kPaddingBytes, static_cast<char>(MINRT_END_OF_INPUT)),
                 reply);
  } else {
    r = exchange(ex, words, reply);
  }
  r.sent += out.size();
  return r;
}

template TransferResult run_course_words<PngReceiver>(Exchange&, const std::string&, const std::string&,
                                                      const CourseHostOptions&, PngReceiver&);
template TransferResult run_course_words<BmpReceiver>(Exchange&, const std::string&, const std::string&,
                                                      const CourseHostOptions&, BmpReceiver&);

TransferResult run_course(Exchange& ex, const std::string& scene_text, const std::string& program,
                          const CourseHostOptions& options, const ImageSpec& spec) {
  TransferResult r;
  std::string words, error;
  if (!sld_to_course_words(scene_text, options.big_endian, words, error)) {
    r.status = TransferResult::Status::kSceneError;
    r.message = error;
    return r;
  }
  PpmReceiver rx(spec);
  return run_course_words(ex, words, program, options, rx);
}

}  // namespace minrt::send
