// A damaged line (tools/fault_relay) to the stand-in board and to the
// firmware in firmware-sim: framed mode delivers the exact image in every
// seeded run; raw mode notices the damage and writes nothing.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "damaged_line.hpp"
#include "fault_model.hpp"
#include "test_support.hpp"

namespace {

std::string ball() { return hs_test::shared_dir() + "/scenes/ball.sld"; }

using hs_test::Board;
using hs_test::DamagedLine;

// Six seeded runs of drops, flips, duplicates, delays and stalls (both
// ways in the last two): framed mode must deliver the exact image each time.
void check_framed_over_damage(Board who) {
  const std::string ref = hs_test::reference_image(ball(), "32x32", "p6");
  hs_test::TempDir dir;
  for (int seed = 1; seed <= 6; ++seed) {
    std::vector<std::string> faults{"--seed",  std::to_string(seed), "--drop", "0.002", "--flip", "0.002", "--dup",
                                    "0.002",   "--stall",            "0.0005", "--stall-ms", "200", "--delay", "0.001"};
    if (seed > 4) faults.push_back("--both-ways");
    DamagedLine line(who, "framed", faults);
    const std::string out = dir.file("f" + std::to_string(seed) + ".ppm");
    const auto r = hs_test::run({HS_HOST_SEND, "--no-handshake", "--port", line.port, "--protocol", "framed", "--size", "32x32",
                                 "--format", "p6", ball(), "-o", out, "--idle-timeout", "20"});
    INFO("seed " << seed << "\n" << r.err << line.relay.output());
    REQUIRE(r.status == 0);
    CHECK(hs_test::read_file(out) == ref);
  }
}

// Byte losses, duplicates, a damaged header, and stalls longer than the
// idle timeout: raw mode either got the exact image or fails with status 1
// and writes nothing. (A flipped pixel byte cannot be seen by raw mode;
// that is what --expect-sha256 and the framed protocol are for.)
void check_raw_over_damage(Board who) {
  const std::string ref = hs_test::reference_image(ball(), "32x32", "p6");
  hs_test::TempDir dir;
  int detected = 0;
  const std::vector<std::vector<std::string>> runs = {
      {"--drop", "0.003"},  {"--drop", "0.01"},   {"--dup", "0.003"},
      {"--dup", "0.01"},    {"--flip", "0.5"},
      {"--stall", "0.002", "--stall-ms", "1500"},
  };
  int seed = 0;
  for (const auto& f : runs) {
    ++seed;
    std::vector<std::string> faults{"--seed", std::to_string(seed)};
    faults.insert(faults.end(), f.begin(), f.end());
    DamagedLine line(who, "raw", faults);
    const std::string out = dir.file("r" + std::to_string(seed) + ".ppm");
    const auto r = hs_test::run({HS_HOST_SEND, "--no-handshake", "--port", line.port, "--size", "32x32", "--format", "p6", ball(), "-o",
                                 out, "--idle-timeout", "1"});
    INFO("run " << seed << "\n" << r.err << line.relay.output());
    if (r.status == 0) {
      CHECK(hs_test::read_file(out) == ref);  // the faults missed the image
    } else {
      ++detected;
      CHECK(r.status == 1);
      CHECK_FALSE(hs_test::file_exists(out));
      CHECK_THAT(r.err, Catch::Contains("truncated") || Catch::Contains("header") || Catch::Contains("idle") ||
                            Catch::Contains("unexpected") || Catch::Contains("image is") || Catch::Contains("magic") ||
                            Catch::Contains("damaged") || Catch::Contains("CRC-32") ||
                            Catch::Contains("does not start"));
    }
  }
  CHECK(detected >= 5);
}

}  // namespace

TEST_CASE("the fault model is repeatable and roughly at its rates", "[fault]") {
  fault_relay::FaultRates rates;
  rates.drop = 0.01;
  rates.flip = 0.02;
  rates.dup = 0.03;
  fault_relay::FaultModel a(42, rates), b(42, rates), c(43, rates);
  bool differs = false;
  for (int i = 0; i < 100000; ++i) {
    const auto x = a.next(static_cast<uint8_t>(i)), y = b.next(static_cast<uint8_t>(i)), z = c.next(static_cast<uint8_t>(i));
    REQUIRE(x.copies == y.copies);
    REQUIRE(x.value == y.value);
    if (x.copies != z.copies || x.value != z.value) differs = true;
  }
  CHECK(differs);
  CHECK(a.counts().dropped == Approx(1000).epsilon(0.15));
  CHECK(a.counts().flipped == Approx(0.99 * 2000).epsilon(0.15));
  CHECK(a.counts().duplicated == Approx(0.99 * 3000).epsilon(0.15));
  rates.skip = 100000;
  fault_relay::FaultModel clean(1, rates);
  for (int i = 0; i < 1000; ++i) CHECK(clean.next(7).copies == 1);
}

TEST_CASE("framed mode delivers the exact image over a damaged line", "[fault][framed]") {
  check_framed_over_damage(Board::kStandin);
}

TEST_CASE("raw mode reports a damaged line instead of writing a wrong image", "[fault][raw]") {
  check_raw_over_damage(Board::kStandin);
}

TEST_CASE("framed mode delivers the firmware's exact image over a damaged line", "[fault][framed][firmware]") {
  HS_NEEDS_FIRMWARE();
  check_framed_over_damage(Board::kFirmware);
}

TEST_CASE("raw mode from the firmware over a damaged line never writes a wrong image", "[fault][raw][firmware]") {
  HS_NEEDS_FIRMWARE();
  check_raw_over_damage(Board::kFirmware);
}
