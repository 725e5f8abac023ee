// The course protocol on one parser: for every scene of ../shared (scenes,
// fuzz, bad) the host's word encoder accepts exactly what the SLD reader
// accepts from text in single precision (what the board does over raw and
// framed), with the same located message, and the board's reader gets the
// same scene back from the words.
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "formats/sld/sld_reader.hpp"
#include "protocol/course_word_values.hpp"
#include "protocol_course_host.hpp"
#include "test_support.hpp"

namespace {

namespace course = minrt::send::course;
using SceneF = minrt::Scene<float>;

bool read_text(const std::string& text, SceneF& scene, minrt::Diagnostic& d) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::SldReader<float> reader(mem.source(), minrt::WarningSink{});
  return reader.read(scene, d);
}

bool read_words(const std::string& words, course::Endian e, SceneF& scene, minrt::Diagnostic& d) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(words.data()), words.size()};
  minrt::SldReader<float, course::CourseWordValues<float>> reader(course::CourseWordValues<float>(mem.source(), e),
                                                                  minrt::WarningSink{});
  return reader.read(scene, d);
}

// Every field the renderer uses (not the source positions: words have no lines).
bool same_scene(const SceneF& a, const SceneF& b) {
  auto eq = [](const float* x, const float* y, int n) {
    for (int i = 0; i < n; ++i)
      if (std::memcmp(&x[i], &y[i], sizeof(float)) != 0) return false;
    return true;
  };
  if (!eq(a.screen, b.screen, 3) || !eq(a.screen_rotation_deg, b.screen_rotation_deg, 2) ||
      a.light_count != b.light_count || !eq(a.light_rotation_deg, b.light_rotation_deg, 2) || !eq(&a.beam, &b.beam, 1) ||
      a.object_count != b.object_count || a.and_count != b.and_count || a.or_count != b.or_count)
    return false;
  for (int i = 0; i < a.object_count; ++i) {
    const auto &p = a.objects[i], &q = b.objects[i];
    if (p.texture != q.texture || p.form != q.form || p.reflection != q.reflection || p.rotated != q.rotated ||
        p.inverted != q.inverted || !eq(p.abc, q.abc, 3) || !eq(p.center, q.center, 3) || !eq(&p.diffuse, &q.diffuse, 1) ||
        !eq(&p.hilight, &q.hilight, 1) || !eq(p.color, q.color, 3) || !eq(p.rotation_deg, q.rotation_deg, 3))
      return false;
  }
  for (int n = 0; n <= a.and_count; ++n)
    for (int k = 0; k <= minrt::limits::kMaxAndNetworkLength; ++k) {
      if (a.and_nets[n][k] != b.and_nets[n][k]) return false;
      if (a.and_nets[n][k] == -1) break;
    }
  for (int n = 0; n <= a.or_count; ++n)
    for (int k = 0; k <= minrt::limits::kMaxOrNetworkLength; ++k) {
      if (a.or_nets[n][k] != b.or_nets[n][k]) return false;
      if (a.or_nets[n][k] == -1) break;
    }
  return true;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("course words: the same acceptance, message and scene as the text reader on every shared scene",
          "[course]") {
  const std::filesystem::path shared = hs_test::shared_dir();
  if (!std::filesystem::exists(shared / "scenes")) {
    WARN("no shared test data at " << shared.string());
    return;
  }
  int accepted = 0, refused = 0;
  for (const char* dir : {"scenes", "fuzz/scenes", "bad"}) {
    for (const auto& entry : std::filesystem::directory_iterator(shared / dir)) {
      if (entry.path().extension() != ".sld") continue;
      const std::string text = slurp(entry.path());
      INFO(entry.path().string());
      auto from_text = std::make_unique<SceneF>();
      minrt::Diagnostic d;
      const bool text_ok = read_text(text, *from_text, d);
      for (const bool big : {false, true}) {
        std::string words, err;
        const bool words_ok = minrt::send::sld_to_course_words(text, big, words, err);
        REQUIRE(words_ok == text_ok);
        if (!text_ok) {
          CHECK(err == std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": " +
                           std::string(d.message, d.length));
          continue;
        }
        auto from_words = std::make_unique<SceneF>();
        minrt::Diagnostic wd;
        REQUIRE(read_words(words, big ? course::Endian::kBig : course::Endian::kLittle, *from_words, wd));
        CHECK(same_scene(*from_text, *from_words));
      }
      ++(text_ok ? accepted : refused);
    }
  }
  CHECK(accepted > 300);
  CHECK(refused >= 15);
}
