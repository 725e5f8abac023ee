// Golden tests: the double/libm build must print exactly the bytes the
// original min-rt printed (sha256 of the P3 output from the manifests), and
// P6 must hold exactly the reference pixels.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sha256.hpp"
#include "test_support.hpp"

using minrt::test::read_file;
using minrt::test::read_manifest;
using minrt::test::render_bytes;
using minrt::test::shared_dir;

namespace {

// Renders every manifest row of the given size and compares sha256; with
// no_warnings, the scene must also read without a warning. Returns the
// scenes checked.
std::vector<std::string> check_rows(const std::string& manifest, const std::string& scene_dir, int size,
                                    bool no_warnings = false) {
  std::vector<std::string> checked;
  for (const auto& row : read_manifest(manifest)) {
    if (row.size != size) continue;
    CAPTURE(row.scene, row.size);
    const auto result = render_bytes(read_file(scene_dir + "/" + row.scene + ".sld"), size, size);
    REQUIRE(result.status == minrt::RenderStatus::kOk);
    CHECK(minrt::host::sha256_hex(result.image) == row.sha256);
    if (no_warnings)
      for (const std::string& w : result.warnings) FAIL_CHECK("warning: " << w);
    checked.push_back(row.scene);
  }
  return checked;
}

void check_manifest(const std::string& manifest, const std::string& scene_dir, int size) {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found at " << shared_dir() << ": golden test skipped");
    return;
  }
  CHECK(!check_rows(manifest, scene_dir, size).empty());
}

}  // namespace

TEST_CASE("golden: the 25 scenes at 128x128 match the original byte for byte", "[golden]") {
  check_manifest(shared_dir() + "/reference/manifest.tsv", shared_dir() + "/scenes", 128);
}

TEST_CASE("golden: the 25 scenes at 512x512 match the original byte for byte", "[golden][slow]") {
  check_manifest(shared_dir() + "/reference/manifest.tsv", shared_dir() + "/scenes", 512);
}

TEST_CASE("golden: the 280 generated scenes at 48x48 match the original byte for byte", "[golden]") {
  check_manifest(shared_dir() + "/fuzz/manifest.tsv", shared_dir() + "/fuzz/scenes", 48);
}

// The repository's own sample scenes; their sums were made with the original
// program built by hand outside the repository (sld/ordinary/README.md).
TEST_CASE("golden: the ordinary scenes of sld/ordinary match the original byte for byte and without warnings",
          "[golden]") {
  const std::string dir = std::string(MINRT_SOURCE_DIR) + "/sld/ordinary";
  std::vector<std::string> checked = check_rows(dir + "/manifest.tsv", dir, 128, true);
  // Every scene of the folder has its row: a scene added without the
  // original's sum fails here.
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".sld") scenes.push_back(entry.path().stem().string());
  std::sort(checked.begin(), checked.end());
  std::sort(scenes.begin(), scenes.end());
  CHECK(!scenes.empty());
  CHECK(checked == scenes);
}

TEST_CASE("golden: P6 output holds exactly the reference pixels", "[golden]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  for (const char* scene : {"contest", "tron", "textest", "shuttle"}) {
    CAPTURE(scene);
    const auto result = render_bytes(read_file(shared_dir() + "/scenes/" + scene + ".sld"), 128,
                                     128, minrt::PpmFormat::kP6);
    REQUIRE(result.status == minrt::RenderStatus::kOk);
    // The reference files put the maxval on its own line; compare pixels.
    const std::string ref = read_file(shared_dir() + "/reference/128/" + scene + ".ppm");
    const std::string ref_header = "P6\n128 128\n255\n", our_header = "P6\n128 128 255\n";
    REQUIRE(ref.compare(0, ref_header.size(), ref_header) == 0);
    REQUIRE(result.image.compare(0, our_header.size(), our_header) == 0);
    CHECK(result.image.substr(our_header.size()) == ref.substr(ref_header.size()));
  }
}

TEST_CASE("golden: any width x height gives a complete image of that size", "[golden]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string sld = read_file(shared_dir() + "/scenes/contest.sld");
  for (auto [w, h] : {std::pair{7, 3}, std::pair{1, 1}, std::pair{33, 2}, std::pair{2, 40}}) {
    CAPTURE(w, h);
    const auto r = render_bytes(sld, w, h);
    REQUIRE(r.status == minrt::RenderStatus::kOk);
    const std::string header = "P3\n" + std::to_string(w) + " " + std::to_string(h) + " 255\n";
    REQUIRE(r.image.compare(0, header.size(), header) == 0);
    const auto lines = std::count(r.image.begin(), r.image.end(), '\n');
    CHECK(lines == 2 + w * h);
    const auto p6 = render_bytes(sld, w, h, minrt::PpmFormat::kP6);
    CHECK(p6.image.size() == header.size() + static_cast<size_t>(3 * w * h));
  }
}
