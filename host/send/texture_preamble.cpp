#include "texture_preamble.hpp"

#include <set>
#include <sstream>
#include <vector>

#include <minrt/serial_protocol.h>

#include "eastray_maps.hpp"
#include "texture_files.hpp"

namespace minrt::send {

namespace {

using minrt::host::RgbTexture;
using minrt::host::TextureLoader;
using minrt::host::TextureProbe;

// `where`: for each name, the "SCENE:LINE:COL: error: " its errors start
// with (empty: not located).
bool assemble(const std::vector<std::string>& names, const std::vector<std::string>& where,
              const std::string& base_dir, TextureProbe probe, TextureLoader load, std::uint64_t board_bytes,
              std::string& out, std::string& error) {
  out.clear();
  if (names.empty()) return true;
  if (names.size() > MINRT_MAX_TEXTURES) {
    error = "more than " + std::to_string(MINRT_MAX_TEXTURES) + " textures";
    return false;
  }
  // The headers' sizes first: a texture over the side limit, or textures
  // over the board's memory, are refused before any is decoded.
  std::uint64_t texel_bytes = 0;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    if (name.size() > 255) {
      error = at + "texture name longer than 255 bytes";
      return false;
    }
    int width = 0, height = 0;
    if (!probe(base_dir, name, width, height, error)) {
      error = at + error;
      return false;
    }
    if (width > MINRT_MAX_TEXTURE_SIDE || height > MINRT_MAX_TEXTURE_SIDE) {
      error = at + "texture " + name + " is " + std::to_string(width) + "x" + std::to_string(height) +
              ", larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    texel_bytes += static_cast<std::uint64_t>(width) * height * 3;
  }
  if (texel_bytes > board_bytes) {
    error = "the textures need " + std::to_string(texel_bytes) + " bytes of the board's memory and at most " +
            std::to_string(board_bytes) + " are free (firmware-sim: --sim-ram-size to give the simulated board more)";
    return false;
  }
  std::string body;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string& name = names[k];
    const std::string at = k < where.size() ? where[k] : std::string();
    RgbTexture img;
    if (!load(base_dir, name, img, error)) {
      error = at + error;
      return false;
    }
    if (img.width > MINRT_MAX_TEXTURE_SIDE || img.height > MINRT_MAX_TEXTURE_SIDE) {
      error = at + "texture " + name + " is larger than " + std::to_string(MINRT_MAX_TEXTURE_SIDE) + " pixels a side";
      return false;
    }
    body.push_back(static_cast<char>(name.size()));
    body += name;
    for (int v : {img.width, img.height}) {
      body.push_back(static_cast<char>(v & 0xff));
      body.push_back(static_cast<char>(v >> 8));
    }
    body.append(reinterpret_cast<const char*>(img.rgb.data()), img.rgb.size());
  }
  out.push_back(static_cast<char>(MINRT_TEXTURES_MARKER));
  out.push_back(static_cast<char>(names.size()));
  out += body;
  return true;
}

}  // namespace

bool build_texture_preamble(const std::string& scene, const std::string& scene_name, const std::string& base_dir,
                            std::uint64_t board_bytes, std::string& out, std::string& error) {
  std::vector<std::string> names;
  std::vector<std::string> where;  // each name's first use, as the reader counts lines and columns
  std::set<std::string> seen;
  std::istringstream lines(scene);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::string kw, name;
    if (!(words >> kw) || kw != "texture" || !(words >> name) || name == "none") continue;
    if (!seen.insert(name).second) continue;
    names.push_back(name);
    const std::size_t col = line.find(name, line.find("texture") + 7) + 1;
    where.push_back(scene_name + ":" + std::to_string(number) + ":" + std::to_string(col) + ": error: ");
  }
  return assemble(names, where, base_dir, &minrt::host::probe_png_texture, &minrt::host::load_png_texture, board_bytes, out, error);
}

bool build_minirt_texture_preamble(const std::string& scene, const std::string& scene_name,
                                   const std::string& base_dir, std::uint64_t board_bytes, std::string& out,
                                   std::string& error) {
  std::vector<std::string> names, where;
  std::set<std::string> seen;
  std::istringstream lines(scene);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (w.empty() || w[0] != "spt") continue;
    for (std::size_t i = 4; i < w.size() && i < 6; ++i) {  // texture, then the optional bump map
      if (!seen.insert(w[i]).second) continue;
      names.push_back(w[i]);
      // minrt's miniRT message for the same file: SCENE:LINE: FIELD "NAME": PATH: reason.
      where.push_back(scene_name + ":" + std::to_string(number) + ": textured sphere " +
                      (i == 4 ? "texture" : "bump map") + " \"" + w[i] + "\": ");
    }
  }
  return assemble(names, where, base_dir, &minrt::host::probe_minirt_texture, &minrt::host::load_minirt_texture, board_bytes, out, error);
}

bool build_eastray_texture_preamble(const std::vector<std::pair<std::string, std::string>>& maps,
                                    const std::string& base_dir, std::uint64_t board_bytes, std::string& out,
                                    std::string& error) {
  std::vector<std::string> names, where;
  std::set<std::string> seen;
  for (const auto& m : maps) {
    if (!seen.insert(m.first).second) continue;
    names.push_back(m.first);
    where.push_back(m.second);
  }
  return assemble(names, where, base_dir, &minrt::host::probe_eastray_map, &minrt::host::load_eastray_map, board_bytes, out,
                  error);
}

}  // namespace minrt::send
