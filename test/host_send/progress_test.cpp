// The progress lines: host-send's three phases, minrt's rows, and the
// smoothed rate their times left come from (posix/progress_line.hpp).
#include <catch2/catch.hpp>

#include "posix/progress_line.hpp"
#include "progress.hpp"

using minrt::host::RateEstimate;
using minrt::send::Progress;

TEST_CASE("host-send's lines: upload, the wait with its timeout, the reply", "[progress]") {
  CHECK(Progress::format_upload(2500, 10000, 1000, 7.5) ==
        "sending the scene [#####...............]  25%  2500/10000 B  1.0 kB/s  ETA 0:08");
  CHECK(Progress::format_wait(120, 7.2) == "scene sent; waiting for the board's first byte, 120 s max (0:07 so far)");
  // The course protocol's start: the request bytes, then the program.
  CHECK(Progress::format_handshake("0x99 (program request)", 30, 3.4) ==
        "waiting for the board's 0x99 (program request), 30 s max (0:03 so far)");
  CHECK(Progress::format_program(40960, 81920) == "sending the program [##########..........]  50%  40960/81920 B");
  CHECK(Progress::format_reply(11520, 23040, 5, 10, 11520, 115200, 1.0) ==
        "receiving [##########..........]  50%  5/10 rows  11.5 kB/s (100.0% of 8N1)  ETA 0:01");
  // No rows known (the fraction from the bytes), no baud rate, no estimate yet.
  CHECK(Progress::format_reply(25, 100, 0, 0, 0, 0, -1) == "receiving [#####...............]  25%  0.0 kB/s  ETA ?");
}

TEST_CASE("minrt's line: percentage, rows and time left", "[progress]") {
  CHECK(minrt::host::WorkProgress::format("minrt: rendering", 1843, 4096, "rows", 3725) ==
        "minrt: rendering [########............]  44%  1843/4096 rows  ETA 1:02:05");
  CHECK(minrt::host::progress_bar(1.5, 4) == "[####]");
  CHECK(minrt::host::progress_bar(-1, 4) == "[....]");
}

TEST_CASE("the rate is unknown during the warm-up, then the average", "[progress]") {
  RateEstimate r(4.0);
  r.reset(10, 0);
  r.sample(10.5, 50);
  CHECK(r.seconds_left(100) < 0);  // half a second is too little to tell
  CHECK(r.rate() == Approx(100));  // what is shown meanwhile: the average so far
  r.sample(11, 100);
  CHECK(r.rate() == Approx(100));
  CHECK(r.seconds_left(500) == Approx(5));
  // Nothing done in the warm-up: still unknown.
  RateEstimate idle;
  idle.reset(0, 0);
  idle.sample(3, 0);
  CHECK(idle.seconds_left(10) < 0);
}

TEST_CASE("the smoothed rate follows a change within a few time constants, not the average since the start",
          "[progress]") {
  // 60 s at 100 units/s, then 10 units/s: the average since the start would
  // still say ~70/s after 20 s more; the estimate is near 10/s.
  RateEstimate r(4.0);
  r.reset(0, 0);
  double done = 0;
  for (double t = 0.2; t <= 60.0001; t += 0.2) r.sample(t, done += 20);
  CHECK(r.rate() == Approx(100).epsilon(0.01));
  for (double t = 60.2; t <= 80.0001; t += 0.2) r.sample(t, done += 2);
  CHECK(r.rate() < 11);
  CHECK(r.rate() > 9.9);
  CHECK(r.seconds_left(100) == Approx(100 / r.rate()));
  // Bursts (all of a second's work at once) give about the same rate as a steady flow.
  RateEstimate bursty(4.0);
  bursty.reset(0, 0);
  done = 0;
  for (int i = 1; i <= 300; ++i) bursty.sample(i * 0.2, done += (i % 5 == 0 ? 100 : 0));
  CHECK(bursty.rate() == Approx(100).epsilon(0.25));
}

TEST_CASE("clock text", "[progress]") {
  CHECK(minrt::host::clock_text(0) == "0:00");
  CHECK(minrt::host::clock_text(59.6) == "1:00");
  CHECK(minrt::host::clock_text(754) == "12:34");
  CHECK(minrt::host::clock_text(3723) == "1:02:03");
  CHECK(minrt::host::eta_text(-1) == "ETA ?");
}
