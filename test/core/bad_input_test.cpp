// Every file in shared/bad must stop with a located one-line error and no
// image bytes; the one valid file there must render.
#include <catch2/catch.hpp>

#include <dirent.h>

#include <algorithm>
#include <map>
#include <string>

#include "test_support.hpp"

using minrt::test::read_file;
using minrt::test::render_bytes;
using minrt::test::shared_dir;

namespace {

struct Expected {
  int line;
  int col;
  const char* phrase;
};

const std::map<std::string, Expected> kExpected = {
    {"andnet-missing-object.sld", {9, 1, "AND network 2 refers to object 2, but only 2 objects"}},
    {"binary-garbage.sld", {1, 1, "expected a number for screen x, got '\\x"}},
    {"empty.sld", {1, 1, "unexpected end of input: expected screen x"}},
    {"huge-token.sld", {4, 35, "token longer than 256 bytes where color blue of object 0"}},
    {"infinite-value.sld", {4, 12, "non-finite value for size a of object 0: '1e999'"}},
    {"missing-final-terminator.sld", {9, 1, "unexpected end of input: expected range primitive of OR network 1"}},
    {"missing-terminators.sld", {21, 1, "unexpected end of input"}},
    {"nan-value.sld", {5, 12, "non-finite value for size a of object 1: 'nan'"}},
    {"non-numeric-token.sld", {4, 12, "expected a number for size a of object 0, got 'abc'"}},
    {"or-net-missing-and-net.sld", {8, 6, "OR network 0 refers to AND network 7, but only 1 AND networks"}},
    {"range-primitive-missing.sld", {8, 1, "range primitive 42"}},
    {"too-many-and-nets.sld", {63, 144, "refers to AND network 50, but at most 50"}},
    {"too-many-objects.sld", {64, 1, "too many objects"}},
    {"truncated-environment.sld", {2, 1, "unexpected end of input"}},
    {"truncated-object.sld", {7, 51, "unexpected end of input: expected color red of object 3"}},
};

std::vector<std::string> bad_files() {
  std::vector<std::string> names;
  if (DIR* d = opendir((shared_dir() + "/bad").c_str())) {
    while (dirent* e = readdir(d)) {
      std::string n = e->d_name;
      if (n.size() > 4 && n.substr(n.size() - 4) == ".sld") names.push_back(n);
    }
    closedir(d);
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST_CASE("bad inputs: each fails with a located error and writes nothing", "[bad]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found at " << shared_dir() << ": skipped");
    return;
  }
  const auto names = bad_files();
  REQUIRE(names.size() >= kExpected.size());
  for (const auto& name : names) {
    if (name == "sixty-objects-fifty-and-nets.sld") continue;
    CAPTURE(name);
    for (auto variant : {minrt::host::Variant{},
                         minrt::host::Variant{minrt::host::Precision::kFloat,
                                              minrt::host::ShimSet::kPortable}}) {
      const auto r = render_bytes(read_file(shared_dir() + "/bad/" + name), 16, 16,
                                  minrt::PpmFormat::kP3, variant);
      CHECK(r.status == minrt::RenderStatus::kSceneError);
      CHECK(r.image.empty());
      CHECK(r.error.has_pos);
      const std::string msg = r.error.message;
      CAPTURE(msg);
      CHECK(msg.find('\n') == std::string::npos);
      const auto it = kExpected.find(name);
      if (it == kExpected.end()) {
        // A file added to shared/bad later: it must still fail cleanly.
        CHECK(!msg.empty());
        continue;
      }
      CHECK(r.error.pos.line == it->second.line);
      CHECK(r.error.pos.col == it->second.col);
      CHECK(msg.find(it->second.phrase) != std::string::npos);
    }
  }
}

TEST_CASE("bad inputs: sixty objects are read and rendered", "[bad]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string sld = read_file(shared_dir() + "/bad/sixty-objects-fifty-and-nets.sld");
  minrt::Scene<double> scene;
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  minrt::SldReader<double> reader(src.source(), {});
  minrt::Diagnostic error;
  REQUIRE(reader.read(scene, error));
  CHECK(scene.object_count == 60);
  CHECK(scene.and_count == 60);
  CHECK(scene.or_count == 1);
  // The last object (the original loses it: it never records the count).
  CHECK(scene.objects[59].center[0] == 36.0);

  const auto r = render_bytes(sld, 64, 64);
  REQUIRE(r.status == minrt::RenderStatus::kOk);
  CHECK(r.image.size() > 64 * 64 * 6);
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0].find("AND networks from 50 on") != std::string::npos);
}
