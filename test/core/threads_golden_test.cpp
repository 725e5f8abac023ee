// Rows rendered on several threads (minrt --threads) give the bytes of one
// thread: every reference scene at 128x128 against the original's sha256,
// odd sizes and the generated scenes against the one-thread render. The
// workers look up the slots that rows above their bands left (the original
// reads stale pixel slots), which ss20 and tsu3 depend on.
#include <catch2/catch.hpp>

#include "sha256.hpp"
#include "test_support.hpp"

using minrt::test::read_file;
using minrt::test::read_manifest;
using minrt::test::render_bytes;
using minrt::test::shared_dir;

namespace {

minrt::test::RenderResult render_on(const std::string& sld, int w, int h, int threads) {
  return render_bytes(sld, w, h, minrt::PpmFormat::kP3, minrt::host::Variant{}, threads);
}

}  // namespace

TEST_CASE("threads: every scene at 128x128 on 1, 2, 3 and 7 threads matches the original", "[golden][threads]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found at " << shared_dir() << ": skipped");
    return;
  }
  int checked = 0;
  for (const auto& row : read_manifest(shared_dir() + "/reference/manifest.tsv")) {
    if (row.size != 128) continue;
    const std::string sld = read_file(shared_dir() + "/scenes/" + row.scene + ".sld");
    for (int threads : {1, 2, 3, 7}) {
      CAPTURE(row.scene, threads);
      const auto r = render_on(sld, 128, 128, threads);
      REQUIRE(r.status == minrt::RenderStatus::kOk);
      CHECK(minrt::host::sha256_hex(r.image) == row.sha256);
    }
    ++checked;
  }
  CHECK(checked == 25);
}

TEST_CASE("threads: odd sizes give the one-thread bytes", "[golden][threads]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  for (const char* scene : {"ss20", "tsu3", "contest"}) {
    const std::string sld = read_file(shared_dir() + "/scenes/" + scene + ".sld");
    for (auto [w, h] : {std::pair{1, 1}, std::pair{7, 3}, std::pair{2, 40}, std::pair{61, 97}, std::pair{96, 200}}) {
      const auto one = render_on(sld, w, h, 1);
      REQUIRE(one.status == minrt::RenderStatus::kOk);
      for (int threads : {2, 5, 16}) {
        CAPTURE(scene, w, h, threads);
        const auto r = render_on(sld, w, h, threads);
        REQUIRE(r.status == minrt::RenderStatus::kOk);
        CHECK(r.image == one.image);
      }
    }
  }
}

TEST_CASE("threads: the generated scenes at 48x48 on 3 threads match the original", "[golden][threads]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  int checked = 0;
  for (const auto& row : read_manifest(shared_dir() + "/fuzz/manifest.tsv")) {
    if (row.size != 48) continue;
    CAPTURE(row.scene);
    const auto r = render_on(read_file(shared_dir() + "/fuzz/scenes/" + row.scene + ".sld"), 48, 48, 3);
    REQUIRE(r.status == minrt::RenderStatus::kOk);
    CHECK(minrt::host::sha256_hex(r.image) == row.sha256);
    ++checked;
  }
  CHECK(checked > 0);
}
