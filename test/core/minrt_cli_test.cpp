// The minrt command as a user meets it: help, option errors, located scene
// errors with exit status 2 and no image, complete-or-nothing -o output.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "sha256.hpp"
#include "test_support.hpp"

namespace {

struct Run {
  int status = -1;
  std::string out;
  std::string err;
};

// Runs minrt with `args` (shell words) and stdin from `input` (a path or "").
Run run(const std::string& args, const std::string& input = "") {
  char dir[] = "/tmp/minrt-cli-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string out = std::string(dir) + "/out", err = std::string(dir) + "/err";
  std::string cmd = std::string(MINRT_BIN) + " " + args + " >" + out + " 2>" + err;
  cmd += input.empty() ? " </dev/null" : " <" + input;
  const int rc = std::system(cmd.c_str());
  Run r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.out = minrt::test::read_file(out);
  r.err = minrt::test::read_file(err);
  std::remove(out.c_str());
  std::remove(err.c_str());
  rmdir(dir);
  return r;
}

bool exists(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0;
}

int count_lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

}  // namespace

TEST_CASE("minrt: --help and --version", "[cli]") {
  const auto help = run("--help");
  CHECK(help.status == 0);
  CHECK(help.out.find("Usage: minrt") == 0);
  const auto version = run("--version");
  CHECK(version.status == 0);
  CHECK(version.out.find("minrt ") == 0);
}

TEST_CASE("minrt: usage errors are one line and exit 2", "[cli]") {
  for (const char* args : {"--size 0x5", "--size 12", "--format p4", "--precision half",
                           "--bogus", "--shims portable --precision double", "a.sld b.sld"}) {
    CAPTURE(args);
    const auto r = run(args);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(count_lines(r.err) == 1);
  }
  const auto missing = run("/nonexistent/scene.sld");
  CHECK(missing.status == 2);
  CHECK(missing.err == "minrt: error: cannot read /nonexistent/scene.sld: No such file or directory\n");
  // A directory is a read error with the system's reason, not an empty scene.
  const auto dir = run("/tmp");
  CHECK(dir.status == 2);
  CHECK(dir.out.empty());
  CHECK(dir.err == "minrt: error: cannot read /tmp: Is a directory\n");
}

TEST_CASE("minrt: a bad scene gives FILE:LINE:COL: error and no image", "[cli]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string bad = minrt::test::shared_dir() + "/bad/range-primitive-missing.sld";
  const auto r = run("--size 16x16 " + bad);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == bad + ":8:1: error: OR network 0 has range primitive 42, but only 1 objects are "
                       "defined (99 means none)\n");
  const auto piped = run("--size 16x16", bad);
  CHECK(piped.status == 2);
  CHECK(piped.err.find("<stdin>:8:1: error:") == 0);

  char dir[] = "/tmp/minrt-out-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string target = std::string(dir) + "/image.ppm";
  const auto o = run("--size 16x16 -o " + target + " " + bad);
  CHECK(o.status == 2);
  CHECK_FALSE(exists(target));
  CHECK(rmdir(dir) == 0);  // no temporary file left either
}

