#include "progress.hpp"

#include <cstdio>

namespace minrt::send {

Progress::Progress(bool enabled, std::uint64_t expected_bytes, int total_rows, std::uint32_t baud)
    : enabled_(enabled), expected_(expected_bytes), total_rows_(total_rows), baud_(baud) {}

void Progress::start() {
  t0_ = last_ = std::chrono::steady_clock::now();
  started_ = true;
}

std::string Progress::format(std::uint64_t bytes, std::uint64_t expected, int rows, int total_rows, double seconds,
                             std::uint32_t baud) {
  char buf[200];
  const double rate = seconds > 0 ? static_cast<double>(bytes) / seconds : 0.0;
  int n = std::snprintf(buf, sizeof buf, "%llu B  %d/%d rows  %.1f kB/s", static_cast<unsigned long long>(bytes), rows,
                        total_rows, rate / 1000.0);
  if (baud > 0 && n > 0 && n < static_cast<int>(sizeof buf))
    n += std::snprintf(buf + n, sizeof buf - n, " (%.1f%% of 8N1)", rate * 1000.0 / baud);
  if (rate > 0 && expected > bytes && n > 0 && n < static_cast<int>(sizeof buf)) {
    const double eta = static_cast<double>(expected - bytes) / rate;
    std::snprintf(buf + n, sizeof buf - n, "  ETA %d:%02d", static_cast<int>(eta) / 60, static_cast<int>(eta) % 60);
  }
  return buf;
}

void Progress::update(std::uint64_t bytes, int rows) {
  if (!enabled_ || !started_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  const double s = std::chrono::duration<double>(now - t0_).count();
  draw(format(bytes, expected_, rows, total_rows_, s, baud_));
}

void Progress::note(const std::string& text) {
  if (enabled_) draw(text);
}

void Progress::draw(const std::string& text) {
  std::fprintf(stderr, "\r\033[K%s", text.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (enabled_ && drawn_) {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }
  drawn_ = false;
}

}  // namespace minrt::send
