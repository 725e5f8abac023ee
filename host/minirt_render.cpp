#include "minirt_render.hpp"

#include <chrono>
#include <memory>

#include "core/base/arena.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "general_rows.hpp"
#include "render/general/render.hpp"
#include "texture_files.hpp"

namespace minrt::host {

namespace {

template <class M>
bool render_with(const std::string& text, const std::string& name, const std::string& base_dir, int width,
                 int height, const GeneralOptions& options, GeneralResult& out, std::string& error) {
  using R = typename M::real;
  const size_t bytes = general_arena_bytes<R>(text);
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);

  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  const Clock::time_point t_parse = Clock::now();
  model::SceneBuilder<R> builder(arena);
  TextureFiles textures(base_dir, &load_minirt_texture, minirt::kMaxTextures, "texture files");
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minirt::Reader<M> reader(mem.source(), builder, minirt::TextureResolver{&TextureFiles::resolve, &textures});
  model::Scene<R> scene;
  minirt::View<R> view;
  Diagnostic d;
  if (reader.read(scene, view, d) != minirt::ReadStatus::kOk) {
    error = d.has_pos ? name + ":" + std::to_string(d.pos.line) + ": " + d.message : name + ": " + d.message;
    return false;
  }
  if (!builder.finish(scene)) {
    error = name + ": the scene does not fit in memory";
    return false;
  }
  scene.width = width;
  scene.height = height;
  scene.camera = minirt::place_camera<M>(view, width, height);
  scene.textures = textures.table();
  scene.texture_count = textures.count();
  out.parse_seconds = seconds_since(t_parse);
  const Clock::time_point t_build = Clock::now();
  general::Renderer<M> renderer;
  if (!renderer.setup(scene, arena, options.seed, options.force_full, options.full_tree)) {
    error = name + ": the scene does not fit in memory (BVH)";
    return false;
  }
  out.build_seconds = seconds_since(t_build);
  out.features = renderer.features();
  out.path = general_path_name(renderer.path());
  render_general_rows(renderer, width, height, options, out);
  return true;
}

}  // namespace

bool render_minirt(const std::string& text, const std::string& name, const std::string& base_dir, int width,
                   int height, const GeneralOptions& options, GeneralResult& out, std::string& error) {
  const Variant v = options.variant;
  if (v.precision == Precision::kDouble && v.shims == ShimSet::kLibm)
    return render_with<LibmDouble>(text, name, base_dir, width, height, options, out, error);
  if (v.precision == Precision::kFloat) {
    switch (v.shims) {
      case ShimSet::kLibm: return render_with<LibmFloat>(text, name, base_dir, width, height, options, out, error);
      case ShimSet::kPortable:
        return render_with<PortableFloat>(text, name, base_dir, width, height, options, out, error);
      case ShimSet::kPortableFast:
        return render_with<PortableFloatFast>(text, name, base_dir, width, height, options, out, error);
      case ShimSet::kPortableMin:
        return render_with<PortableFloatMin>(text, name, base_dir, width, height, options, out, error);
    }
  }
  error = name + ": this combination of --precision and --shims is not built";
  return false;
}

}  // namespace minrt::host
