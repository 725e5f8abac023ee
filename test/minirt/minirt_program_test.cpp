// minrt installed as `miniRT` (the build makes the link beside minrt) keeps
// the 42 subject's contract: exactly one .rt argument, never standard
// input, and every failure "Error", one line, status 1, no window.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <fstream>
#include <string>

#include "test_support.hpp"

namespace {

using Run = minrt::test::CommandRun;

// miniRT in `cwd` with shell words `args`, without a display.
Run mini_rt(const std::string& cwd, const std::string& args) {
  return minrt::test::run_in_dir(cwd, std::string("env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER ") +
                                          MINIRT_BIN + " " + args);
}

void check_error(const Run& r, const std::string& fragment) {
  INFO(r.err);
  CHECK(r.status == 1);
  REQUIRE(r.err.rfind("Error\n", 0) == 0);
  const std::string rest = r.err.substr(6);
  CHECK(rest.find('\n') == rest.size() - 1);  // one line
  CHECK(rest.find(fragment) != std::string::npos);
}

}  // namespace

TEST_CASE("miniRT program: the subject's command-line contract", "[minirt][program]") {
  const std::string dir = minrt::test::temp_dir("miniRT-program");
  const std::string scene = "A 0.2 255,255,255\nC 0,0,10 0,0,-1 70\nL 0,5,5 0.8 255,255,255\nsp 0,0,0 2 255,0,0\n";
  std::ofstream(dir + "/good.rt") << scene;
  std::ofstream(dir + "/good.txt") << scene;
  ::mkdir((dir + "/folder.rt").c_str(), 0755);

  check_error(mini_rt(dir, ""), "no scene given");
  check_error(mini_rt(dir, "< good.rt"), "no scene given");  // never standard input
  check_error(mini_rt(dir, "good.rt good.rt"), "expected one scene file");
  check_error(mini_rt(dir, "good.txt"), "must end in .rt");
  check_error(mini_rt(dir, "folder.rt"), "Is a directory");
  check_error(mini_rt(dir, "good.rt"), "no display");  // the window it needs cannot open
  check_error(mini_rt(dir, "--bogus good.rt"), "unknown option");
}

TEST_CASE("miniRT program: with -o it writes the image minrt writes", "[minirt][program]") {
  const std::string dir = minrt::test::temp_dir("miniRT-program-o");
  std::ofstream(dir + "/good.rt")
      << "A 0.2 255,255,255\nC 0,0,10 0,0,-1 70\nL 0,5,5 0.8 255,255,255\nsp 0,0,0 2 255,0,0\n";
  const Run a = mini_rt(dir, "--size 40x30 -o a.png good.rt");
  const Run b = minrt::test::run_in_dir(dir, std::string(MINRT_BIN) + " --size 40x30 -o b.png good.rt");
  INFO(a.err << b.err);
  REQUIRE(a.status == 0);
  REQUIRE(b.status == 0);
  CHECK(minrt::test::read_file(dir + "/a.png") == minrt::test::read_file(dir + "/b.png"));
}
