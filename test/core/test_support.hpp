// Helpers shared by the core tests: the shared/ data folder, reference
// manifests, and rendering a scene in-process to a byte string.
#pragma once

#include <string>
#include <vector>

#include "core/base/diagnostic.hpp"
#include "render/sld/render.hpp"
#include "render_variants.hpp"

namespace minrt::test {

// Path of the shared test data (../shared next to the checkout).
std::string shared_dir();
bool shared_available();
std::string read_file(const std::string& path);

struct ManifestEntry {
  std::string scene;
  int size = 0;
  std::string sha256;
};
// Rows of a reference manifest.tsv (header skipped).
std::vector<ManifestEntry> read_manifest(const std::string& path);

struct RenderResult {
  RenderStatus status = RenderStatus::kOk;
  std::string image;
  Diagnostic error;
  std::vector<std::string> warnings;
};

// A fresh directory /tmp/minrt-TAG-XXXXXX; the test fails when it cannot
// be made.
std::string temp_dir(const std::string& tag);

struct CommandRun {
  int status = -1;  // exit status; -1 when killed by a signal
  std::string err;  // what it wrote to standard error
};
// Runs the shell command line `command` in `cwd` with standard input from
// `input` and standard output discarded.
CommandRun run_in_dir(const std::string& cwd, const std::string& command, const std::string& input = "/dev/null");

// threads: as minrt --threads (0: every core).
RenderResult render_bytes(const std::string& sld, int width, int height,
                          PpmFormat format = PpmFormat::kP3,
                          host::Variant variant = host::Variant{}, int threads = 1);

}  // namespace minrt::test
