// The texture files a scene names, as the host finds and decodes them: the
// general tracer's readers ask for a name (TextureResolver), host-send packs
// the same pixels for the board. A loader per format turns a name into RGB8
// rows; TextureFiles decodes each name once and keeps the table the tracer
// reads for the render's life.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/base/diagnostic.hpp"
#include "formats/model/scene.hpp"
#include "ppm_texture.hpp"

namespace minrt::host {

// Finds texture `name` of a scene whose folder is `base_dir` (with its
// trailing slash, or empty) and decodes it to RGB8; false with the whole
// message (the file and the reason) in `error`.
using TextureLoader = bool (*)(const std::string& base_dir, const std::string& name, RgbTexture& out,
                               std::string& error);

// CS418: a PNG, the name relative to the scene's folder unless absolute;
// "texture PATH: REASON" when it cannot.
bool load_png_texture(const std::string& base_dir, const std::string& name, RgbTexture& out, std::string& error);

// Where a miniRT texture name is looked for, in order: an absolute name as
// it is; else relative to the scene's folder; else its last component in
// the scene's folder (the shared scenes name `scenes/textures/earth.ppm`
// and ship the file beside them).
std::vector<std::string> minirt_texture_candidates(const std::string& base_dir, const std::string& name);

// miniRT: a PPM at the first candidate that has one; "PATH: REASON" when
// none does, naming a file that exists but is not a good PPM before a
// missing one.
bool load_minirt_texture(const std::string& base_dir, const std::string& name, RgbTexture& out, std::string& error);

// The size a loader above would decode, from the file's header alone (the
// same file the loader picks): host-send weighs it against the board's
// memory before decoding anything.
using TextureProbe = bool (*)(const std::string& base_dir, const std::string& name, int& width, int& height,
                              std::string& error);
bool probe_png_texture(const std::string& base_dir, const std::string& name, int& width, int& height,
                       std::string& error);
bool probe_minirt_texture(const std::string& base_dir, const std::string& name, int& width, int& height,
                          std::string& error);

class TextureFiles {
 public:
  // At most `max_count` distinct names; one more is refused with "more than
  // MAX_COUNT NOUN".
  TextureFiles(std::string base_dir, TextureLoader load, int max_count, const char* noun)
      : base_(std::move(base_dir)), load_(load), max_count_(max_count), noun_(noun) {}

  // The readers' TextureResolver callback; `ctx` is the TextureFiles.
  static int32_t resolve(void* ctx, const char* name, Diagnostic& error);

  // The texture's index in table(), or -1 with the reason in `error`.
  int32_t find(const std::string& name, Diagnostic& error);

  const model::Texture* table() const { return textures_.empty() ? nullptr : textures_.data(); }
  uint32_t count() const { return static_cast<uint32_t>(textures_.size()); }

 private:
  std::string base_;
  TextureLoader load_;
  int max_count_;
  const char* noun_;
  std::map<std::string, int32_t> ids_;
  std::vector<std::unique_ptr<RgbTexture>> data_;  // owners of the rows table() points into
  std::vector<model::Texture> textures_;
};

}  // namespace minrt::host
