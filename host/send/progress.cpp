#include "progress.hpp"

#include <cstdio>

namespace minrt::send {

using minrt::host::clock_text;
using minrt::host::eta_text;
using minrt::host::progress_bar;

namespace {

std::string percent(std::uint64_t done, std::uint64_t total) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%3d%%", static_cast<int>(total > 0 ? (done < total ? done : total) * 100 / total : 0));
  return buf;
}

std::string rate_text(double bytes_per_s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f kB/s", bytes_per_s / 1000.0);
  return buf;
}

}  // namespace

Progress::Progress(bool enabled, std::uint64_t expected_bytes, int total_rows, std::uint32_t baud,
                   int first_byte_timeout_s)
    : line_(enabled), expected_(expected_bytes), total_rows_(total_rows), baud_(baud),
      first_byte_timeout_s_(first_byte_timeout_s) {}

std::string Progress::format_upload(std::uint64_t sent, std::uint64_t total, double rate, double seconds_left) {
  const double fraction = total > 0 ? static_cast<double>(sent) / static_cast<double>(total) : 1.0;
  return "sending the scene " + progress_bar(fraction) + " " + percent(sent, total) + "  " + std::to_string(sent) + "/" +
         std::to_string(total) + " B  " + rate_text(rate) + "  " + eta_text(seconds_left);
}

std::string Progress::format_wait(int timeout_s, double waited_s) {
  return "scene sent; waiting for the board's first byte, " + std::to_string(timeout_s) + " s max (" +
         clock_text(waited_s) + " so far)";
}

std::string Progress::format_handshake(const std::string& what, int timeout_s, double waited_s) {
  return "waiting for the board's " + what + ", " + std::to_string(timeout_s) + " s max (" + clock_text(waited_s) +
         " so far)";
}

std::string Progress::format_program(std::uint64_t sent, std::uint64_t total) {
  const double fraction = total > 0 ? static_cast<double>(sent) / static_cast<double>(total) : 1.0;
  return "sending the program " + progress_bar(fraction) + " " + percent(sent, total) + "  " + std::to_string(sent) +
         "/" + std::to_string(total) + " B";
}

std::string Progress::format_reply(std::uint64_t bytes, std::uint64_t expected, int rows, int total_rows, double rate,
                                   std::uint32_t baud, double seconds_left) {
  const std::uint64_t done = total_rows > 0 ? static_cast<std::uint64_t>(rows) : bytes;
  const std::uint64_t total = total_rows > 0 ? static_cast<std::uint64_t>(total_rows) : expected;
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
  std::string s = "receiving " + progress_bar(fraction) + " " + percent(done, total) + "  ";
  if (total_rows > 0) s += std::to_string(rows) + "/" + std::to_string(total_rows) + " rows  ";
  s += rate_text(rate);
  if (baud > 0) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " (%.1f%% of 8N1)", rate * 1000.0 / baud);
    s += buf;
  }
  return s + "  " + eta_text(seconds_left);
}

void Progress::start() {
  line_.restart();
  phase_ = Phase::kSending;
  phase_t0_ = 0;
  work_rate_.reset(0, 0);
}

void Progress::sending(std::uint64_t sent, std::uint64_t total) {
  if (!line_.enabled() || phase_ == Phase::kReceiving) return;
  const double t = line_.seconds();
  if (sent < total) {
    if (phase_ != Phase::kSending) start();
    if (!line_.due()) return;
    work_rate_.sample(t, static_cast<double>(sent));
    line_.draw(format_upload(sent, total, work_rate_.rate(),
                             work_rate_.seconds_left(static_cast<double>(total - sent))));
    return;
  }
  // Everything sent: say at once what is being waited for, and for how long.
  if (phase_ != Phase::kWaiting) {
    phase_ = Phase::kWaiting;
    phase_t0_ = t;
  } else if (!line_.due()) {
    return;
  }
  line_.draw(format_wait(first_byte_timeout_s_, t - phase_t0_));
}

void Progress::update(std::uint64_t bytes, int rows) {
  if (!line_.enabled()) return;
  const double t = line_.seconds();
  const bool by_rows = total_rows_ > 0;
  const double work = by_rows ? rows : static_cast<double>(bytes);
  if (phase_ != Phase::kReceiving) {
    phase_ = Phase::kReceiving;
    work_rate_.reset(t, work);
    bytes_rate_.reset(t, static_cast<double>(bytes));
  }
  if (!line_.due()) return;
  work_rate_.sample(t, work);
  bytes_rate_.sample(t, static_cast<double>(bytes));
  const double total = by_rows ? total_rows_ : static_cast<double>(expected_);
  line_.draw(format_reply(bytes, expected_, rows, total_rows_, bytes_rate_.rate(), baud_,
                          work_rate_.seconds_left(total > work ? total - work : 0)));
}

void Progress::handshake(const std::string& what, int timeout_s, double waited_s) {
  if (line_.enabled() && line_.due()) line_.draw(format_handshake(what, timeout_s, waited_s));
}

void Progress::sending_program(std::uint64_t sent, std::uint64_t total) {
  if (line_.enabled() && line_.due()) line_.draw(format_program(sent, total));
}

void Progress::finish() { line_.clear(); }

}  // namespace minrt::send
