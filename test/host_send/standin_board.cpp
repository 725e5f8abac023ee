// A stand-in for the board in tests: takes firmware-sim's command line
// (`--pty [--baud N] ELF -- --size WxH --format F [--protocol=P]`), opens a
// pseudo-terminal, announces it like firmware-sim and plays the firmware's
// part with the host renderer linked in (float precision, portable shims:
// the firmware's arithmetic). --baud paces the output at baud/10 bytes/s.
#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <minrt/serial_protocol.h>

#include "core/base/peek_source.hpp"
#include "protocol/raw_check.hpp"
#include "protocol/scene_check.hpp"
#include "render_variants.hpp"
#include "standin_protocols.hpp"

namespace {

struct Board {
  int fd = -1;
  long baud = 0;
  bool ended = false;
  std::chrono::steady_clock::time_point t0;
  unsigned long long sent = 0;

  // Raw input: bytes up to MINRT_END_OF_INPUT or hang-up.
  int get() {
    if (ended) return -1;
    unsigned char c;
    for (;;) {
      const ssize_t n = ::read(fd, &c, 1);
      if (n == 1) {
        if (c == MINRT_END_OF_INPUT) {
          ended = true;
          return -1;
        }
        return c;
      }
      if (n < 0 && errno == EINTR) continue;
      ended = true;
      return -1;
    }
  }
  bool read_exact(unsigned char* p, size_t n) {
    while (n > 0) {
      const ssize_t k = ::read(fd, p, n);
      if (k < 0 && errno == EINTR) continue;
      if (k <= 0) return false;
      p += k;
      n -= static_cast<size_t>(k);
    }
    return true;
  }
  void put(const uint8_t* data, size_t size) {
    if (sent == 0) t0 = std::chrono::steady_clock::now();
    while (size > 0) {
      size_t chunk = size;
      if (baud > 0) {
        // Send no faster than baud/10 bytes per second since the first byte.
        const double allowed_at = static_cast<double>(sent) * 10.0 / static_cast<double>(baud);
        const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (allowed_at > now) std::this_thread::sleep_for(std::chrono::duration<double>(allowed_at - now));
        chunk = std::min<size_t>(size, static_cast<size_t>(std::max<long>(1, baud / 10 / 200)));
      }
      const ssize_t n = ::write(fd, data, chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return;
      data += n;
      size -= static_cast<size_t>(n);
      sent += static_cast<unsigned long long>(n);
    }
  }
  static int read_fn(void* ctx) { return static_cast<Board*>(ctx)->get(); }
  static int read_binary_fn(void* ctx) {
    unsigned char c = 0;
    return static_cast<Board*>(ctx)->read_exact(&c, 1) ? c : -1;
  }
  static void write_fn(void* ctx, const uint8_t* d, size_t n) { static_cast<Board*>(ctx)->put(d, n); }
};

int open_pty_and_wait() {
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) return -1;
  const char* name = ::ptsname(master);
  const int s = ::open(name, O_RDWR | O_NOCTTY);
  termios t{};
  if (s >= 0 && ::tcgetattr(s, &t) == 0) {
    ::cfmakeraw(&t);
    ::tcsetattr(s, TCSANOW, &t);
  }
  std::fprintf(stderr, "standin-board: uart on %s\n", name);
  std::fflush(stderr);
  if (s >= 0) ::close(s);
  for (;;) {
    pollfd p{master, POLLIN, 0};
    ::poll(&p, 1, 50);
    if (!(p.revents & POLLHUP)) break;
    ::usleep(10000);
  }
  return master;
}

// Waits (bounded) for the host to close its end, so nothing we sent is lost
// when the master closes.
void wait_for_hangup(int fd) {
  for (int i = 0; i < 3000; ++i) {
    pollfd p{fd, POLLIN, 0};
    ::poll(&p, 1, 10);
    if (p.revents & POLLHUP) return;
    if (p.revents & POLLIN) {
      unsigned char junk[256];
      if (::read(fd, junk, sizeof junk) <= 0) return;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  minrt::RenderOptions options;
  std::string protocol = "raw";
  long baud = 0;
  bool big_endian = false;
  bool after_dashes = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--") {
      after_dashes = true;
    } else if (a == "--baud" && i + 1 < argc) {
      baud = std::atol(argv[++i]);
    } else if (a == "--size" && i + 1 < argc) {
      options.width = std::atoi(argv[++i]);
      const char* x = std::strchr(argv[i], 'x');
      options.height = x != nullptr ? std::atoi(x + 1) : options.width;
    } else if (a == "--format" && i + 1 < argc) {
      const std::string f = argv[++i];
      options.format = (f == "p6" || f == "P6") ? minrt::PpmFormat::kP6 : minrt::PpmFormat::kP3;
    } else if (a.rfind("--protocol=", 0) == 0) {
      protocol = a.substr(11);
    } else if (a == "--endian=big") {
      big_endian = true;
    }
    (void)after_dashes;
  }
  Board board;
  board.baud = baud;
  board.fd = open_pty_and_wait();
  if (board.fd < 0) {
    std::perror("standin-board: pty");
    return 1;
  }
  minrt::ByteSink sink{&Board::write_fn, &board};
  minrt::host::Variant variant{minrt::host::Precision::kFloat, minrt::host::ShimSet::kPortable};
  minrt::Diagnostic error;
  minrt::RenderStatus st = minrt::RenderStatus::kOk;

  auto render_from = [&](minrt::ByteSource src, minrt::ByteSink out) {
    return minrt::host::render_variant(variant, src, out, options, error, minrt::WarningSink{});
  };
  auto send_error = [&] {
    std::string line = MINRT_ERROR_MARKER;
    if (error.has_pos) line += std::to_string(error.pos.line) + ":" + std::to_string(error.pos.col) + ": ";
    line += error.message;
    line += "\n";
    board.put(reinterpret_cast<const uint8_t*>(line.data()), line.size());
  };

  if (protocol == "raw") {
    // The CRC-32 trailer when the host asks for it, as the firmware does.
    const minrt::ByteSource line{&Board::read_fn, &board};
    minrt::PeekSource request(line);
    const int lead = request.first_nonblank();
    // A checked upload is held and checked first (protocol/scene_check.hpp).
    std::vector<uint8_t> memory(64 * 1024 * 1024);
    minrt::Arena arena(memory.data(), memory.size());
    minrt::send::scene_check::CheckedUpload upload;
    if (lead == MINRT_SCENE_CHECK_REQUEST) {
      const minrt::ByteSource binary{&Board::read_binary_fn, &board};
      if (upload.receive_raw(binary, arena, error) != minrt::send::scene_check::Result::kOk) {
        send_error();
        wait_for_hangup(board.fd);
        ::close(board.fd);
        return 2;
      }
    }
    const bool checked = lead == MINRT_CHECK_REQUEST || upload.received();
    minrt::send::raw_check::CheckedSink out(sink, checked);
    st = render_from(upload.received() ? upload.text() : checked ? line : request.source(), out.sink());
    if (st != minrt::RenderStatus::kOk) send_error();
    else out.end();
  } else {
    standin::Link link{&board, [](void* c, uint8_t* p, size_t n) { return static_cast<Board*>(c)->read_exact(p, n); },
                       [](void* c, const uint8_t* p, size_t n) { static_cast<Board*>(c)->put(p, n); },
                       board.fd};
    standin::RenderFn render = [&](minrt::ByteSource src, minrt::ByteSink out, minrt::Diagnostic& err) {
      err = minrt::Diagnostic{};
      return minrt::host::render_variant(variant, src, out, options, err, minrt::WarningSink{}) ==
             minrt::RenderStatus::kOk;
    };
    bool ok = false;
    if (protocol == "course") {
      standin::CourseRenderFn render_words = [&](minrt::ByteSource words, minrt::ByteSink out,
                                                 minrt::Diagnostic& err) {
        err = minrt::Diagnostic{};
        return minrt::host::render_variant_course_words(variant, words, big_endian, out, options, err,
                                                        minrt::WarningSink{}) == minrt::RenderStatus::kOk;
      };
      ok = standin::serve_course(link, render_words, big_endian);
    } else if (protocol == "framed") {
      standin::RowRenderFn render_rows = [&](minrt::ByteSource src, const minrt::RowSink& rows,
                                             minrt::Diagnostic& err) {
        err = minrt::Diagnostic{};
        return minrt::host::render_variant_rows(variant, src, rows, options, err, minrt::WarningSink{}) ==
               minrt::RenderStatus::kOk;
      };
      ok = standin::serve_framed(link, options, render_rows);
    }
    st = ok ? minrt::RenderStatus::kOk : minrt::RenderStatus::kSceneError;
  }
  wait_for_hangup(board.fd);
  ::close(board.fd);
  return st == minrt::RenderStatus::kOk ? 0 : 2;
}
