// A progress line on standard error for long work: a bar, the percentage
// and the time left, redrawn in place a few times a second. The time left
// comes from the rate smoothed over the last seconds, not the average since
// the start, so that it follows work whose speed changes (an upload, then a
// render it waits for; a render's sky rows, then its objects) and does not
// jump with every burst. Drawn only when asked (the tools ask when standard
// error is a terminal); cut to the terminal's width so that it never wraps.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace minrt::host {

// Units per second, smoothed exponentially with a time constant.
class RateEstimate {
 public:
  explicit RateEstimate(double time_constant_s = 4.0) : tau_(time_constant_s) {}
  // Starts over at time `t` (seconds from any fixed origin) with `done` units.
  void reset(double t, double done);
  // The work has reached `done` units at time `t`.
  void sample(double t, double done);
  // The smoothed rate; during the warm-up the average so far.
  double rate() const;
  // Seconds for `left` more units; negative while the rate is not known
  // yet (less than kWarmUp seconds seen, or nothing done).
  double seconds_left(double left) const;

  static constexpr double kWarmUp = 1.0;

 private:
  double tau_;
  double t0_ = 0, done0_ = 0;  // where the estimate started
  double t_ = 0, done_ = 0;    // the last sample
  double rate_ = 0;
  bool known_ = false;
};

// "[#########...........]" for `fraction` (clamped to 0..1), `width` cells inside.
std::string progress_bar(double fraction, int width = 20);
// "0:07", "12:34", "1:02:03".
std::string clock_text(double seconds);
// "  45%  ETA 0:12" parts: " 45%", "ETA 0:12" or "ETA ?" when unknown.
std::string eta_text(double seconds_left);

// The line itself: draws, clears, limits how often.
class ProgressLine {
 public:
  // `show_after_s`: stay silent until the work has run this long (short
  // work prints nothing).
  explicit ProgressLine(bool enabled, double show_after_s = 0);
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  bool enabled() const { return enabled_; }
  // Restarts the clock `seconds()` counts from.
  void restart();
  double seconds() const;
  // Whether a redraw is due: enabled, past show_after, and kRedraw since
  // the last one.
  bool due() const;
  bool drawn() const { return drawn_; }
  void draw(const std::string& text);
  // Removes the line (before other output, and at the end).
  void clear();

  static constexpr double kRedraw = 0.2;

 private:
  using Clock = std::chrono::steady_clock;
  bool enabled_;
  double show_after_;
  Clock::time_point t0_, last_;
  bool drawn_ = false;
};

// Work counted in units from any thread (minrt's rows): each add() is one
// atomic increment, and the thread that finds a redraw due draws
// "LABEL [bar]  45%  DONE/TOTAL UNIT  ETA 0:12". With show_after_s the line
// appears only once the work has run that long and will take at least
// twice that in all.
class WorkProgress {
 public:
  WorkProgress(bool enabled, std::string label, std::string unit, std::uint64_t total, double show_after_s);
  void add(std::uint64_t n = 1);
  void finish() { line_.clear(); }
  // The text for `done` of `total` with `seconds_left` (tests).
  static std::string format(const std::string& label, std::uint64_t done, std::uint64_t total, const std::string& unit,
                            double seconds_left);

 private:
  ProgressLine line_;
  std::string label_, unit_;
  std::uint64_t total_;
  double show_after_;
  std::atomic<std::uint64_t> done_{0};
  std::mutex draw_;
  RateEstimate rate_;
};

}  // namespace minrt::host
