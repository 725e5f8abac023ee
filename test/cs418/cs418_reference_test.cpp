// The CS418 scenes against the course's reference images, with the
// measures and bounds of SPEC.md 1.6: the deterministic tests pixel by
// pixel, the random ones (aa, dof, rough, gi) statistically.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "render_driver.hpp"
#include "image_metrics.hpp"
#include "png_io.hpp"
#include "test_support.hpp"

namespace {

const char* const kDeterministic[] = {
    "behind", "bounces", "bulb", "color", "expose1", "expose2", "fisheye", "ior", "many", "neglight",
    "overlap", "panorama", "plane", "shadow-basic", "shadow-bulb", "shadow-plane", "shadow-suns",
    "shadow-triangle", "shine1", "shine3", "sphere", "sun", "suns", "tex", "trans1", "trans3", "tri",
    "trit", "view"};

std::string cs418_dir() { return minrt::test::shared_dir() + "/formats/cs418/"; }

minrt::host::RgbaImage render(const std::string& name, minrt::host::Variant v, uint32_t seed = 1, int threads = 2) {
  const std::string path = cs418_dir() + "ray-" + name + ".txt";
  minrt::host::DriverOptions o;
  o.variant = v;
  o.seed = seed;
  o.threads = threads;
  minrt::host::RenderedScene r;
  std::string error;
  const minrt::host::SceneInput in{path, path, cs418_dir(), minrt::test::read_file(path)};
  const bool ok = minrt::host::render_in_memory(minrt::formats::format_of(minrt::formats::FormatId::kCs418), in, o,
                                                r, error);
  INFO(error);
  REQUIRE(ok);
  return r.image;
}

minrt::host::RgbaImage reference(const std::string& name) {
  minrt::host::RgbaImage img;
  std::string why;
  INFO(why);
  REQUIRE(minrt::host::read_png(cs418_dir() + "ray-" + name + ".png", img, why));
  return img;
}

}  // namespace

TEST_CASE("CS418 deterministic tests: double within max(12, 0.15%) pixels of the references", "[cs418][reference]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  for (const char* name : kDeterministic) {
    DYNAMIC_SECTION(name) {
      const auto ours = render(name, {});
      const auto ref = reference(name);
      REQUIRE(ours.width == ref.width);
      REQUIRE(ours.height == ref.height);
      const auto d = minrt::host::compare_images(ours, ref);
      const long bound = std::max(12L, static_cast<long>(d.pixels * 0.0015));
      INFO(name << ": " << d.off_by_more_than_1 << " pixels off by more than 1 (bound " << bound << ")");
      CHECK(d.off_by_more_than_1 <= bound);
    }
  }
}

TEST_CASE("CS418 deterministic tests: float builds within the documented bound", "[cs418][reference][float]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  // docs/cs418.md: float (C library or portable shims) stays within
  // max(12, 0.7%) pixels off by more than 1; ray-trit is the worst (0.6%).
  const minrt::host::Variant variants[] = {
      {minrt::host::Precision::kFloat, minrt::host::ShimSet::kLibm},
      {minrt::host::Precision::kFloat, minrt::host::ShimSet::kPortable}};
  for (const char* name : kDeterministic) {
    DYNAMIC_SECTION(name) {
      const auto ref = reference(name);
      for (const auto& v : variants) {
        const auto d = minrt::host::compare_images(render(name, v), ref);
        const long bound = std::max(12L, static_cast<long>(d.pixels * 0.007));
        INFO(name << " " << (v.shims == minrt::host::ShimSet::kLibm ? "float/libm" : "float/portable") << ": "
                  << d.off_by_more_than_1 << " off (bound " << bound << ")");
        CHECK(d.off_by_more_than_1 <= bound);
      }
    }
  }
}

TEST_CASE("CS418 random tests pass the self-calibrated statistical check", "[cs418][reference][random]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  // SPEC.md 1.6: MSE(ours, reference) <= 1.3 MSE(ours, ours with another
  // seed) on block-averaged images, channel means within 1/255 (1.5 for
  // dof), both sides averaged over six seeds. ray-aa has only 64 blocks:
  // over 30 seeds its ratio is 1.46 for us and 1.32 for SPEC's Python model,
  // so the ratio cannot separate right from wrong there; it takes SPEC's
  // fixed threshold instead (block PSNR >= 44 dB; a wrong jitter gives 33).
  struct Case {
    const char* name;
    double mean_bound;  // bytes
  };
  constexpr int kSeeds = 6;
  for (const Case c : {Case{"aa", 1.0}, Case{"dof", 1.5}, Case{"rough", 1.0}, Case{"gi", 1.0}}) {
    DYNAMIC_SECTION(c.name) {
      const auto ref = reference(c.name);
      std::vector<minrt::host::RgbaImage> ours;
      for (int s = 1; s <= kSeeds; ++s) ours.push_back(render(c.name, {}, static_cast<uint32_t>(s)));
      double vs_ref = 0, self = 0, mean[3] = {};
      int block = 0;
      for (int i = 0; i < kSeeds; ++i) {
        const auto d = minrt::host::compare_images(ours[i], ref);
        block = d.block;
        vs_ref += d.block_mse / kSeeds;
        for (int k = 0; k < 3; ++k) mean[k] += d.mean_diff[k] / kSeeds;
        self += minrt::host::block_mse(ours[i], ours[(i + 1) % kSeeds], block) / kSeeds;
      }
      INFO(c.name << ": mean block MSE vs reference " << vs_ref << ", between seeds " << self
                  << ", mean diff " << mean[0] << " " << mean[1] << " " << mean[2]);
      CHECK(self > 0);  // the seeds really differ
      if (std::string(c.name) == "aa") CHECK(10.0 * std::log10(255.0 * 255.0 / vs_ref) >= 44.0);
      else CHECK(vs_ref <= 1.3 * self);
      for (double m : mean) CHECK(std::abs(m) <= c.mean_bound);
    }
  }
}

TEST_CASE("CS418: the image does not depend on the number of threads", "[cs418][threads]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  for (const char* name : {"gi", "many", "dof"}) {
    DYNAMIC_SECTION(name) {
      const auto one = render(name, {}, 7, 1);
      CHECK(render(name, {}, 7, 2).rgba == one.rgba);
      CHECK(render(name, {}, 7, 5).rgba == one.rgba);
    }
  }
}
