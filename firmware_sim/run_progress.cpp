#include "run_progress.hpp"

#include <algorithm>
#include <chrono>
#include <csignal>

namespace fwsim {

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

extern "C" void on_interrupt(int) { g_interrupted = 1; }

// A slice is sized to take about this long: Ctrl-C and the line answer
// within it, while the end of a run, which costs a few milliseconds with a
// cycle model (the block costs are folded), stays a small share: 1.6% on a
// terminal, 0.4% elsewhere.
constexpr double kShownSliceSeconds = 0.25;
constexpr double kQuietSliceSeconds = 1.0;
constexpr uint64_t kFirstSlice = 1u << 22;
constexpr uint64_t kLargestSlice = uint64_t{1} << 32;
// The line appears once a run has lasted this long and is redrawn at most
// this often: a short run shows nothing.
constexpr double kLineAfterSeconds = 1.0;
constexpr double kRedrawSeconds = kShownSliceSeconds;

struct sigaction g_previous {};

}  // namespace

RunProgress::RunProgress(bool show, std::FILE* out) : show_(show), out_(out) {
  g_interrupted = 0;
  struct sigaction sa {};
  sa.sa_handler = &on_interrupt;
  sigemptyset(&sa.sa_mask);
  // No SA_RESTART: a host call the simulator waits in returns at once. The
  // handler goes back to the default after the first Ctrl-C, so a second one
  // ends the process however busy it is.
  sa.sa_flags = SA_RESETHAND;
  ::sigaction(SIGINT, &sa, &g_previous);
}

RunProgress::~RunProgress() {
  clear();
  ::sigaction(SIGINT, &g_previous, nullptr);
}

bool RunProgress::interrupted() const { return g_interrupted != 0; }

StopInfo RunProgress::run(Machine& m, uint64_t max_instructions) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  // A traced run is slow (a line per instruction): smaller slices, so a
  // trace whose writes fail stops it soon.
  const uint64_t smallest = failed_ ? kFirstSlice / 64 : kFirstSlice / 4;
  uint64_t slice = failed_ ? smallest : kFirstSlice;
  for (;;) {
    const uint64_t done = m.hart().instret;
    const bool last = max_instructions - done <= slice;
    const auto t0 = Clock::now();
    StopInfo s = m.run(last ? max_instructions : done + slice);
    // A slice ends at the first taken jump past its end, which may already
    // be past the limit: where one run would have stopped too.
    if (s.cause != StopCause::InstructionLimit || last || m.hart().instret > max_instructions) {
      clear();
      return s;
    }
    if (g_interrupted) {
      clear();
      return StopInfo{StopCause::None, m.hart().pc};
    }
    if (failed_ && failed_()) {
      clear();
      return StopInfo{StopCause::HostIo, m.hart().pc};
    }
    const auto t1 = Clock::now();
    const double took = std::chrono::duration<double>(t1 - t0).count();
    const double target = show_ ? kShownSliceSeconds : kQuietSliceSeconds;
    const double scaled = static_cast<double>(slice) * target / std::max(took, 1e-6);
    slice = std::clamp<uint64_t>(static_cast<uint64_t>(scaled), smallest, kLargestSlice);
    const double elapsed = std::chrono::duration<double>(t1 - start).count();
    if (show_ && elapsed >= kLineAfterSeconds && elapsed - last_draw_ >= kRedrawSeconds) draw(m.hart().instret, elapsed);
  }
}

void RunProgress::draw(uint64_t instructions, double seconds) {
  // \r and "erase to the end of the line": each update replaces the last.
  const double millions = static_cast<double>(instructions) * 1e-6;
  std::fprintf(out_, "\r\033[Kfirmware-sim: %.1f M instructions, %.0f MIPS, %.1f s", millions, millions / seconds,
               seconds);
  std::fflush(out_);
  drawn_ = true;
  last_draw_ = seconds;
}

void RunProgress::clear() {
  if (!drawn_) return;
  std::fputs("\r\033[K", out_);
  std::fflush(out_);
  drawn_ = false;
}

}  // namespace fwsim
