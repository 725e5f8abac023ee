#include "session_host.hpp"

#include <chrono>
#include <cstdio>

#include <minrt/serial_protocol.h>

#include "protocol/session.hpp"

namespace minrt::send {
namespace {

long long now_ms() {
  using namespace std::chrono;
  return duration_cast<milliseconds>(steady_clock::now().time_since_epoch()).count();
}

const std::string kIdentityHead = MINRT_SESSION_IDENTITY;
const std::string kAccepted = MINRT_SESSION_ACCEPTED;
const std::string kErrorMarker = MINRT_ERROR_MARKER;

// The identity line at `at` in `buf` (its lead), complete up to '\n':
// parsed into `id`; `damaged` when its CRC-32 does not match.
bool take_identity(const std::string& buf, std::size_t at, BoardIdentity& id, bool& damaged) {
  const std::size_t nl = buf.find('\n', at);
  if (nl == std::string::npos) return false;
  const std::string text = buf.substr(at + 1, nl - at - 1);
  minrt::session::LineReader line(text.data(), text.size());
  if (!line.check()) {
    damaged = true;
    return true;
  }
  const char* word;
  std::size_t word_n;
  line.head(word, word_n);
  id.line = text;
  id.fields.clear();
  const char *key, *value;
  std::size_t key_n, value_n;
  while (line.next(key, key_n, value, value_n)) id.fields[std::string(key, key_n)] = std::string(value, value_n);
  return true;
}

// Reads until the line has been quiet for `quiet_ms`, at most until
// `deadline`; the count of bytes read, -1 on a link error.
long drain_until_quiet(SerialPort& port, int quiet_ms, long long deadline, bool& still_sending) {
  char buf[4096];
  long total = 0;
  still_sending = false;
  for (;;) {
    const long long left = deadline - now_ms();
    if (left <= 0) {
      still_sending = true;
      return total;
    }
    const long n = port.read_some(buf, sizeof buf, static_cast<int>(left < quiet_ms ? left : quiet_ms));
    if (n < 0) return -1;
    if (n == 0) return total;
    total += n;
  }
}

std::string baud_text(unsigned baud) { return "-b " + std::to_string(baud); }

}  // namespace

GreetResult greet_board(SerialPort& port, unsigned baud, int answer_ms, int attempts, int drain_ms) {
  GreetResult r;
  port.flush_input();
  const long long drain_deadline = now_ms() + drain_ms;
  long drained = 0;
  std::size_t garbage = 0;
  bool damaged_seen = false;
  for (int attempt = 0; attempt < attempts;) {
    if (!port.write_all(MINRT_SESSION_GREETING, MINRT_SESSION_GREETING_SIZE, 2000)) {
      r.status = GreetResult::Status::kLinkError;
      r.message = "cannot write the greeting to " + port.device() + " (the port or its adapter went away?)";
      return r;
    }
    std::string buf;
    // Each try waits twice as long as the one before: a board still inside
    // the upload of a host that died takes the greeting as scene bytes, and
    // answers only once its idle count has run out.
    const long long deadline = now_ms() + (static_cast<long long>(answer_ms) << attempt);
    bool more_than_an_answer = false;
    while (now_ms() < deadline) {
      char c;
      // An answer comes in one burst: bytes, then 0.3 s of quiet, end it.
      const long long left = deadline - now_ms();
      const long n = port.read_some(&c, 1, static_cast<int>(buf.empty() || left < 300 ? left : 300));
      if (n < 0) {
        r.status = GreetResult::Status::kLinkError;
        r.message = "lost " + port.device() + " while waiting for the board's identity";
        return r;
      }
      if (n == 0) break;
      buf.push_back(c);
      const std::size_t at = buf.rfind(kIdentityHead);
      bool damaged = false;
      if (at != std::string::npos && take_identity(buf, at, r.identity, damaged)) {
        if (!damaged) {
          r.status = GreetResult::Status::kOk;
          garbage += at;
          drained += static_cast<long>(at);
          if (drained > 0)
            r.note = "drained " + std::to_string(drained) + " bytes of an earlier reply before the board answered";
          return r;
        }
        damaged_seen = true;
        buf.clear();
      }
      // An image or a long error line: an earlier reply still coming.
      if (buf.size() > 2 * MINRT_SESSION_LINE_MAX || buf.find(kErrorMarker) != std::string::npos) {
        more_than_an_answer = true;
        break;
      }
    }
    if (buf.empty() && !more_than_an_answer) {
      ++attempt;
      continue;
    }
    if (more_than_an_answer) {
      bool still_sending = false;
      const long n = drain_until_quiet(port, 500, drain_deadline, still_sending);
      if (n < 0) {
        r.status = GreetResult::Status::kLinkError;
        r.message = "lost " + port.device() + " while draining an earlier reply";
        return r;
      }
      drained += static_cast<long>(buf.size()) + n;
      if (still_sending) {
        r.status = GreetResult::Status::kBusy;
        r.message = "the board on " + port.device() + " is still sending an earlier reply (" + std::to_string(drained) +
                    " bytes drained in " + std::to_string(drain_ms / 1000) +
                    " s): wait for it to end and run again, or reset the board";
        return r;
      }
      continue;  // greet again, not counted as a try
    }
    garbage += buf.size();
    ++attempt;
  }
  if (damaged_seen || garbage > 0) {
    r.status = GreetResult::Status::kGarbled;
    r.message = "garbled answer from the board on " + port.device() + " (" + std::to_string(garbage) +
                " bytes, no valid identity line" + (damaged_seen ? ", a damaged one" : "") +
                "): the baud rate likely differs from the board's (" + baud_text(baud) +
                "; check the board's UART divisor for its clock), or the line is noisy";
    return r;
  }
  r.status = GreetResult::Status::kSilent;
  r.message = "no answer from the board on " + port.device() + " to " + std::to_string(attempts) + " greetings in " +
              std::to_string(((answer_ms << attempts) - answer_ms) / 1000) + " s: check that it is powered and out of reset, that it runs the minrt firmware, the cable "
              "(board TX to adapter RX and back) and the baud rate (" +
              baud_text(baud) + " must match the board's UART divisor); a firmware without the session needs --no-handshake";
  return r;
}

bool send_run_options(SerialPort& port, const RunOptions& o, std::string& error, bool& refused, int answer_ms) {
  refused = false;
  minrt::session::LineWriter line(MINRT_SESSION_OPTIONS);
  const std::string size = std::to_string(o.width) + "x" + std::to_string(o.height);
  line.field("size", size.c_str())
      .field("format", o.p6 ? "p6" : "p3")
      .field("protocol", o.protocol)
      .field("endian", o.big_endian ? "big" : "little");
  line.finish();
  if (!port.write_all(line.data(), line.size(), 2000)) {
    error = "cannot write the run's options to " + port.device();
    return false;
  }
  // One byte at a time: what follows the acceptance (the course board's
  // 0x99) belongs to the protocol.
  std::string buf;
  const long long deadline = now_ms() + answer_ms;
  while (now_ms() < deadline) {
    char c;
    const long n = port.read_some(&c, 1, static_cast<int>(deadline - now_ms()));
    if (n < 0) {
      error = "lost " + port.device() + " while waiting for the board to accept the options";
      return false;
    }
    if (n == 0) break;
    buf.push_back(c);
    if (c != '\n') continue;
    if (buf.size() >= kAccepted.size() && buf.compare(buf.size() - kAccepted.size(), kAccepted.size(), kAccepted) == 0)
      return true;
    const std::size_t at = buf.find(kErrorMarker);
    if (at != std::string::npos) {
      refused = true;
      error = "the board refused the run's options: " + buf.substr(at + kErrorMarker.size(), buf.size() - at - kErrorMarker.size() - 1);
      return false;
    }
    buf.clear();  // a line before the answer (an identity for a greeting sent twice)
  }
  error = "the board on " + port.device() + " answered the greeting but not the run's options within " +
          std::to_string(answer_ms / 1000) + " s: reset the board and run again";
  return false;
}

std::string describe_identity(const BoardIdentity& id) {
  const std::string clock = id.get("clock");
  const std::string wait = id.get("wait");
  std::string s;
  s += "board: " + id.get("board") + " (" + id.get("isa") + ", clock " +
       (clock.empty() || clock == "0" ? std::string("not known") : clock + " Hz") + ")\n";
  s += "firmware: " + id.get("fw") + ", build " + id.get("build") + ", session v" + id.get("v") + "\n";
  s += "memory: " + id.get("ram") + " bytes RAM, " + id.get("arena") + " bytes arena\n";
  s += "protocols: " + id.get("protocols") + "\n";
  s += "defaults: " + id.get("size") + " " + id.get("format") + ", protocol " + id.get("protocol") + ", endian " +
       id.get("endian") + "\n";
  s += "after an image: " + std::string(id.get("after") == "halt" ? "halts" : "waits for the next scene") +
       "; waits for a host " + (wait.empty() || wait == "0" ? std::string("forever") : wait + " polls") + "\n";
  return s;
}

}  // namespace minrt::send
