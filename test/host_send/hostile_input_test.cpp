// Hostile inputs to minrt and host-send: self-doubling EASTRAY includes and
// macros, a PNG whose header claims 16384x16384, FIFOs where files are
// expected, fatal signals during a render with -o, and a 254-byte output
// name. Each asserts the behaviour (status, message, memory, what is left
// in the folder); the limits make the refusals fast, so no timing is asserted.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "child_process.hpp"
#include "core/base/crc32.hpp"

namespace {

struct Run {
  int status = -1;      // exit status, or 128 + signal
  long max_rss_kib = 0;
  std::string err;
};

// Runs argv in `dir`; `signal_after_ms` >= 0 sends `sig` that long after the
// start. A run over 60 s is killed (status 137) so a hang fails the test.
Run run(const std::vector<std::string>& argv, const std::string& dir, int sig = 0, int signal_after_ms = -1) {
  const std::string err_path = dir + "/.stderr";
  const pid_t pid = hs_test::start_program(argv, "/dev/null", err_path, dir);
  const auto start = std::chrono::steady_clock::now();
  bool signalled = false;
  int st = 0;
  rusage ru{};
  for (;;) {
    const pid_t w = ::wait4(pid, &st, WNOHANG, &ru);
    if (w == pid) break;
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - start).count();
    if (!signalled && signal_after_ms >= 0 && ms >= signal_after_ms) {
      ::kill(pid, sig);
      signalled = true;
    }
    if (ms > 60000) ::kill(pid, SIGKILL);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  Run r;
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.max_rss_kib = ru.ru_maxrss;
  std::ifstream f(err_path);
  std::stringstream ss;
  ss << f.rdbuf();
  r.err = ss.str();
  ::unlink(err_path.c_str());
  return r;
}

struct Dir {
  std::string path;
  Dir() {
    char t[] = "/tmp/hostile-XXXXXX";
    path = ::mkdtemp(t);
  }
  ~Dir() { std::system(("rm -rf '" + path + "'").c_str()); }
  std::string file(const std::string& name) const { return path + "/" + name; }
  void write(const std::string& name, const std::string& text) const { std::ofstream(file(name)) << text; }
  // Every entry but the test's own.
  std::vector<std::string> entries() const {
    std::vector<std::string> out;
    if (DIR* d = ::opendir(path.c_str())) {
      while (dirent* e = ::readdir(d)) {
        const std::string n = e->d_name;
        if (n != "." && n != "..") out.push_back(n);
      }
      ::closedir(d);
    }
    return out;
  }
};

constexpr long kMemoryBoundKiB = 64 * 1024;

// 41 files, each including the one before twice: 2^41 inclusions unbounded.
void write_doubling_includes(const Dir& d) {
  d.write("inc0.h", "sphere 0 0 0 1\n");
  for (int k = 1; k <= 40; ++k)
    d.write("inc" + std::to_string(k) + ".h", "#include \"inc" + std::to_string(k - 1) + ".h\"\n#include \"inc" +
                                                  std::to_string(k - 1) + ".h\"\n");
  d.write("top.ray", "/* EASTRAY */\n#include \"inc40.h\"\n");
}

// A #define doubled 18 times: 2^18 copies of its first body.
void write_doubling_macros(const Dir& d) {
  std::string s = "/* EASTRAY */\n#define M0 sphere 0 0 0 1\n";
  for (int k = 1; k <= 18; ++k)
    s += "#define M" + std::to_string(k) + " M" + std::to_string(k - 1) + " M" + std::to_string(k - 1) + "\n";
  s += "M18\n";
  d.write("top.ray", s);
}

void put_be32(std::string& s, uint32_t v) {
  for (int i = 3; i >= 0; --i) s.push_back(static_cast<char>(v >> (8 * i)));
}

void chunk(std::string& png, const char* type, const std::string& data) {
  put_be32(png, static_cast<uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  png += body;
  put_be32(png, minrt::crc32(reinterpret_cast<const uint8_t*>(body.data()), body.size()));
}

// A PNG whose header says 16384x16384 RGB; its IDAT is an empty zlib
// stream, so a reader that trusts the header and allocates first is caught
// by its memory, one that checks the header refuses at once.
std::string png_claiming(uint32_t side) {
  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  put_be32(ihdr, side);
  put_be32(ihdr, side);
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);
  chunk(png, "IHDR", ihdr);
  chunk(png, "IDAT", std::string("\x78\x01\x01\x00\x00\xff\xff\x00\x00\x00\x01", 11));
  chunk(png, "IEND", "");
  return png;
}

const char kCs418Textured[] = "png 8 8 out.png\nsun 1 1 1\ncolor 1 1 1\ntexture big.png\nsphere 0 0 -1 0.4\n";

}  // namespace

