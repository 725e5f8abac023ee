// The raw protocol's PNG receiver (CS418 scenes): accepts the core's stream,
// catches a damaged byte by the chunk CRC, a wrong size, a cut-off stream,
// and hands over the firmware's error line.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "core/image/png_writer.hpp"
#include "core/image/row_sink.hpp"
#include "png_receiver.hpp"

namespace {

std::string stream(int w, int h) {
  std::string bytes;
  minrt::PngStoredWriter png(minrt::ByteSink{
      [](void* ctx, const uint8_t* p, size_t n) { static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(p), n); },
      &bytes});
  std::vector<uint8_t> row(static_cast<size_t>(w) * 4, 7);
  png.begin(w, h);
  for (int y = 0; y < h; ++y) png.row(y, row.data());
  png.end();
  return bytes;
}

minrt::send::PngReceiver fed(const std::string& bytes, int w, int h) {
  minrt::send::PngReceiver rx(w, h);
  rx.feed(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  rx.finish();
  return rx;
}

}  // namespace

TEST_CASE("PngReceiver: a whole stream is accepted, row by row", "[png][receiver]") {
  const std::string s = stream(5, 3);
  minrt::send::PngReceiver rx(5, 3);
  CHECK(rx.feed(reinterpret_cast<const uint8_t*>(s.data()), s.size()) == s.size());
  CHECK(rx.done());
  CHECK(rx.rows_complete() == 3);
}

TEST_CASE("PngReceiver: damage, a wrong size, a cut and an error line are each caught", "[png][receiver]") {
  std::string s = stream(5, 3);
  std::string flipped = s;
  flipped[60] = static_cast<char>(flipped[60] ^ 0x10);
  const auto bad = fed(flipped, 5, 3);
  CHECK(bad.failed());
  CHECK(bad.message().find("bad CRC-32") != std::string::npos);
  const auto size = fed(s, 6, 3);
  CHECK(size.failed());
  CHECK(size.message() == "the board sent a 5x3 image, the scene asks for 6x3");
  const auto cut = fed(s.substr(0, s.size() - 20), 5, 3);
  CHECK(cut.failed());
  CHECK(cut.message().find("truncated") != std::string::npos);
  const auto err = fed("!minrt-error: 2:15: not a number: 'O.5'\n", 5, 3);
  CHECK(err.firmware_error());
  CHECK(err.message() == "2:15: not a number: 'O.5'");
}

TEST_CASE("PngReceiver: an error line between the rows is the board's, not damage", "[png][receiver]") {
  // A board that stops at a texel of a sparse texture not sent: signature,
  // IHDR and the first rows' chunks went out, then its error line.
  const std::string s = stream(5, 3);
  const std::string whole_rows = s.substr(0, s.find("IDAT") - 4);  // up to the first row's chunk
  const auto err = fed(whole_rows + "!minrt-error: texel not sent: texture a.png at 3,4, row 0 of the image\n", 5, 3);
  CHECK(err.firmware_error());
  CHECK(err.message() == "texel not sent: texture a.png at 3,4, row 0 of the image");
  // Inside a chunk the same byte is data, caught by the chunk's CRC-32.
  std::string inside = s;
  inside[s.find("IDAT") + 6] = '!';
  CHECK(fed(inside, 5, 3).failed());
}
