// Tracer::render_rows on bands that skip rows (render/sld/band_rows.hpp):
// with slot rows (prepare_bands) and by replay without them, alone and two
// tracers handing boundary rows over (RowExchange), the rows must be those
// of the whole-image render. ss20 and tsu3 end traces early after mirrors,
// so their skipped rows' slots are looked up (resolve_slots); contest never
// does.
#include <catch2/catch.hpp>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/math/math_libm.hpp"
#include "minrt_parallel.hpp"
#include "test_support.hpp"

namespace {

using M = minrt::LibmDouble;
using R = M::real;

// The rows a render hands over, by row.
struct RowStore {
  explicit RowStore(int w) : width(w) {}
  int width = 0;
  std::map<int, std::string> rows;
  int repeats = 0;
  void begin(int, int) {}
  void row(int y, const uint8_t* rgb) {
    if (!rows.emplace(y, std::string(reinterpret_cast<const char*>(rgb), 3 * static_cast<size_t>(width))).second)
      ++repeats;
  }
  void end() {}
};

// A scene read once and tracers initialised from it, each with its arena.
class Scene {
 public:
  Scene(const std::string& name, int width, int height) : width_(width), height_(height) {
    const std::string sld = minrt::test::read_file(minrt::test::shared_dir() + "/scenes/" + name + ".sld");
    minrt::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
    minrt::SldReader<R> reader(src.source(), minrt::WarningSink{});
    minrt::Diagnostic error;
    REQUIRE(reader.read(scene_, error));
  }

  minrt::Tracer<M>& tracer(bool bands) {
    const size_t bytes = minrt::Tracer<M>::arena_bytes(scene_, width_) + minrt::Tracer<M>::band_bytes(width_);
    memory_.emplace_back(new unsigned char[bytes]);
    tracers_.emplace_back(new minrt::Tracer<M>());
    minrt::Arena arena(memory_.back().get(), bytes);
    REQUIRE(tracers_.back()->init(scene_, width_, height_, arena));
    if (bands) REQUIRE(tracers_.back()->prepare_bands(arena));
    return *tracers_.back();
  }

  // The whole image on one tracer, row by row.
  std::map<int, std::string> whole() {
    RowStore store{width_};
    const minrt::RowSink sink = minrt::row_sink_of(store);
    tracer(false).render(sink);
    return store.rows;
  }

 private:
  int width_, height_;
  minrt::Scene<R> scene_;
  std::vector<std::unique_ptr<unsigned char[]>> memory_;
  std::vector<std::unique_ptr<minrt::Tracer<M>>> tracers_;
};

}  // namespace

TEST_CASE("threads: band rows: bands far apart on one tracer give the whole render's rows", "[threads][bands]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const int w = 96, h = 128;
  // Gaps of 1 to 60 rows, a one-row band, and the image's first and last rows.
  const std::vector<std::pair<int, int>> bands = {{0, 2}, {3, 9}, {30, 31}, {33, 40}, {100, 104}, {120, 128}};
  for (const char* name : {"ss20", "tsu3", "contest"}) {
    Scene scene(name, w, h);
    const auto whole = scene.whole();
    for (bool slot_rows : {true, false}) {
      CAPTURE(name, slot_rows);
      minrt::Tracer<M>& t = scene.tracer(slot_rows);
      RowStore store{w};
      const minrt::RowSink sink = minrt::row_sink_of(store);
      size_t n = 0;
      for (auto [y0, y1] : bands) {
        t.render_rows(y0, y1, sink);
        n += static_cast<size_t>(y1 - y0);
      }
      REQUIRE(store.rows.size() == n);
      CHECK(store.repeats == 0);
      for (const auto& [y, bytes] : store.rows) {
        CAPTURE(y);
        CHECK(bytes == whole.at(y));
      }
    }
  }
}

TEST_CASE("threads: band rows: two tracers taking turns hand their boundary rows over", "[threads][bands]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const int w = 80, h = 100;
  for (const char* name : {"ss20", "tsu3", "contest"}) {
    CAPTURE(name);
    Scene scene(name, w, h);
    const auto whole = scene.whole();
    minrt::Tracer<M>* turns[2] = {&scene.tracer(true), &scene.tracer(true)};
    minrt::host::RowExchange exchange(h);
    const minrt::SharedRows shared = exchange.shared();
    RowStore store{w};
    const minrt::RowSink sink = minrt::row_sink_of(store);
    // Bands of 2 to 13 rows, each tracer taking the next band in turn (one
    // thread, so whoever asks first for a shared row traces it).
    int y0 = 0;
    for (int i = 0; y0 < h; ++i) {
      const int y1 = std::min(h, y0 + 2 + (i * 5) % 12);
      turns[i % 2]->render_rows(y0, y1, sink, shared);
      y0 = y1;
    }
    REQUIRE(store.rows.size() == static_cast<size_t>(h));
    CHECK(store.repeats == 0);
    for (const auto& [y, bytes] : store.rows) {
      CAPTURE(y);
      CHECK(bytes == whole.at(y));
    }
  }
}
