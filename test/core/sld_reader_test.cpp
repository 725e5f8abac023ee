// The SLD reader: token rules, field types, limits, cross references,
// warnings, and positions in error messages.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "formats/sld/scene.hpp"
#include "formats/sld/sld_reader.hpp"

namespace {

struct Read {
  bool ok = false;
  minrt::Scene<double> scene;
  minrt::Diagnostic error;
  std::vector<std::string> warnings;
};

void collect(void* ctx, const minrt::Diagnostic& d) {
  static_cast<std::vector<std::string>*>(ctx)->push_back(d.message);
}

Read read(const std::string& text) {
  Read r;
  minrt::MemorySource src{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::SldReader<double> reader(src.source(), minrt::WarningSink{&collect, &r.warnings});
  r.ok = reader.read(r.scene, r.error);
  return r;
}

const std::string kEnv = "0 0 0 10 20\n1 30 40\n255\n";
const std::string kSphere = "0 3 1 0 5 5 5 0 0 0 1 1 0 255 255 255\n";

std::string objects(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += kSphere;
  return s;
}

}  // namespace

TEST_CASE("reader: a minimal scene", "[reader]") {
  const auto r = read(kEnv + kSphere + "-1\n0 -1\n-1\n99 0 -1\n-1\n");
  REQUIRE(r.ok);
  CHECK(r.scene.object_count == 1);
  CHECK(r.scene.and_count == 1);
  CHECK(r.scene.or_count == 1);
  CHECK(r.scene.screen_rotation_deg[1] == 20.0);
  CHECK(r.scene.light_count == 1);
  CHECK(r.scene.beam == 255.0);
  CHECK(r.scene.objects[0].form == minrt::kFormQuadric);
  CHECK(r.scene.or_nets[0][0] == 99);
  CHECK(r.scene.or_nets[0][1] == 0);
  CHECK(r.scene.or_nets[0][2] == -1);
  CHECK(r.scene.or_nets[1][0] == -1);
  CHECK(r.warnings.empty());
}

TEST_CASE("reader: only space, tab, CR and LF separate tokens", "[reader]") {
  const auto r = read("0\t0\r\n0 10 20\n1 30 40\n255\n" + kSphere + "-1\n0 -1\n-1\n99 0 -1\n-1");
  REQUIRE(r.ok);  // no newline after the final -1 is fine
  const auto bad = read("0,0 0 10 20\n");
  REQUIRE_FALSE(bad.ok);
  CHECK(std::string(bad.error.message) == "expected a number for screen x, got '0,0'");
}

TEST_CASE("reader: integers where the original reads integers", "[reader]") {
  const auto r = read(kEnv + "0 3.0 1 0 5 5 5 0 0 0 1 1 0 255 255 255\n-1\n");
  REQUIRE_FALSE(r.ok);
  CHECK(std::string(r.error.message) == "expected an integer for form of object 0, got '3.0'");
  CHECK(r.error.pos.line == 4);
  CHECK(r.error.pos.col == 3);
  const auto light = read("0 0 0 10 20\n1.5 30 40\n255\n");
  REQUIRE_FALSE(light.ok);
  CHECK(std::string(light.error.message).find("light count") != std::string::npos);
}

TEST_CASE("reader: a rotated object reads three more numbers", "[reader]") {
  const auto r = read(kEnv + "0 3 1 1 5 5 5 0 0 0 1 1 0 255 255 255 10 20 30\n-1\n0 -1\n-1\n99 0 -1\n-1\n");
  REQUIRE(r.ok);
  CHECK(r.scene.objects[0].rotated == 1);
  CHECK(r.scene.objects[0].rotation_deg[2] == 30.0);
}

TEST_CASE("reader: the polarity is a float whose sign matters", "[reader]") {
  const auto r = read(kEnv + "0 3 1 0 5 5 5 0 0 0 -0.5 1 0 255 255 255\n"
                             "0 3 1 0 5 5 5 0 0 0 -0 1 0 255 255 255\n-1\n-1\n-1\n");
  REQUIRE(r.ok);
  CHECK(r.scene.objects[0].inverted);
  CHECK_FALSE(r.scene.objects[1].inverted);  // -0 is not negative
}

TEST_CASE("reader: sixty objects are fine, sixty-one are not", "[reader]") {
  const auto ok = read(kEnv + objects(60) + "-1\n-1\n-1\n");
  REQUIRE(ok.ok);
  CHECK(ok.scene.object_count == 60);
  const auto bad = read(kEnv + objects(61) + "-1\n-1\n-1\n");
  REQUIRE_FALSE(bad.ok);
  CHECK(bad.error.pos.line == 4 + 60);
  CHECK(std::string(bad.error.message).find("too many objects") == 0);
}

TEST_CASE("reader: unknown codes render as in the original, with warnings", "[reader]") {
  const auto r = read(kEnv + "7 9 5 0 5 5 5 0 0 0 1 1 0 255 255 255\n-1\n-1\n-1\n");
  REQUIRE(r.ok);
  REQUIRE(r.warnings.size() == 3);
  CHECK(r.warnings[0] == "object 0: unknown texture 7, drawn untextured as the original does");
  CHECK(r.warnings[1].find("unknown form 9") != std::string::npos);
  CHECK(r.warnings[2].find("unknown reflection type 5") != std::string::npos);
}

TEST_CASE("reader: AND networks must name defined objects", "[reader]") {
  const auto r = read(kEnv + objects(2) + "-1\n0 1 -1\n1 4 -1\n-1\n-1\n");
  REQUIRE_FALSE(r.ok);
  CHECK(std::string(r.error.message) ==
        "AND network 1 refers to object 4, but only 2 objects are defined");
  CHECK(r.error.pos.line == 8);
  CHECK(r.error.pos.col == 3);
  const auto neg = read(kEnv + objects(1) + "-1\n-3 -1\n-1\n-1\n");
  REQUIRE_FALSE(neg.ok);
  CHECK(std::string(neg.error.message).find("refers to object -3") != std::string::npos);
}

TEST_CASE("reader: OR networks, range primitives and the lattice.sld run", "[reader]") {
  // A run of consecutive indices past the defined networks is what course
  // scenes contain; the original reads those networks as empty.
  const auto run = read(kEnv + objects(2) + "-1\n0 -1\n1 -1\n-1\n99 0 1 2 3 -1\n-1\n");
  REQUIRE(run.ok);
  CHECK(run.scene.or_nets[0][3] == -1);  // 2 and 3 dropped
  REQUIRE(run.warnings.size() == 1);
  CHECK(run.warnings[0].find("undefined AND networks from 2 on") != std::string::npos);
  // Anything else that names a missing network is an error.
  const auto gap = read(kEnv + objects(2) + "-1\n0 -1\n-1\n99 0 5 -1\n-1\n");
  REQUIRE_FALSE(gap.ok);
  CHECK(std::string(gap.error.message).find("refers to AND network 5") != std::string::npos);
  const auto range = read(kEnv + objects(2) + "-1\n0 -1\n-1\n1 0 -1\n2 0 -1\n-1\n");
  REQUIRE_FALSE(range.ok);
  CHECK(std::string(range.error.message) ==
        "OR network 1 has range primitive 2, but only 2 objects are defined (99 means none)");
}

TEST_CASE("reader: reading stops right after the final terminator", "[reader]") {
  // Over a serial line nothing follows; trailing text is never looked at.
  const auto r = read(kEnv + kSphere + "-1\n0 -1\n-1\n99 0 -1\n-1\ngarbage that is never read");
  CHECK(r.ok);
}

TEST_CASE("reader: end of input names what was expected", "[reader]") {
  const auto r = read(kEnv + "0 3 1 0 5 5");
  REQUIRE_FALSE(r.ok);
  CHECK(std::string(r.error.message) == "unexpected end of input: expected size c of object 0");
  CHECK(r.error.pos.line == 4);
  CHECK(r.error.pos.col == 12);
}

TEST_CASE("reader: over-long tokens are refused before they are stored", "[reader]") {
  const auto r = read("0 " + std::string(100000, '1') + " 0 10 20\n");
  REQUIRE_FALSE(r.ok);
  CHECK(r.error.pos.col == 3);
  CHECK(std::string(r.error.message).find("token longer than 256 bytes where screen y") == 0);
}
