// Raw-protocol integrity: the receivers check the layout the
// firmware writes, and the CRC-32 trailer catches what the layout cannot:
// a dropped or doubled digit that leaves a valid number (`94` -> `4`,
// `16` -> `116`), a flipped pixel bit. Units on built replies, then the
// same single defects put on the line by fault-relay between host-send and
// the board (the stand-in, and the firmware in firmware-sim).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <minrt/serial_protocol.h>

#include "bmp_receiver.hpp"
#include "checked_reply.hpp"
#include "core/image/bmp_writer.hpp"
#include "damaged_line.hpp"
#include "ppm_receiver.hpp"
#include "protocol/raw_check.hpp"
#include "test_support.hpp"

using minrt::send::BmpReceiver;
using minrt::send::CheckedReply;
using minrt::send::ImageSpec;
using minrt::send::PpmKind;
using minrt::send::PpmReceiver;
using minrt::send::RawCheck;

namespace {

const std::uint8_t* bytes_of(const std::string& s) { return reinterpret_cast<const std::uint8_t*>(s.data()); }

// A 4x2 P3 image in the firmware's layout holding the values 94 and 16.
std::string p3_with_94_and_16() {
  return "P3\n4 2 255\n"
         "0 0 0\n94 0 0\n243 16 16\n255 255 255\n"
         "1 2 3\n16 94 200\n7 0 10\n99 100 101\n";
}

std::string p6_image(int w, int h) {
  std::string s = "P6\n" + std::to_string(w) + " " + std::to_string(h) + " 255\n";
  for (int i = 0; i < w * h * 3; ++i) s.push_back(static_cast<char>((i * 37) & 0xFF));
  return s;
}

// What the board sends when asked for the trailer: the announce byte, the
// image, the trailer over the image (protocol/raw_check.hpp's own sink).
std::string checked_reply_of(const std::string& image) {
  std::string out;
  minrt::ByteSink sink{[](void* ctx, const std::uint8_t* d, std::size_t n) {
                         static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(d), n);
                       },
                       &out};
  minrt::send::raw_check::CheckedSink checked(sink, true);
  checked.sink().put(bytes_of(image), image.size());
  checked.end();
  return out;
}

std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

struct Outcome {
  bool done = false, failed = false, checked = false;
  std::string message, image;
};

template <class Receiver>
Outcome receive(Receiver& inner, const std::string& reply, RawCheck mode, std::size_t chunk = 7) {
  CheckedReply<Receiver> rx(inner, mode);
  for (std::size_t at = 0; at < reply.size() && !rx.done() && !rx.failed() && !rx.firmware_error(); at += chunk)
    rx.feed(bytes_of(reply) + at, std::min(chunk, reply.size() - at));
  if (!rx.done() && !rx.failed() && !rx.firmware_error()) rx.finish();
  return Outcome{rx.done(), rx.failed(), rx.checked(), rx.message(), rx.image()};
}

Outcome receive_p3(const std::string& reply, RawCheck mode = RawCheck::kAuto) {
  PpmReceiver inner(ImageSpec{4, 2, PpmKind::kP3});
  return receive(inner, reply, mode);
}

// Feeds a plain P3 (no trailer) to the receiver alone.
PpmReceiver plain_p3(const std::string& image) {
  PpmReceiver rx(ImageSpec{4, 2, PpmKind::kP3});
  rx.feed(bytes_of(image), image.size());
  if (!rx.done() && !rx.failed()) rx.finish();
  return rx;
}

}  // namespace

TEST_CASE("raw P3 with the trailer: an intact reply is the exact image, checked", "[raw][crc]") {
  const std::string image = p3_with_94_and_16();
  for (std::size_t chunk : {1u, 5u, 4096u}) {
    PpmReceiver inner(ImageSpec{4, 2, PpmKind::kP3});
    const Outcome o = receive(inner, checked_reply_of(image), RawCheck::kAuto, chunk);
    REQUIRE(o.done);
    CHECK(o.checked);
    CHECK(o.image == image);
  }
}

