#include "file_input.hpp"

#include <cstdio>

namespace minrt::host {

bool read_scene_file(const std::string& path, std::string& text, std::size_t max_bytes) {
  if (path == "-") return true;
  std::string why;
  if (read_whole_file(path, text, why, max_bytes)) return true;
  std::fprintf(stderr, "minrt: error: cannot read %s: %s\n", path.c_str(), why.c_str());
  return false;
}

}  // namespace minrt::host