TEST_CASE("EASTRAY includes that double at every level are refused by the budget, in little memory") {
  Dir d;
  write_doubling_includes(d);
  const Run m = run({HS_MINRT, "-o", "out.png", "top.ray"}, d.path);
  INFO(m.err);
  CHECK(m.status == 2);
  CHECK(m.err.find("expands past") != std::string::npos);
  CHECK(m.err.find("inc") != std::string::npos);  // located in an include file
  CHECK(m.max_rss_kib < kMemoryBoundKiB);
  // host-send: "scene rejected before sending", status 3, before any port.
  const Run h = run({HS_HOST_SEND, "-p", "/dev/null", "top.ray"}, d.path);
  INFO(h.err);
  CHECK(h.status == 3);
  CHECK(h.err.find("expands past") != std::string::npos);
  CHECK(h.max_rss_kib < kMemoryBoundKiB);
}

TEST_CASE("an EASTRAY #define doubled 18 times is refused by the budget, in little memory") {
  Dir d;
  write_doubling_macros(d);
  const Run m = run({HS_MINRT, "-o", "out.png", "top.ray"}, d.path);
  INFO(m.err);
  CHECK(m.status == 2);
  CHECK(m.err.find("top.ray:") != std::string::npos);
  CHECK(m.err.find("expands past") != std::string::npos);
  CHECK(m.max_rss_kib < kMemoryBoundKiB);
}

TEST_CASE("a PNG texture whose header claims 16384x16384 is refused by its header") {
  Dir d;
  d.write("big.png", png_claiming(16384));
  d.write("scene.txt", kCs418Textured);
  const Run m = run({HS_MINRT, "scene.txt"}, d.path);
  INFO(m.err);
  CHECK(m.status == 2);
  CHECK(m.err.find("nothing decoded") != std::string::npos);
  CHECK(m.max_rss_kib < kMemoryBoundKiB);
  // host-send weighs the header's size against the board's memory first.
  const Run h = run({HS_HOST_SEND, "-p", "/dev/null", "scene.txt"}, d.path);
  INFO(h.err);
  CHECK(h.status == 3);
  CHECK(h.err.find("texture big.png (16384x16384) takes the textures to 805306368 bytes decoded") !=
        std::string::npos);  // 16384 x 16384 x 3
  CHECK(h.err.find("bytes the board has for them") != std::string::npos);
  CHECK(h.max_rss_kib < kMemoryBoundKiB);
}