TEST_CASE("minrt: -o replaces only a regular file or a new name, and leaves no temporary behind", "[cli]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string ball = minrt::test::shared_dir() + "/scenes/ball.sld";
  const std::string contest = minrt::test::shared_dir() + "/scenes/contest.sld";
  char dir[] = "/tmp/minrt-out-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string d = dir;
  // A FIFO and a symbolic link are refused and stay what they are.
  REQUIRE(mkfifo((d + "/fifo").c_str(), 0600) == 0);
  REQUIRE(symlink((d + "/elsewhere").c_str(), (d + "/link").c_str()) == 0);
  for (const char* name : {"/fifo", "/link"}) {
    const auto r = run("--size 8x8 -o " + d + name + " " + ball);
    CHECK(r.status == 2);
    CHECK(r.err.find("refusing to replace " + d + name) != std::string::npos);
  }
  struct stat st {};
  REQUIRE(lstat((d + "/fifo").c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  REQUIRE(lstat((d + "/link").c_str(), &st) == 0);
  CHECK(S_ISLNK(st.st_mode));
  // Two runs writing one target at once: both finish, and the file is one
  // whole image (the temporary names are unique).
  const std::string target = d + "/image.ppm";
  const std::string expected = run("--size 64x64 " + ball).out;
  const std::string cmd = std::string(MINRT_BIN) + " --size 64x64 -o " + target + " " + ball;
  CHECK(std::system((cmd + " & " + cmd + " & wait").c_str()) == 0);
  CHECK(minrt::test::read_file(target) == expected);
  // SIGTERM during a long render removes the temporary file; the target
  // keeps its old content.
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    execl(MINRT_BIN, MINRT_BIN, "--size", "2048x2048", "-q", "-o", target.c_str(), contest.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  usleep(300000);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  CHECK(WIFSIGNALED(status));
  CHECK(minrt::test::read_file(target) == expected);
  std::remove(target.c_str());
  std::remove((d + "/fifo").c_str());
  std::remove((d + "/link").c_str());
  CHECK(rmdir(dir) == 0);  // nothing else was left in the folder
}

TEST_CASE("minrt: -o syncs the file and its folder only with --sync", "[cli]") {
  if (!minrt::test::shared_available() || std::system("strace -V >/dev/null 2>&1") != 0) {
    WARN("shared/ test data or strace not found: skipped");
    return;
  }
  const std::string ball = minrt::test::shared_dir() + "/scenes/ball.sld";
  char dir[] = "/tmp/minrt-sync-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string d = dir, log = d + "/trace";
  // Counts the fsync calls of one run of `command`, which writes `target`.
  auto fsyncs = [&](const std::string& command, const std::string& target) {
    const std::string cmd = "strace -f -qq -e trace=fsync -o " + log + " " + command;
    REQUIRE(std::system(cmd.c_str()) == 0);
    CHECK(minrt::test::read_file(target).size() > 0);
    const std::string trace = minrt::test::read_file(log);
    int n = 0;
    for (std::size_t at = 0; (at = trace.find("fsync(", at)) != std::string::npos; ++at) ++n;
    return n;
  };
  const std::string ppm = d + "/image.ppm";
  const std::string expected = run("--size 16x16 " + ball).out;
  auto minrt = [&](const std::string& options, const std::string& scene, const std::string& target) {
    return std::string(MINRT_BIN) + " --size 16x16 " + options + " -o " + target + " " + scene;
  };
  CHECK(fsyncs(minrt("", ball, ppm), ppm) == 0);  // replaced atomically, not synced
  CHECK(minrt::test::read_file(ppm) == expected);
  CHECK(fsyncs(minrt("--sync", ball, ppm), ppm) == 2);  // the file, then its folder after the rename
  CHECK(minrt::test::read_file(ppm) == expected);
  // Every format's writer takes the choice from the option.
  const struct {
    const char *file, *text;
  } scenes[] = {
      {"cs418.txt", "png 8 8 out.png\nsphere 0 0 -2 1\n"},
      {"jaworski.txt",
       "imwidth 8 imheight 8 canvwidth 1 canvheight 1 depth 1 lights directional 1 white 0 0 1 "
       "objects sphere 0 0 5 1 diffusive red\n"},
      {"scene.rt", "A 0.2 255,255,255\nC 0,0,10 0,0,-1 70\nL 0,5,5 0.8 255,255,255\nsp 0,0,0 2 255,0,0\n"},
      {"scene.ray",
       "display 8 8 0 0 7 7 1 1 1 ;\ncondition 4 0.01 0.00001 0 ;\ncamera 0 2 9  0 1 0  0 10 0  25 0 ;\n"
       "sky 0.2 0.4 0.8 ;\nenv 0.2 0.2 0.2 ;\nshadow 1 ;\n"
       "color [ grey 0.6 0.6 0.6  0 0 0  0 0 0  1 1  0  0 0 1 ; ]\nobj [ 2 grey 1  0 1 0  1 ; ]\n"},
  };
  const std::string png = d + "/image.png";
  for (const auto& sc : scenes) {
    INFO(sc.file);
    const std::string scene = d + "/" + sc.file;
    { std::ofstream(scene) << sc.text; }
    CHECK(fsyncs(minrt("", scene, png), png) == 0);
    CHECK(fsyncs(minrt("--sync", scene, png), png) == 2);
    std::remove(scene.c_str());
  }
  // The other writers always sync: image-compare's contact sheet, say.
  CHECK(fsyncs(std::string(MINRT_IMAGE_COMPARE_BIN) + " --sheet " + d + "/sheet.png " + png + " " + png + " >/dev/null",
               d + "/sheet.png") == 2);
  for (const char* name : {"image.ppm", "image.png", "sheet.png", "trace"}) std::remove((d + "/" + name).c_str());
  CHECK(rmdir(dir) == 0);  // no temporary left behind
}

TEST_CASE("minrt: file argument, stdin and -o give the reference bytes", "[cli]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string scene = minrt::test::shared_dir() + "/scenes/ball.sld";
  std::string want;
  for (const auto& row : minrt::test::read_manifest(minrt::test::shared_dir() + "/reference/manifest.tsv"))
    if (row.scene == "ball" && row.size == 128) want = row.sha256;
  REQUIRE(!want.empty());
  const auto by_file = run("--size 128x128 " + scene);
  CHECK(by_file.status == 0);
  CHECK(minrt::host::sha256_hex(by_file.out) == want);
  const auto by_stdin = run("--size 128x128", scene);
  CHECK(by_stdin.out == by_file.out);
  char dir[] = "/tmp/minrt-out-XXXXXX";
  REQUIRE(mkdtemp(dir) != nullptr);
  const std::string target = std::string(dir) + "/ball.ppm";
  const auto o = run("--size 128x128 -o " + target + " " + scene);
  CHECK(o.status == 0);
  CHECK(o.out.empty());
  CHECK(minrt::test::read_file(target) == by_file.out);
  std::remove(target.c_str());
  rmdir(dir);
}

TEST_CASE("minrt: unknown codes warn on stderr and still render", "[cli]") {
  char path[] = "/tmp/minrt-scene-XXXXXX";
  const int fd = mkstemp(path);
  REQUIRE(fd >= 0);
  const std::string sld = "0 0 0 10 20\n1 30 40\n255\n7 3 1 0 5 5 5 0 0 0 1 1 0 255 255 255\n-1\n0 -1\n-1\n99 0 -1\n-1\n";
  REQUIRE(write(fd, sld.data(), sld.size()) == static_cast<ssize_t>(sld.size()));
  close(fd);
  const auto r = run(std::string("--size 8x8 ") + path);
  CHECK(r.status == 0);
  CHECK(r.err == std::string(path) + ":4:1: warning: object 0: unknown texture 7, drawn untextured as the original does\n");
  CHECK(count_lines(r.out) == 2 + 64);
  const auto quiet = run(std::string("-q --size 8x8 ") + path);
  CHECK(quiet.err.empty());
  std::remove(path);
}

TEST_CASE("minrt: --threads renders SLD rows on several threads with the same bytes", "[cli][threads]") {
  if (!minrt::test::shared_available()) {
    WARN("shared/ test data not found: skipped");
    return;
  }
  const std::string scene = minrt::test::shared_dir() + "/scenes/tsu3.sld";
  const auto one = run("--threads 1 --size 40x33 '" + scene + "'");
  REQUIRE(one.status == 0);
  REQUIRE(one.out.compare(0, 13, "P3\n40 33 255\n") == 0);
  for (const char* threads : {"2", "4"}) {
    CAPTURE(threads);
    const auto r = run(std::string("--threads ") + threads + " --size 40x33 '" + scene + "'");
    CHECK(r.status == 0);
    CHECK(r.out == one.out);
  }
  const auto every_core = run("--size 40x33 '" + scene + "'");  // the default
  CHECK(every_core.out == one.out);
  const auto bad = run("--threads 0 '" + scene + "'");
  CHECK(bad.status == 2);
  CHECK(bad.out.empty());
  CHECK(bad.err.find("bad --threads '0'") != std::string::npos);
}
