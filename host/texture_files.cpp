#include "texture_files.hpp"

#include <cstddef>

#include "png_io.hpp"

namespace minrt::host {

bool load_png_texture(const std::string& base_dir, const std::string& name, RgbTexture& out, std::string& error) {
  const std::string path = !name.empty() && name[0] == '/' ? name : base_dir + name;
  RgbaImage img;
  std::string why;
  if (!read_png(path, img, why)) {
    error = "texture " + path + ": " + why;
    return false;
  }
  // Kept as sRGB RGB8, like the board.
  out.width = img.width;
  out.height = img.height;
  out.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
  for (std::size_t i = 0, n = static_cast<std::size_t>(img.width) * img.height; i < n; ++i)
    for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = img.rgba[4 * i + c];
  return true;
}

bool probe_png_texture(const std::string& base_dir, const std::string& name, int& width, int& height,
                       std::string& error) {
  const std::string path = !name.empty() && name[0] == '/' ? name : base_dir + name;
  std::string why;
  if (png_header_size(path, width, height, why)) return true;
  error = "texture " + path + ": " + why;
  return false;
}

bool probe_minirt_texture(const std::string& base_dir, const std::string& name, int& width, int& height,
                          std::string& error) {
  error.clear();
  for (const std::string& path : minirt_texture_candidates(base_dir, name)) {
    std::string reason;
    if (ppm_header_size(path, width, height, reason)) return true;
    const bool missing = reason.find("No such file") != std::string::npos;
    if (error.empty() || !missing) error = path + ": " + reason;
    if (!missing) break;
  }
  return false;
}

std::vector<std::string> minirt_texture_candidates(const std::string& base_dir, const std::string& name) {
  if (!name.empty() && name[0] == '/') return {name};
  std::vector<std::string> c{base_dir + name};
  const std::size_t slash = name.rfind('/');
  if (slash != std::string::npos) c.push_back(base_dir + name.substr(slash + 1));
  return c;
}

bool load_minirt_texture(const std::string& base_dir, const std::string& name, RgbTexture& out, std::string& error) {
  error.clear();
  for (const std::string& path : minirt_texture_candidates(base_dir, name)) {
    std::string reason;
    if (read_ppm(path, out, reason)) return true;
    // A file that exists but is not a good PPM is the error to report.
    const bool missing = reason.find("No such file") != std::string::npos;
    if (error.empty() || !missing) error = path + ": " + reason;
    if (!missing) break;
  }
  return false;
}

int32_t TextureFiles::resolve(void* ctx, const char* name, Diagnostic& error) {
  return static_cast<TextureFiles*>(ctx)->find(name, error);
}

int32_t TextureFiles::find(const std::string& name, Diagnostic& error) {
  const auto it = ids_.find(name);
  if (it != ids_.end()) return it->second;
  if (textures_.size() >= static_cast<std::size_t>(max_count_)) {
    error.text("more than ").number(max_count_).text(" ").text(noun_);
    return -1;
  }
  auto tex = std::make_unique<RgbTexture>();
  std::string why;
  if (!load_(base_, name, *tex, why)) {
    error.text(why.c_str());
    return -1;
  }
  model::Texture t;
  t.width = tex->width;
  t.height = tex->height;
  t.rgb = tex->rgb.data();
  data_.push_back(std::move(tex));
  textures_.push_back(t);
  const auto id = static_cast<int32_t>(textures_.size() - 1);
  ids_[name] = id;
  return id;
}

}  // namespace minrt::host