TEST_CASE("raw P3: a dropped digit (94 -> 4) or a doubled one (16 -> 116) is caught by the CRC-32 trailer",
          "[raw][crc]") {
  const std::string image = p3_with_94_and_16();
  const std::string reply = checked_reply_of(image);
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\n94 0 0\n", "\n4 0 0\n"}, {" 16 16\n", " 116 16\n"}, {"\n16 94", "\n16 4"}, {"243", "43"}}) {
    INFO(from << " -> " << to);
    const std::string damaged = replace_once(reply, from, to);
    // The layout alone cannot see it: the damaged image is a valid P3.
    const std::string damaged_image = replace_once(image, from, to);
    CHECK(plain_p3(damaged_image).done());
    const Outcome o = receive_p3(damaged);
    CHECK_FALSE(o.done);
    CHECK(o.failed);
    CHECK_THAT(o.message, Catch::Contains("CRC-32") || Catch::Contains("bytes arrived"));
  }
}

TEST_CASE("raw P3 layout: lost or doubled separators and doubled zeros fail without a trailer", "[raw][ppm]") {
  const std::string image = p3_with_94_and_16();
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"1 2 3\n", "12 3\n"},        // a lost space: two values on the line
           {"1 2 3\n", "1  2 3\n"},      // a doubled space
           {"1 2 3\n", "1 2 3\n\n"},     // a doubled newline
           {"\n1 2 3\n", "\n1 2 3 "},    // a lost newline... then a space where it was
           {"\n1 2 3\n", "\n1 2 3"},     // a lost newline: four values on a line
           {"\n0 0 0\n", "\n00 0 0\n"},  // a doubled 0
           {"7 0 10", "7 0 010"},        // a leading zero
           {"243", "2443"},              // above 255
           {"99 100", "99\t100"}}) {     // not the writer's separator
    INFO(from << " -> " << to);
    const PpmReceiver rx = plain_p3(replace_once(image, from, to));
    CHECK(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains("P3 pixel data damaged") || Catch::Contains("truncated"));
  }
  const PpmReceiver ok = plain_p3(image);
  CHECK(ok.done());
}

TEST_CASE("raw P6 with the trailer: a flipped, dropped or doubled byte is caught", "[raw][crc]") {
  const std::string image = p6_image(5, 4);
  const std::string reply = checked_reply_of(image);
  const std::size_t pixel = 1 + 11 + 17;  // a pixel byte in the reply (after the announce byte and header)
  std::vector<std::string> damaged;
  std::string flipped = reply;
  flipped[pixel] = static_cast<char>(flipped[pixel] ^ 0x10);
  damaged.push_back(flipped);
  damaged.push_back(std::string(reply).erase(pixel, 1));
  damaged.push_back(std::string(reply).insert(pixel, 1, reply[pixel]));
  std::string trailer_flip = reply;
  trailer_flip[reply.size() - 2] = static_cast<char>(trailer_flip[reply.size() - 2] ^ 1);
  damaged.push_back(trailer_flip);
  damaged.push_back(reply.substr(0, reply.size() - 3));  // trailer cut off
  for (std::size_t i = 0; i < damaged.size(); ++i) {
    INFO("case " << i);
    PpmReceiver inner(ImageSpec{5, 4, PpmKind::kP6});
    const Outcome o = receive(inner, damaged[i], RawCheck::kAuto);
    CHECK_FALSE(o.done);
    CHECK(o.failed);
  }
  PpmReceiver inner(ImageSpec{5, 4, PpmKind::kP6});
  const Outcome o = receive(inner, reply, RawCheck::kAuto);
  CHECK(o.done);
  CHECK(o.image == image);
}

