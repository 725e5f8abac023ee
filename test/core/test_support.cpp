#include "test_support.hpp"

#include <catch2/catch.hpp>

#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace minrt::test {

std::string shared_dir() {
  if (const char* env = std::getenv("MINRT_SHARED_DIR")) return env;
  return MINRT_SHARED_DIR;
}

bool shared_available() {
  struct stat st {};
  return ::stat((shared_dir() + "/scenes").c_str(), &st) == 0;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string temp_dir(const std::string& tag) {
  std::string dir = "/tmp/minrt-" + tag + "-XXXXXX";
  REQUIRE(::mkdtemp(dir.data()) != nullptr);
  return dir;
}

CommandRun run_in_dir(const std::string& cwd, const std::string& command, const std::string& input) {
  const std::string err = cwd + "/.stderr";
  const std::string line = "cd '" + cwd + "' && " + command + " 2>" + err + " >/dev/null <'" + input + "'";
  const int rc = std::system(line.c_str());
  CommandRun r;
  r.status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  r.err = read_file(err);
  std::remove(err.c_str());
  return r;
}

std::vector<ManifestEntry> read_manifest(const std::string& path) {
  std::vector<ManifestEntry> rows;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    ManifestEntry e;
    std::string size;
    std::getline(fields, e.scene, '\t');
    std::getline(fields, size, '\t');
    std::getline(fields, e.sha256, '\t');
    if (e.scene.empty()) continue;
    e.size = std::stoi(size);
    rows.push_back(e);
  }
  return rows;
}

namespace {

void append(void* ctx, const uint8_t* data, size_t size) {
  static_cast<std::string*>(ctx)->append(reinterpret_cast<const char*>(data), size);
}

void collect_warning(void* ctx, const Diagnostic& d) {
  static_cast<std::vector<std::string>*>(ctx)->push_back(d.message);
}

}  // namespace

RenderResult render_bytes(const std::string& sld, int width, int height, PpmFormat format,
                          host::Variant variant, int threads) {
  RenderResult r;
  MemorySource src{reinterpret_cast<const uint8_t*>(sld.data()), sld.size()};
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.format = format;
  r.status = host::render_variant(variant, src.source(), ByteSink{&append, &r.image}, options,
                                  r.error, WarningSink{&collect_warning, &r.warnings}, threads);
  return r;
}

}  // namespace minrt::test
