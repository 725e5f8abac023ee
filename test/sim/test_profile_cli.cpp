// Profiles people can read: the SVG flame graph and demangled names in
// every profile output.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <string>

#include "cli_runner.hpp"

using namespace cli;

namespace {
size_t count_of(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
}  // namespace

TEST_CASE("flame-out writes an SVG flame graph of the run", "[cli][profile]") {
  const std::string svg_path = temp_path("flame.svg");
  Result r = sim("--stats --flame-out " + svg_path + " " + kElf + " -- recur 15");
  REQUIRE(r.status == 0);
  const std::string svg = slurp(svg_path);
  CHECK(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0) == 0);
  CHECK_THAT(svg, Catch::EndsWith("</svg>\n"));
  // The bottom box is _start with every cycle of the run.
  const uint64_t cycles = stat_value(r.err, "cycles");
  std::string total = std::to_string(cycles);
  for (int i = static_cast<int>(total.size()) - 3; i > 0; i -= 3) total.insert(static_cast<size_t>(i), ",");
  CHECK(svg.find("<g><title>_start\n" + total + " cycles (100.00%)") != std::string::npos);
  // recur calls itself 15 levels deep: one box per level on the path that
  // always takes the n-1 branch, at least.
  CHECK(count_of(svg, "<title>recur\n") >= 14);
  CHECK(count_of(svg, "<rect") == count_of(svg, "</g>") + 1);  // + the background
  if (std::system("command -v python3 >/dev/null 2>&1") == 0) {
    CHECK(std::system(("python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' " + svg_path).c_str()) == 0);
  }
  std::remove(svg_path.c_str());
}

#ifdef FWSIM_RENDERER_ELF
TEST_CASE("C++ names are demangled in stats, callgrind, folded stacks and the flame graph", "[cli][profile]") {
  const std::string cg = temp_path("r.cg"), folded = temp_path("r.folded"), svg = temp_path("r.svg");
  Result r = sim("--stats --profile-out " + cg + " --folded-out " + folded + " --flame-out " + svg +
                 " --uart-in " + std::string(FWSIM_RENDER_SCENE) + " --uart-out /dev/null " + FWSIM_RENDERER_ELF +
                 " -- --size 8x8");
  REQUIRE(r.status == 0);
  const std::string outputs[4] = {r.err, slurp(cg), slurp(folded), slurp(svg)};
  for (const std::string& text : outputs) {
    CHECK(text.find("_ZN") == std::string::npos);
    CHECK(text.find("minrt::Tracer") != std::string::npos);
  }
  CHECK(outputs[3].find("<title>minrt::Tracer&lt;minrt::") != std::string::npos);  // full name, escaped
  CHECK(std::regex_search(r.err, std::regex("\n +[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+  minrt::")));
  std::remove(cg.c_str());
  std::remove(folded.c_str());
  std::remove(svg.c_str());
}
#endif