TEST_CASE("raw: --check refuses an image without the trailer, the default takes it unchecked", "[raw][crc]") {
  const std::string image = p3_with_94_and_16();
  const Outcome required = receive_p3(image, RawCheck::kRequire);
  CHECK(required.failed);
  CHECK_THAT(required.message, Catch::Contains("did not announce"));
  const Outcome automatic = receive_p3(image, RawCheck::kAuto);
  CHECK(automatic.done);
  CHECK_FALSE(automatic.checked);
  CHECK(automatic.image == image);
  // An error line is not an image: no announce byte, no trailer, any mode.
  for (RawCheck mode : {RawCheck::kAuto, RawCheck::kRequire}) {
    PpmReceiver inner(ImageSpec{4, 2, PpmKind::kP3});
    CheckedReply<PpmReceiver> rx(inner, mode);
    const std::string line = std::string(MINRT_ERROR_MARKER) + "3:1: bad\n";
    rx.feed(bytes_of(line), line.size());
    CHECK(rx.firmware_error());
    CHECK(rx.message() == "3:1: bad");
  }
  // An announced image whose trailer never comes is not complete.
  const Outcome cut = receive_p3(checked_reply_of(image).substr(0, image.size() + 1));
  CHECK(cut.failed);
  CHECK_THAT(cut.message, Catch::Contains("trailer is cut off"));
}

TEST_CASE("raw BMP: a lost or doubled byte shows as a pixel that is not opaque", "[raw][bmp]") {
  std::string bmp;
  minrt::ByteSink sink{[](void* ctx, const std::uint8_t* d, std::size_t n) {
                         static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(d), n);
                       },
                       &bmp};
  minrt::BmpWriter writer(sink);
  writer.begin(3, 2);
  const std::uint8_t row[12] = {10, 20, 30, 255, 40, 50, 60, 255, 70, 80, 90, 255};
  writer.row(0, row);
  writer.row(1, row);
  writer.end();
  {
    BmpReceiver rx;
    CHECK(rx.feed(bytes_of(bmp), bmp.size()) == bmp.size());
    CHECK(rx.done());
  }
  for (const std::string& damaged : {std::string(bmp).erase(54 + 5, 1), std::string(bmp).insert(54 + 1, 1, '\x14')}) {
    BmpReceiver rx;
    rx.feed(bytes_of(damaged), damaged.size());
    CHECK(rx.failed());
    CHECK_THAT(rx.message(), Catch::Contains("not opaque"));
  }
}

// ---- The same defects on the line, host-send against a board. ----

