// host-send's status line on standard error, in three phases: the scene
// going out (bar, percentage, rate, time left), the wait for the board's
// first byte (how long so far, and the timeout), and the image coming in
// (bar, percentage of the rows, rows, rate, share of the 8N1 limit, time
// left). The times left come from rates smoothed over the last seconds
// (posix/progress_line.hpp). Silent unless enabled (the CLI enables it when
// standard error is a terminal, or with --progress).
#pragma once

#include <cstdint>
#include <string>

#include "posix/progress_line.hpp"

namespace minrt::send {

class Progress {
 public:
  // `expected_bytes` and `total_rows` describe the reply (rows 0: unknown,
  // the bytes then measure it); `baud` 0: no 8N1 share (a pty has no rate).
  Progress(bool enabled, std::uint64_t expected_bytes, int total_rows, std::uint32_t baud, int first_byte_timeout_s);
  void start();  // the scene's first byte is about to go out
  // The upload so far, on every turn of the transfer loop until the reply
  // starts; once all is sent this shows the wait for the first byte.
  void sending(std::uint64_t sent, std::uint64_t total);
  void update(std::uint64_t bytes, int rows);  // the reply so far
  // The course protocol's start: the wait for the board's request byte
  // `what` (at most `timeout_s`), and the program going out.
  void handshake(const std::string& what, int timeout_s, double waited_s);
  void sending_program(std::uint64_t sent, std::uint64_t total);
  void finish();                               // clears the line
  std::uint64_t expected_bytes() const { return expected_; }

  // The lines' texts (for tests), independent of `enabled`. Rates in bytes
  // per second; seconds_left < 0: not known yet.
  static std::string format_upload(std::uint64_t sent, std::uint64_t total, double rate, double seconds_left);
  static std::string format_wait(int timeout_s, double waited_s);
  static std::string format_handshake(const std::string& what, int timeout_s, double waited_s);
  static std::string format_program(std::uint64_t sent, std::uint64_t total);
  static std::string format_reply(std::uint64_t bytes, std::uint64_t expected, int rows, int total_rows, double rate,
                                  std::uint32_t baud, double seconds_left);

 private:
  enum class Phase { kIdle, kSending, kWaiting, kReceiving };

  minrt::host::ProgressLine line_;
  std::uint64_t expected_;
  int total_rows_;
  std::uint32_t baud_;
  int first_byte_timeout_s_;
  Phase phase_ = Phase::kIdle;
  double phase_t0_ = 0;
  minrt::host::RateEstimate work_rate_;   // upload bytes, or reply rows (bytes when rows are unknown)
  minrt::host::RateEstimate bytes_rate_;  // reply bytes, for the kB/s shown
};

}  // namespace minrt::send
