// The raw protocol's BMP receiver (Jaworski scenes): takes the core's BMP
// stream whole, refuses a header the firmware never writes, reports a cut
// and hands over the error line.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "bmp_receiver.hpp"
#include "core/image/bmp_writer.hpp"
#include "core/image/row_sink.hpp"

namespace {

std::string stream(int w, int h) {
  std::string bytes;
  minrt::BmpWriter bmp(minrt::ByteSink{
      [](void* ctx, const uint8_t* p, size_t n) { static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(p), n); },
      &bytes});
  // Opaque, as every pixel the firmware writes (the receiver checks it).
  std::vector<uint8_t> row(static_cast<size_t>(w) * 4, 9);
  for (size_t i = 3; i < row.size(); i += 4) row[i] = 255;
  bmp.begin(w, h);
  for (int y = 0; y < h; ++y) bmp.row(y, row.data());
  bmp.end();
  return bytes;
}

minrt::send::BmpReceiver fed(const std::string& bytes) {
  minrt::send::BmpReceiver rx;
  rx.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  rx.finish();
  return rx;
}

}  // namespace

TEST_CASE("BmpReceiver: whole, damaged, cut, error line", "[bmp][receiver]") {
  const std::string s = stream(7, 5);
  CHECK(s.size() == 54 + 7 * 5 * 4);
  minrt::send::BmpReceiver rx;
  CHECK(rx.feed(reinterpret_cast<const uint8_t*>(s.data()), s.size()) == s.size());
  CHECK(rx.done());
  CHECK(rx.rows_complete() == 5);
  std::string damaged = s;
  damaged[28] = 24;  // bits per pixel
  CHECK(fed(damaged).failed());
  const auto cut = fed(s.substr(0, s.size() - 30));
  CHECK(cut.failed());
  CHECK(cut.message().find("truncated: 3 of 5 rows") != std::string::npos);
  const auto err = fed("!minrt-error: 7:1: expected 'sphere'\n");
  CHECK(err.firmware_error());
  CHECK(err.message() == "7:1: expected 'sphere'");
}
