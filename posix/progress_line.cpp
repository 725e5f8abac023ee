#include "posix/progress_line.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace minrt::host {

void RateEstimate::reset(double t, double done) {
  t0_ = t_ = t;
  done0_ = done_ = done;
  rate_ = 0;
  known_ = false;
}

void RateEstimate::sample(double t, double done) {
  if (t <= t_) return;
  if (!known_) {
    // The first estimate: the average over the warm-up, then smoothing.
    if (t - t0_ >= kWarmUp && done > done0_) {
      rate_ = (done - done0_) / (t - t0_);
      known_ = true;
    }
  } else {
    const double dt = t - t_;
    const double weight = 1.0 - std::exp(-dt / tau_);
    rate_ += weight * ((done - done_) / dt - rate_);
  }
  t_ = t;
  done_ = done;
}

double RateEstimate::rate() const {
  if (known_) return rate_;
  return t_ > t0_ ? (done_ - done0_) / (t_ - t0_) : 0.0;
}

double RateEstimate::seconds_left(double left) const {
  if (!known_ || rate_ <= 0) return -1;
  return left > 0 ? left / rate_ : 0.0;
}

std::string progress_bar(double fraction, int width) {
  if (!(fraction > 0)) fraction = 0;
  if (fraction > 1) fraction = 1;
  const int full = static_cast<int>(fraction * width);
  return "[" + std::string(static_cast<std::size_t>(full), '#') + std::string(static_cast<std::size_t>(width - full), '.') +
         "]";
}

std::string clock_text(double seconds) {
  const long long s = seconds > 0 ? static_cast<long long>(std::llround(seconds)) : 0;
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%lld:%02lld:%02lld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%lld:%02lld", s / 60, s % 60);
  return buf;
}

std::string eta_text(double seconds_left) {
  return seconds_left < 0 ? "ETA ?" : "ETA " + clock_text(seconds_left);
}

ProgressLine::ProgressLine(bool enabled, double show_after_s) : enabled_(enabled), show_after_(show_after_s) {
  restart();
}

void ProgressLine::restart() { t0_ = last_ = Clock::now(); }

double ProgressLine::seconds() const { return std::chrono::duration<double>(Clock::now() - t0_).count(); }

bool ProgressLine::due() const {
  if (!enabled_) return false;
  const auto now = Clock::now();
  if (std::chrono::duration<double>(now - t0_).count() < show_after_) return false;
  return !drawn_ || std::chrono::duration<double>(now - last_).count() >= kRedraw;
}

void ProgressLine::draw(const std::string& text) {
  if (!enabled_) return;
  std::string shown = text;
  // A line longer than the terminal wraps, and the next \r returns only to
  // the start of its last part.
  winsize ws{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1 && shown.size() >= ws.ws_col)
    shown.resize(ws.ws_col - 1u);
  std::fprintf(stderr, "\r\033[K%s", shown.c_str());
  std::fflush(stderr);
  drawn_ = true;
  last_ = Clock::now();
}

void ProgressLine::clear() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

WorkProgress::WorkProgress(bool enabled, std::string label, std::string unit, std::uint64_t total,
                           double show_after_s)
    : line_(enabled, show_after_s),
      label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      show_after_(show_after_s) {
  rate_.reset(0, 0);
}

std::string WorkProgress::format(const std::string& label, std::uint64_t done, std::uint64_t total,
                                 const std::string& unit, double seconds_left) {
  const double fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0.0;
  char pct[16];
  std::snprintf(pct, sizeof pct, "%3d%%", static_cast<int>(total > 0 ? (done < total ? done : total) * 100 / total : 0));
  return label + " " + progress_bar(fraction) + " " + pct + "  " + std::to_string(done) + "/" + std::to_string(total) +
         " " + unit + "  " + eta_text(seconds_left);
}

void WorkProgress::add(std::uint64_t n) {
  const std::uint64_t done = done_.fetch_add(n, std::memory_order_relaxed) + n;
  if (!line_.enabled()) return;
  std::unique_lock<std::mutex> lock(draw_, std::try_to_lock);
  if (!lock.owns_lock() || !line_.due()) return;
  const double t = line_.seconds();
  rate_.sample(t, static_cast<double>(done));
  const double left = rate_.seconds_left(static_cast<double>(total_ - (done < total_ ? done : total_)));
  // Work that will be over by about twice the delay stays silent.
  if (!line_.drawn() && (left < 0 || t + left < 2 * show_after_)) return;
  line_.draw(format(label_, done, total_, unit_, left));
}

}  // namespace minrt::host
