#include "eastray_stereo.hpp"

namespace minrt::host {

std::string eastray_stereo_name(const std::string& path, char side) {
  const std::string tag = std::string("_") + side;
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) || dot == slash + 1) return path + tag;
  return path.substr(0, dot) + tag + path.substr(dot);
}

}  // namespace minrt::host