namespace {

std::string ball() { return hs_test::shared_dir() + "/scenes/ball.sld"; }

// host-send over a line that damages exactly one board->host byte.
hs_test::RunResult send_over(hs_test::Board who, const std::string& format, const std::vector<std::string>& fault,
                             const std::vector<std::string>& extra, const std::string& out) {
  hs_test::DamagedLine line(who, "raw", fault, "32x32", format);
  std::vector<std::string> argv{HS_HOST_SEND, "--no-handshake", "--port", line.port, "--size", "32x32", "--format", format, ball(),
                                "-o",         out,      "--idle-timeout", "2"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  hs_test::RunResult r = hs_test::run(argv, 60);
  r.err += line.report();
  return r;
}

// Index in the reply (announce byte first) of the first digit of `value`
// standing as a whole number at the start of a line.
std::size_t reply_index_of_line_start(const std::string& ref, const std::string& value) {
  const std::size_t at = ref.find("\n" + value + " ");
  REQUIRE(at != std::string::npos);
  return 1 + at + 1;
}

void check_single_digit_faults(hs_test::Board who) {
  const std::string ref = hs_test::reference_image(ball(), "32x32", "p3");
  hs_test::TempDir dir;
  // 94 -> 4: drop the 9. 16 -> 116: send the 1 twice (" 16 " inside a line).
  const std::size_t nine = reply_index_of_line_start(ref, "94");
  const std::size_t sixteen = ref.find(" 16 ");
  REQUIRE(sixteen != std::string::npos);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases{
      {"94 -> 4", {"--drop-at", std::to_string(nine)}},
      {"16 -> 116", {"--dup-at", std::to_string(1 + sixteen + 1)}},
  };
  for (const auto& [what, fault] : cases) {
    const std::string out = dir.file("d.ppm");
    const auto r = send_over(who, "p3", fault, {}, out);
    INFO(what << "\n" << r.err);
    CHECK(r.status == 1);
    CHECK_FALSE(hs_test::file_exists(out));
    CHECK_THAT(r.err, Catch::Contains("CRC-32") || Catch::Contains("bytes arrived"));
    CHECK_THAT(r.err, Catch::Contains("1 dropped") || Catch::Contains("1 duplicated"));
  }
  // The undamaged line through the same relay: the exact image, checked.
  const std::string out = dir.file("ok.ppm");
  const auto r = send_over(who, "p3", {}, {}, out);
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(hs_test::read_file(out) == ref);
  CHECK_THAT(r.err, Catch::Contains("CRC-32 trailer checked"));
}

// The named blind spot: without the trailer (--no-check) raw P6 has no
// checksum, and a flipped pixel bit gives status 0 and a wrong image; with
// the trailer (the default) the same flip is refused.
void check_p6_flip(hs_test::Board who) {
  const std::string ref = hs_test::reference_image(ball(), "32x32", "p6");
  hs_test::TempDir dir;
  const std::size_t pixel = ref.size() / 2;
  const std::string unchecked = dir.file("u.ppm");
  const auto blind = send_over(who, "p6", {"--flip-at", std::to_string(pixel)}, {"--no-check"}, unchecked);
  INFO(blind.err);
  REQUIRE(blind.status == 0);
  std::string expected_wrong = ref;
  expected_wrong[pixel] = static_cast<char>(expected_wrong[pixel] ^ 1);
  CHECK(hs_test::read_file(unchecked) == expected_wrong);

  const std::string checked = dir.file("c.ppm");
  const auto caught = send_over(who, "p6", {"--flip-at", std::to_string(1 + pixel)}, {}, checked);
  INFO(caught.err);
  CHECK(caught.status == 1);
  CHECK_FALSE(hs_test::file_exists(checked));
  CHECK_THAT(caught.err, Catch::Contains("CRC-32 mismatch"));
}

}  // namespace

TEST_CASE("raw P3 from the stand-in board: 94 -> 4 and 16 -> 116 on the line give status 1 and no file",
          "[raw][crc][e2e]") {
  check_single_digit_faults(hs_test::Board::kStandin);
}

TEST_CASE("raw P3 from the firmware: 94 -> 4 and 16 -> 116 on the line give status 1 and no file",
          "[raw][crc][firmware]") {
  HS_NEEDS_FIRMWARE();
  check_single_digit_faults(hs_test::Board::kFirmware);
}

TEST_CASE("raw P6 from the firmware: a flipped bit passes only with --no-check", "[raw][crc][firmware]") {
  HS_NEEDS_FIRMWARE();
  check_p6_flip(hs_test::Board::kFirmware);
}

TEST_CASE("raw P6 from the stand-in board: a flipped bit passes only with --no-check", "[raw][crc][e2e]") {
  check_p6_flip(hs_test::Board::kStandin);
}

TEST_CASE("host-send --check is for the raw and course protocols only", "[raw][crc][cli]") {
  hs_test::TempDir dir;
  for (const char* protocol : {"framed"}) {
    const auto r = hs_test::run({HS_HOST_SEND, "--sim", "--protocol", protocol, "--check", ball(), "-o",
                                 dir.file("x.ppm")});
    INFO(r.err);
    CHECK(r.status == 2);
    CHECK_THAT(r.err, Catch::Contains("--check applies to --protocol raw and course"));
    CHECK_FALSE(hs_test::file_exists(dir.file("x.ppm")));
  }
}
