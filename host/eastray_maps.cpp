#include "eastray_maps.hpp"

#include <sys/stat.h>

#include "png_io.hpp"
#include "ppm_texture.hpp"
#include "tiff_io.hpp"

namespace minrt::host {

namespace {

// The most images one scene may name (each is decoded once).
constexpr int kMaxMapFiles = 256;

std::string lower_extension(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::size_t slash = name.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = name.substr(dot);
  for (char& c : e)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return e;
}

bool is_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string scene_folder(const std::string& scene_path) {
  const std::size_t slash = scene_path.rfind('/');
  return slash == std::string::npos ? std::string() : scene_path.substr(0, slash + 1);
}

}  // namespace

namespace {

// The file a map's name as written stands for, and its extension in lower
// case; false with the reason (an old format, a wrong extension, no file).
bool find_map_file(const std::string& base_dir, const std::string& written, std::string& path, std::string& ext,
                   std::string& error) {
  std::string name = written;
  for (char& c : name)
    if (c == '\\') c = '/';
  ext = lower_extension(name);
  if (ext == ".fal" || ext == ".ipr") {
    error = name + ": " + ext.substr(1) +
            " images (raw RGB with a header) are not read; convert the raw RGB file to TIFF, e.g. "
            "'convert -size WxH -depth 8 rgb:FILE.rgb FILE.tif', and name the .tif";
    return false;
  }
  if (ext != ".tif" && ext != ".tiff" && ext != ".png" && ext != ".ppm" && ext != ".pnm") {
    error = name + ": map_data images must be .tif, .tiff, .png, .ppm or .pnm";
    return false;
  }
  path = name;
  if (name[0] != '/' && !base_dir.empty() && is_file(base_dir + name)) path = base_dir + name;
  if (!is_file(path)) {
    error = name + ": no such file (looked beside the scene and in the current folder)";
    return false;
  }
  return true;
}

}  // namespace

bool probe_eastray_map(const std::string& base_dir, const std::string& written, int& width, int& height,
                       std::string& error) {
  std::string path, ext, why;
  if (!find_map_file(base_dir, written, path, ext, error)) return false;
  bool ok;
  if (ext == ".png") {
    ok = png_header_size(path, width, height, why);
  } else if (ext == ".ppm" || ext == ".pnm") {
    ok = ppm_header_size(path, width, height, why);
  } else {  // TIFF: libtiff reads the size from the directory only when decoding; decode it
    RgbTexture t;
    ok = read_tiff_rgb(path, t.width, t.height, t.rgb, why);
    width = t.width;
    height = t.height;
  }
  if (!ok) error = path + ": " + why;
  return ok;
}

bool load_eastray_map(const std::string& base_dir, const std::string& written, RgbTexture& out, std::string& error) {
  std::string path, ext;
  if (!find_map_file(base_dir, written, path, ext, error)) return false;
  std::string why;
  bool ok;
  if (ext == ".tif" || ext == ".tiff") {
    ok = read_tiff_rgb(path, out.width, out.height, out.rgb, why);
  } else if (ext == ".png") {
    RgbaImage img;
    ok = read_png(path, img, why);
    if (ok) {
      out.width = img.width;
      out.height = img.height;
      out.rgb.resize(static_cast<std::size_t>(img.width) * img.height * 3);
      for (std::size_t i = 0, n = static_cast<std::size_t>(img.width) * img.height; i < n; ++i)
        for (int c = 0; c < 3; ++c) out.rgb[3 * i + c] = img.rgba[4 * i + c];
    }
  } else {
    ok = read_ppm(path, out, why);
  }
  if (!ok) error = path + ": " + why;
  return ok;
}

EastrayMaps::EastrayMaps(const std::string& scene_path)
    : files_(scene_folder(scene_path), &load_eastray_map, kMaxMapFiles, "map_data images") {}

bool EastrayMaps::load(const model::EastrayMapFile* files, int count, int& bad, std::string& error) {
  textures_.clear();
  for (int i = 0; i < count; ++i) {
    Diagnostic d;
    const int32_t id = files_.find(files[i].file, d);
    if (id < 0) {
      bad = i;
      error = d.message;
      return false;
    }
    textures_.push_back(files_.table()[id]);
  }
  return true;
}

bool EastrayMaps::load_input(const std::string& name, std::string& error) {
  Diagnostic d;
  const int32_t id = files_.find(name, d);
  if (id < 0) {
    error = d.message;
    return false;
  }
  input_ = files_.table()[id];
  has_input_ = true;
  return true;
}

}  // namespace minrt::host
