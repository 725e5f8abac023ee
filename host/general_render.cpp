#include "general_render.hpp"

#include <chrono>
#include <cstdlib>
#include <memory>

#include "core/base/arena.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "math_policy_dispatch.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "general_rows.hpp"
#include "render/general/render.hpp"
#include "texture_files.hpp"

namespace minrt::host {

namespace {

std::string located(const std::string& name, const Diagnostic& d) {
  if (!d.has_pos) return name + ": error: " + d.message;
  return name + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": error: " + d.message;
}

template <class M>
bool render_with(const std::string& text, const std::string& name, const std::string& base_dir,
                 const GeneralOptions& options, GeneralResult& out, std::string& error,
                 const WarningSink& warnings) {
  using R = typename M::real;
  // One allocation, made once.
  const size_t bytes = general_arena_bytes<R>(text);
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);

  const auto t_parse = std::chrono::steady_clock::now();
  model::SceneBuilder<R> builder(arena);
  TextureFiles textures(base_dir, &load_png_texture, cs418::kMaxTextures, "textures");
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  cs418::Reader<M> reader(mem.source(), builder, cs418::TextureResolver{&TextureFiles::resolve, &textures}, warnings);
  cs418::Header header;
  model::Scene<R> scene;
  Diagnostic d;
  const cs418::ReadStatus st = reader.read(header, scene, d);
  if (st != cs418::ReadStatus::kOk) {
    error = located(name, d);
    return false;
  }
  if (!builder.finish(scene)) {
    error = name + ": error: scene does not fit in memory";
    return false;
  }
  scene.textures = textures.table();
  scene.texture_count = textures.count();
  out.output_name = header.output_name;
  if (!set_up_and_render<M>(scene, arena, scene.width, scene.height, options, t_parse, out)) {
    error = name + ": error: scene does not fit in memory (BVH)";
    return false;
  }
  return true;
}

}  // namespace

const char* general_path_name(uint32_t path) {
  switch (path) {
    case general::kPathBasic: return "basic (spheres, suns)";
    case general::kPathDirect: return "direct (planes, triangles, bulbs, lenses, exposure)";
    case general::kPathPhong: return "phong (miniRT: spheres, planes)";
    case general::kPathPhongFull: return "phong-full (miniRT: every element)";
    case general::kPathEastray: return "eastray (CSG of quadrics, meshes, EASTRAY's shading)";
    default: return "full (every feature)";
  }
}

bool render_cs418(const std::string& text, const std::string& name, const std::string& base_dir,
                  const GeneralOptions& options, GeneralResult& out, std::string& error,
                  const WarningSink& warnings) {
  bool ok = false;
  if (with_math_policy(options.variant, [&]<class M>() {
        ok = render_with<M>(text, name, base_dir, options, out, error, warnings);
      }))
    return ok;
  error = name + ": error: this combination of --precision and --shims is not built";
  return false;
}

}  // namespace minrt::host
