#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "core/base/arena.hpp"
#include "png_io.hpp"
#include "protocol/texture_blobs.hpp"

namespace hs_test {

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void write_texture(const std::string& path, int w, int h, std::uint32_t seed, int gx, int gy, int noise_shift) {
  minrt::host::RgbaImage img;
  img.width = w;
  img.height = h;
  img.rgba.resize(static_cast<std::size_t>(w) * h * 4);
  std::uint32_t x = seed;
  for (int y = 0; y < h; ++y)
    for (int i = 0; i < w; ++i) {
      std::uint8_t* p = img.rgba.data() + (static_cast<std::size_t>(y) * w + i) * 4;
      x = x * 1664525u + 1013904223u;
      p[0] = static_cast<std::uint8_t>(i * gx + (x >> noise_shift));
      p[1] = static_cast<std::uint8_t>(y * gy + (x >> (noise_shift + 1)));
      p[2] = static_cast<std::uint8_t>((i ^ y) + (x >> (noise_shift - 1)));
      p[3] = 255;
    }
  std::FILE* f = std::fopen(path.c_str(), "wb");
  REQUIRE(f != nullptr);
  std::string why;
  REQUIRE(minrt::host::write_png(f, img, why));
  std::fclose(f);
}

std::string unpack_textures_error(const std::string& preamble) {
  std::vector<std::uint8_t> mem(1 << 20);
  minrt::Arena arena(mem.data(), mem.size());
  minrt::send::textures::Table table{};
  minrt::Diagnostic error;
  std::size_t used = 0;
  const bool ok = minrt::send::textures::unpack(reinterpret_cast<const std::uint8_t*>(preamble.data()), preamble.size(),
                                                arena, table, used, error);
  return ok ? std::string() : std::string(error.message, error.length);
}

bool file_exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

TempDir::TempDir() {
  char tmpl[] = "/tmp/host_send_test.XXXXXX";
  path = ::mkdtemp(tmpl);
}

TempDir::~TempDir() {
  if (DIR* d = ::opendir(path.c_str())) {
    while (dirent* e = ::readdir(d))
      if (e->d_name[0] != '.') ::unlink((path + "/" + e->d_name).c_str());
    ::closedir(d);
  }
  ::rmdir(path.c_str());
}

RunResult run(const std::vector<std::string>& argv, int timeout_s) {
  RunResult r;
  TempDir dir;
  const std::string out_path = dir.file("stdout"), err_path = dir.file("stderr");
  const pid_t pid = start_program(argv, out_path, err_path);
  int st = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  for (;;) {
    const pid_t w = ::waitpid(pid, &st, WNOHANG);
    if (w == pid) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &st, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.out = read_file(out_path);
  r.err = read_file(err_path);
  return r;
}

std::string reference_image(const std::string& scene, const std::string& size, const std::string& format) {
  TempDir dir;
  const std::string out = dir.file("ref.ppm");
  run({HS_MINRT, "--size", size, "--format", format, "--precision", "float", "--shims", "portable", "-q", "-o", out,
       scene});
  return read_file(out);
}

void start_standin(minrt::send::SimLauncher& board, const std::string& size, const std::string& format,
                   const std::string& protocol) {
  minrt::send::SimConfig cfg;
  cfg.simulator = HS_STANDIN;
  cfg.firmware = HS_STANDIN;  // ignored by the stand-in
  cfg.firmware_args = {"--size", size, "--format", format, "--protocol=" + protocol};
  std::string err;
  if (!board.start(cfg, err)) throw std::runtime_error("cannot start the stand-in board: " + err);
}

bool firmware_available() {
  return ::access(HS_FIRMWARE_SIM, X_OK) == 0 && ::access(HS_FIRMWARE_ELF, R_OK) == 0;
}

std::string shared_dir() { return HS_SHARED_DIR; }

std::vector<std::string> bad_scenes() {
  std::vector<std::string> out;
  const std::string dir = shared_dir() + "/bad";
  if (DIR* d = ::opendir(dir.c_str())) {
    while (dirent* e = ::readdir(d)) {
      const std::string n = e->d_name;
      if (n.size() > 4 && n.compare(n.size() - 4, 4, ".sld") == 0) out.push_back(dir + "/" + n);
    }
    ::closedir(d);
  }
  std::sort(out.begin(), out.end());
  return out;
}

RunResult send_sim(const std::string& scene, const std::string& out, const std::vector<std::string>& extra) {
  std::vector<std::string> argv{HS_HOST_SEND, "--sim-binary", HS_FIRMWARE_SIM, "--sim", HS_FIRMWARE_ELF};
  argv.insert(argv.end(), extra.begin(), extra.end());
  argv.push_back(scene);
  argv.push_back("-o");
  argv.push_back(out);
  return run(argv);
}

const std::vector<std::vector<std::string>>& text_protocols() {
  static const std::vector<std::vector<std::string>> p = {
      {"--protocol", "course"}, {"--protocol", "course", "--endian", "big"}, {"--protocol", "framed"}};
  return p;
}

std::string joined(const std::vector<std::string>& words) {
  std::string s;
  for (const auto& w : words) s += (s.empty() ? "" : " ") + w;
  return s;
}

void check_png_on_every_protocol(const TempDir& dir, const std::string& scene, const std::vector<std::string>& extra) {
  const std::string host = dir.file("host.png");
  std::vector<std::string> model{HS_MINRT, "-q", "--precision", "float", "--shims", "portable", scene, "-o", host};
  model.insert(model.end(), extra.begin(), extra.end());
  const RunResult m = run(model);
  INFO(scene << "\n" << m.err);
  REQUIRE(m.status == 0);
  const std::string raw = dir.file("raw.png");
  const RunResult r = send_sim(scene, raw, extra);
  INFO(r.err);
  REQUIRE(r.status == 0);
  minrt::host::RgbaImage want;
  std::string why;
  REQUIRE(minrt::host::read_png(host, want, why));
  for (const auto& protocol : text_protocols()) {
    const std::string got = dir.file("got.png");
    std::vector<std::string> options = protocol;
    options.insert(options.end(), extra.begin(), extra.end());
    const RunResult p = send_sim(scene, got, options);
    INFO(joined(protocol) << "\n" << p.err);
    REQUIRE(p.status == 0);
    CHECK(read_file(got) == read_file(raw));
    minrt::host::RgbaImage img;
    REQUIRE(minrt::host::read_png(got, img, why));
    CHECK(img.width == want.width);
    CHECK(img.height == want.height);
    CHECK(img.rgba == want.rgba);
  }
}

// The children of `parent`, from /proc/*/stat (field 4 is the parent pid).
std::vector<pid_t> children_of(pid_t parent) {
  std::vector<pid_t> out;
  DIR* d = ::opendir("/proc");
  if (d == nullptr) return out;
  while (const dirent* e = ::readdir(d)) {
    const pid_t pid = static_cast<pid_t>(std::atoi(e->d_name));
    if (pid <= 0) continue;
    std::ifstream f("/proc/" + std::string(e->d_name) + "/stat");
    std::string line;
    if (!std::getline(f, line)) continue;
    const std::size_t close = line.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream rest(line.substr(close + 2));
    char state = 0;
    pid_t ppid = 0;
    rest >> state >> ppid;
    if (ppid == parent) out.push_back(pid);
  }
  ::closedir(d);
  return out;
}

bool alive(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return false;
  const std::size_t close = line.rfind(')');
  return close != std::string::npos && line[close + 2] != 'Z';
}

}  // namespace hs_test
