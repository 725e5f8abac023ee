// Helpers shared by the core tests: the shared/ data folder, reference
// manifests, and rendering a scene in-process to a byte string.
#pragma once

#include <string>
#include <vector>

#include "core/base/diagnostic.hpp"
#include "render/minrt/render.hpp"
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

// threads: as minrt --threads (0: every core).
RenderResult render_bytes(const std::string& sld, int width, int height,
                          PpmFormat format = PpmFormat::kP3,
                          host::Variant variant = host::Variant{}, int threads = 1);

}  // namespace minrt::test
