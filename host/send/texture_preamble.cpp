#include "texture_preamble.hpp"

#include <set>
#include <sstream>
#include <vector>

#include <minrt/serial_protocol.h>

#include "png_io.hpp"

namespace minrt::send {

bool build_texture_preamble(const std::string& scene, const std::string& base_dir, std::uint64_t board_bytes,
                            std::string& out, std::string& error) {
  out.clear();
  std::vector<std::string> names;
  std::set<std::string> seen;
  std::istringstream lines(scene);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string kw, name;
    if (!(words >> kw) || kw != "texture" || !(words >> name) || name == "none") continue;
    if (seen.insert(name).second) names.push_back(name);
  }
  if (names.empty()) return true;
  if (names.size() > MINRT_MAX_TEXTURES) {
    error = "more than " + std::to_string(MINRT_MAX_TEXTURES) + " textures";
    return false;
  }
  std::string body;
  std::uint64_t texel_bytes = 0;
  for (const std::string& name : names) {
    if (name.size() > 255) {
      error = "texture name longer than 255 bytes";
      return false;
    }
    const std::string path = name[0] == '/' ? name : base_dir + name;
    minrt::host::RgbaImage img;
    std::string why;
    if (!minrt::host::read_png(path, img, why)) {
      error = "texture " + path + ": " + why;
      return false;
    }
    if (img.width > MINRT_MAX_TEXTURE_SIDE || img.height > MINRT_MAX_TEXTURE_SIDE) {
      error = "texture " + path + " is larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    texel_bytes += static_cast<std::uint64_t>(img.width) * img.height * 3;
    body.push_back(static_cast<char>(name.size()));
    body += name;
    for (int v : {img.width, img.height}) {
      body.push_back(static_cast<char>(v & 0xff));
      body.push_back(static_cast<char>(v >> 8));
    }
    for (std::size_t i = 0, n = static_cast<std::size_t>(img.width) * img.height; i < n; ++i)
      body.append(reinterpret_cast<const char*>(&img.rgba[4 * i]), 3);
  }
  if (texel_bytes > board_bytes) {
    error = "the textures need " + std::to_string(texel_bytes) + " bytes of the board's memory and at most " +
            std::to_string(board_bytes) + " are free (firmware-sim: --sim-ram-size to give the simulated board more)";
    return false;
  }
  out.push_back(static_cast<char>(MINRT_TEXTURES_MARKER));
  out.push_back(static_cast<char>(names.size()));
  out += body;
  return true;
}

}  // namespace minrt::send