TEST_CASE("a FIFO as texture, include, --verify or --program is refused at once") {
  Dir d;
  REQUIRE(::mkfifo(d.file("big.png").c_str(), 0600) == 0);
  REQUIRE(::mkfifo(d.file("fifo.h").c_str(), 0600) == 0);
  d.write("scene.txt", kCs418Textured);
  d.write("top.ray", "/* EASTRAY */\n#include \"fifo.h\"\n");
  d.write("ball.sld", "0 0 0\n");
  // No writer ever opens the FIFOs: a blocking open() would hang until the
  // runner's 60 s kill (status 137).
  const Run tex = run({HS_MINRT, "scene.txt"}, d.path);
  INFO(tex.err);
  CHECK(tex.status == 2);
  CHECK(tex.err.find("FIFO") != std::string::npos);
  const Run inc = run({HS_MINRT, "-o", "out.png", "top.ray"}, d.path);
  INFO(inc.err);
  CHECK(inc.status == 2);
  CHECK(inc.err.find("FIFO") != std::string::npos);
  const Run tex_send = run({HS_HOST_SEND, "-p", "/dev/null", "scene.txt"}, d.path);
  INFO(tex_send.err);
  CHECK(tex_send.status == 3);
  CHECK(tex_send.err.find("FIFO") != std::string::npos);
  const Run verify = run({HS_HOST_SEND, "-p", "/dev/null", "--verify", "fifo.h", "ball.sld"}, d.path);
  INFO(verify.err);
  CHECK(verify.status == 2);
  CHECK(verify.err.find("FIFO") != std::string::npos);
  const Run program =
      run({HS_HOST_SEND, "-p", "/dev/null", "--protocol", "course", "--program", "fifo.h", "ball.sld"}, d.path);
  INFO(program.err);
  CHECK(program.status == 2);
  CHECK(program.err.find("FIFO") != std::string::npos);
}

TEST_CASE("SIGKILL, SIGXFSZ and SIGUSR1 during minrt -o leave nothing beside the target") {
  const std::string scene = std::string(HS_SHARED_DIR) + "/scenes/contest.sld";
  if (::access(scene.c_str(), R_OK) != 0) {
    WARN("skipped: " << scene << " missing");
    return;
  }
  for (int sig : {SIGKILL, SIGXFSZ, SIGUSR1}) {
    Dir d;
    const Run r = run({HS_MINRT, "--size", "1024x1024", "--threads", "1", "-o", "out.ppm", scene}, d.path, sig, 400);
    INFO("signal " << sig << ": " << r.err);
    CHECK(r.status == 128 + sig);  // ended by the signal, mid-render
    CHECK(d.entries().empty());
  }
}

TEST_CASE("a 254-byte output name is written (its temporary name fits NAME_MAX)") {
  const std::string scene = std::string(HS_SHARED_DIR) + "/scenes/ball.sld";
  if (::access(scene.c_str(), R_OK) != 0) {
    WARN("skipped: " << scene << " missing");
    return;
  }
  Dir d;
  const std::string name = std::string(250, 'n') + ".ppm";
  REQUIRE(name.size() == 254);
  const Run r = run({HS_MINRT, "--size", "8x8", "-o", name, scene}, d.path);
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(d.entries() == std::vector<std::string>{name});
}

