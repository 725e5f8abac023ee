// One status line on standard error while the image comes in: bytes, rows,
// rate, share of the 8N1 limit, ETA. Silent unless enabled (the CLI enables
// it only when standard error is a terminal).
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace minrt::send {

class Progress {
 public:
  Progress(bool enabled, std::uint64_t expected_bytes, int total_rows, std::uint32_t baud);
  void start();  // first byte sent
  void update(std::uint64_t bytes, int rows);
  void note(const std::string& text);  // e.g. "waiting for the board"
  void finish();                       // clears the line

  // Text of the status line (for tests), independent of `enabled`.
  static std::string format(std::uint64_t bytes, std::uint64_t expected, int rows, int total_rows, double seconds,
                            std::uint32_t baud);

 private:
  void draw(const std::string& text);

  bool enabled_;
  std::uint64_t expected_;
  int total_rows_;
  std::uint32_t baud_;
  std::chrono::steady_clock::time_point t0_, last_;
  bool started_ = false;
  bool drawn_ = false;
};

}  // namespace minrt::send
