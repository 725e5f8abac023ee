// EASTRAY's map_data images on the host (manual lines 369-398,
// docs/eastray.md "Mapping"): each file the scene names, found beside the
// scene or in the current folder and decoded by its extension to 8-bit RGB:
// `.tif`/`.tiff` through libtiff (every kind the manual lists: 2, 16 and
// 256 colours with palettes, 32K and full colour, compressed), `.png`
// through libpng, `.ppm`/`.pnm` here. `.fal` and `.ipr` (FM TOWNS raw RGB
// with a header file) no library reads: an error with the command that
// converts them.
#pragma once

#include <string>
#include <vector>

#include "formats/model/eastray_mapping.hpp"
#include "formats/model/scene.hpp"
#include "texture_files.hpp"

namespace minrt::host {

// Decodes one map file (the name as written, `\` read as `/`) relative to
// `base_dir` (the scene's folder with its slash, or empty), else the
// current folder. False with "FILE: REASON".
bool load_eastray_map(const std::string& base_dir, const std::string& name, RgbTexture& out, std::string& error);

// The size load_eastray_map would decode, from a PNG's or PPM's header (a
// TIFF is decoded): host-send weighs it against the board's memory first.
bool probe_eastray_map(const std::string& base_dir, const std::string& name, int& width, int& height,
                       std::string& error);

// The decoded images of a scene's map_data entries, in order.
class EastrayMaps {
 public:
  explicit EastrayMaps(const std::string& scene_path);
  // Loads entries [0, count); on failure `bad` is the entry and `error`
  // says why.
  bool load(const model::EastrayMapFile* files, int count, int& bad, std::string& error);
  const model::Texture* table() const { return textures_.empty() ? nullptr : textures_.data(); }
  int count() const { return static_cast<int>(textures_.size()); }
  // The `input` statement's background image (read like the maps).
  bool load_input(const std::string& name, std::string& error);
  const model::Texture* input() const { return has_input_ ? &input_ : nullptr; }

 private:
  TextureFiles files_;
  std::vector<model::Texture> textures_;
  model::Texture input_;
  bool has_input_ = false;
};

}  // namespace minrt::host