TEST_CASE("an output name a scene chooses stays in the scene's or the working folder") {
  Dir d;
  REQUIRE(::mkdir(d.file("work").c_str(), 0700) == 0);
  REQUIRE(::mkdir(d.file("scenes").c_str(), 0700) == 0);
  d.write("scenes/up.txt", "png 8 8 ../x.png\nsun 1 1 1\ncolor 1 1 1\nsphere 0 0 -1 0.4\n");
  std::ifstream shared(std::string(HS_SHARED_DIR) + "/formats/eastray/csg_or_and_diff_range.ray");
  std::stringstream ray;
  ray << shared.rdbuf();
  const bool have_ray = !ray.str().empty();
  d.write("scenes/abs.ray", ray.str() + "\noutput " + d.file("abs.png") + " ;\n");
  const std::string work = d.file("work");
  const Run cs418 = run({HS_MINRT, "../scenes/up.txt"}, work);
  INFO(cs418.err);
  CHECK(cs418.status != 0);
  CHECK(cs418.err.find("named by the scene") != std::string::npos);
  CHECK(::access(d.file("x.png").c_str(), F_OK) != 0);
  if (have_ray) {
    const Run eastray = run({HS_MINRT, "../scenes/abs.ray"}, work);
    INFO(eastray.err);
    CHECK(eastray.status != 0);
    CHECK(eastray.err.find("named by the scene") != std::string::npos);
    CHECK(::access(d.file("abs.png").c_str(), F_OK) != 0);
  }
  const Run send = run({HS_HOST_SEND, "-p", "/dev/null", "../scenes/up.txt"}, work);
  INFO(send.err);
  CHECK(send.status == 2);
  CHECK(send.err.find("named by the scene") != std::string::npos);
  // --allow-any-output lets the scene choose; -o names the output itself.
  const Run allowed = run({HS_MINRT, "--allow-any-output", "../scenes/up.txt"}, work);
  INFO(allowed.err);
  CHECK(allowed.status == 0);
  CHECK(::access(d.file("x.png").c_str(), F_OK) == 0);
  const Run named = run({HS_MINRT, "-o", "../y.png", "../scenes/up.txt"}, work);
  INFO(named.err);
  CHECK(named.status == 0);
  CHECK(::access(d.file("y.png").c_str(), F_OK) == 0);
}

TEST_CASE("a Jaworski scene of one sphere and a 10 MB comment renders in little memory") {
  // The arena follows what the scene holds, not its bytes: a comment costs
  // nothing (sized from the file, this took 873 MB).
  const Dir d;
  std::string scene = "# " + std::string(10u << 20, 'c') + "\n";
  scene += "imWidth 16\nimHeight 12\ncanvWidth 4\ncanvHeight 3\ndepth 4\nlights\ndirectional 1 white 1 -1 2\n"
           "objects\nsphere 0 0 6 2.5 diffusive white\n";
  d.write("big-comment.txt", scene);
  const Run r = run({HS_MINRT, "-o", "out.bmp", "big-comment.txt"}, d.path);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.max_rss_kib < kMemoryBoundKiB);
  // The same image as the scene without its comment.
  d.write("plain.txt", scene.substr(scene.find('\n') + 1));
  REQUIRE(run({HS_MINRT, "-o", "plain.bmp", "plain.txt"}, d.path).status == 0);
  std::ifstream a(d.file("out.bmp"), std::ios::binary), b(d.file("plain.bmp"), std::ios::binary);
  std::stringstream sa, sb;
  sa << a.rdbuf();
  sb << b.rdbuf();
  CHECK(sa.str().size() > 54);
  CHECK(sa.str() == sb.str());
}

TEST_CASE("minrt -o with an empty name is a usage error, not standard output") {
  const Dir d;
  d.write("s.txt", "imWidth 4\nimHeight 4\ncanvWidth 4\ncanvHeight 3\ndepth 1\nlights\nobjects\n");
  const Run r = run({HS_MINRT, "-o", "", "s.txt"}, d.path);
  CHECK(r.status == 2);
  CHECK(r.err.find("expected a file name") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

TEST_CASE("a write error on minrt's standard output names it once") {
  // /dev/full as standard output: every write fails with ENOSPC.
  const Dir d;
  d.write("s.txt", "imWidth 4\nimHeight 4\ncanvWidth 4\ncanvHeight 3\ndepth 1\nlights\nobjects\n");
  const std::string err_path = d.file(".stderr");
  const std::string cmd = std::string(HS_MINRT) + " -o - " + d.file("s.txt") + " >/dev/full 2>" + err_path;
  const int rc = std::system(cmd.c_str());
  std::ifstream f(err_path);
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string err = ss.str();
  CHECK(WIFEXITED(rc));
  CHECK(WEXITSTATUS(rc) != 0);
  CHECK(err.find("cannot write -:") != std::string::npos);
  CHECK(err.find("cannot write -: cannot write") == std::string::npos);
  CHECK(std::count(err.begin(), err.end(), '\n') == 1);
}
