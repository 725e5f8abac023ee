// The course's older triangle names (trif: flat colour; trit: textured)
// rendered against tri, on scenes of ../shared.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "cs418_render.hpp"
#include "test_support.hpp"

namespace {

minrt::host::RenderedScene render_text(const std::string& text) {
  minrt::host::DriverOptions o;
  o.threads = 2;
  minrt::host::RenderedScene r;
  std::string error;
  const std::string dir = minrt::test::shared_dir() + "/formats/cs418/";
  const bool ok = minrt::test::render_cs418(text, "scene.txt", dir, o, r, error);
  INFO(error);
  REQUIRE(ok);
  return r;
}

std::string shared_scene(const std::string& name) {
  std::ifstream in(minrt::test::shared_dir() + "/formats/cs418/" + name, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

TEST_CASE("trif and trit: the course's older triangle names render as tri does", "[general][cs418]") {
  // Untextured: trif, trit and tri give the same bytes.
  const std::string shadow = shared_scene("ray-shadow-triangle.txt");
  REQUIRE(shadow.find("\ntri ") != std::string::npos);
  const auto tri = render_text(shadow);
  CHECK(render_text(replaced(shadow, "\ntri ", "\ntrif ")).image.rgba == tri.image.rgba);
  CHECK(render_text(replaced(shadow, "\ntri ", "\ntrit ")).image.rgba == tri.image.rgba);
  // Textured: trit is tri; trif takes the colour as if the texture were none.
  const std::string tex = shared_scene("ray-trit.txt");
  const auto textured = render_text(tex);
  CHECK(render_text(replaced(tex, "\ntri ", "\ntrit ")).image.rgba == textured.image.rgba);
  const auto flat = render_text(replaced(tex, "\ntri ", "\ntrif "));
  CHECK(flat.image.rgba != textured.image.rgba);
  CHECK(flat.image.rgba == render_text(replaced(tex, "\ntexture ", "\ntexture none\n#")).image.rgba);
}
