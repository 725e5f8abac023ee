// PPM formatting and the pixel clamp with the original's integer conversion.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "core/image/ppm_writer.hpp"
#include "render/sld/tracer.hpp"

namespace {

struct Recorder {
  std::string bytes;
  std::vector<size_t> writes;
  static void write(void* ctx, const uint8_t* data, size_t size) {
    auto* r = static_cast<Recorder*>(ctx);
    r->bytes.append(reinterpret_cast<const char*>(data), size);
    r->writes.push_back(size);
  }
  minrt::ByteSink sink() { return minrt::ByteSink{&write, this}; }
};

}  // namespace

TEST_CASE("ppm: P3 header and pixels are printed like the original", "[ppm]") {
  Recorder rec;
  minrt::PpmWriter w(rec.sink(), minrt::PpmFormat::kP3);
  const uint8_t row[6] = {0, 128, 255, 7, 10, 100};
  const minrt::RowSink sink = w.sink();
  sink.begin(2, 384);
  sink.row(0, row);
  CHECK(rec.bytes == "P3\n2 384 255\n0 128 255\n7 10 100\n");
  CHECK(rec.writes.size() == 1);  // the header waits for the first row: one write
}

TEST_CASE("ppm: P6 writes raw bytes after the same header", "[ppm]") {
  Recorder rec;
  minrt::PpmWriter w(rec.sink(), minrt::PpmFormat::kP6);
  const uint8_t row[6] = {0, 128, 255, 10, 13, 32};
  w.begin(2, 1);
  w.row(0, row);
  w.end();
  CHECK(rec.bytes == std::string("P6\n2 1 255\n\x00\x80\xff\x0a\x0d\x20", 17));
}

TEST_CASE("ppm: each finished row reaches the sink at once", "[ppm]") {
  Recorder rec;
  minrt::PpmWriter w(rec.sink(), minrt::PpmFormat::kP3);
  w.begin(3, 2);
  for (int y = 0; y < 2; ++y) {
    const size_t before = rec.bytes.size();
    const uint8_t row[9] = {0, uint8_t(y), 255, 1, uint8_t(y), 255, 2, uint8_t(y), 255};
    w.row(y, row);
    CHECK(rec.bytes.size() > before);
    CHECK(rec.bytes.back() == '\n');
  }
  // Long rows go out in pieces of the writer's buffer, never all at the end.
  Recorder big;
  minrt::PpmWriter wb(big.sink(), minrt::PpmFormat::kP3);
  for (int x = 0; x < 2000; ++x) wb.pixel(255, 255, 255);
  CHECK(big.writes.size() >= 10);
}

TEMPLATE_TEST_CASE("ppm: channel clamp follows OCaml's int_of_float on x86-64", "[ppm]",
                   minrt::LibmDouble, minrt::LibmFloat, minrt::PortableFloat) {
  using R = typename TestType::real;
  auto ch = [](R x) { return minrt::pixel_channel<TestType>(x); };
  CHECK(ch(R(0.0)) == 0);
  CHECK(ch(R(0.99)) == 0);
  CHECK(ch(R(1.0)) == 1);
  CHECK(ch(R(254.999)) == 254);
  CHECK(ch(R(255.5)) == 255);
  CHECK(ch(R(1e6)) == 255);
  CHECK(ch(R(-0.5)) == 0);
  CHECK(ch(R(-300.0)) == 0);
  CHECK(ch(R(NAN)) == 0);
  CHECK(ch(R(INFINITY)) == 0);   // 64-bit conversion overflows to 0x8000...
  CHECK(ch(R(-INFINITY)) == 0);
  CHECK(ch(R(4611686018427387904.0)) == 0);    // 2^62 wraps negative
  CHECK(ch(R(4.0e18)) == 255);                 // just below 2^62
  CHECK(ch(R(-6.0e18)) == 255);                // wraps positive
  CHECK(ch(R(-4611686018427387904.0)) == 0);   // -2^62 stays negative
  CHECK(ch(R(-9223372036854775808.0)) == 0);   // -2^63: the overflow value
}
