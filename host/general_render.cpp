#include "general_render.hpp"

#include <chrono>
#include <cstdlib>
#include <memory>

#include "core/base/arena.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
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

  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  const Clock::time_point t_parse = Clock::now();
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
  out.parse_seconds = seconds_since(t_parse);
  const Clock::time_point t_build = Clock::now();
  general::Renderer<M> renderer;
  if (!renderer.setup(scene, arena, options.seed, options.force_full, options.full_tree)) {
    error = name + ": error: scene does not fit in memory (BVH)";
    return false;
  }
  out.build_seconds = seconds_since(t_build);
  out.output_name = header.output_name;
  out.features = renderer.features();
  out.path = general_path_name(renderer.path());
  render_general_rows(renderer, scene.width, scene.height, options, out);
  return true;
}

}  // namespace

const char* general_path_name(uint32_t path) {
  switch (path) {
    case general::kPathBasic: return "basic (spheres, suns)";
    case general::kPathDirect: return "direct (planes, triangles, bulbs, lenses, exposure)";
    case general::kPathPhong: return "phong (miniRT: spheres, planes)";
    case general::kPathPhongFull: return "phong-full (miniRT: every element)";
    default: return "full (every feature)";
  }
}

bool render_cs418(const std::string& text, const std::string& name, const std::string& base_dir,
                  const GeneralOptions& options, GeneralResult& out, std::string& error,
                  const WarningSink& warnings) {
  const Variant v = options.variant;
  if (v.precision == Precision::kDouble && v.shims == ShimSet::kLibm)
    return render_with<LibmDouble>(text, name, base_dir, options, out, error, warnings);
  if (v.precision == Precision::kFloat) {
    switch (v.shims) {
      case ShimSet::kLibm: return render_with<LibmFloat>(text, name, base_dir, options, out, error, warnings);
      case ShimSet::kPortable: return render_with<PortableFloat>(text, name, base_dir, options, out, error, warnings);
      case ShimSet::kPortableFast:
        return render_with<PortableFloatFast>(text, name, base_dir, options, out, error, warnings);
      case ShimSet::kPortableMin:
        return render_with<PortableFloatMin>(text, name, base_dir, options, out, error, warnings);
    }
  }
  error = name + ": error: this combination of --precision and --shims is not built";
  return false;
}

}  // namespace minrt::host
