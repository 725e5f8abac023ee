#include "minirt_render.hpp"

#include <chrono>
#include <memory>

#include "core/base/arena.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "math_policy_dispatch.hpp"
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
                 int height, const minirt::ReaderOptions& reader_options, const GeneralOptions& options,
                 GeneralResult& out, std::string& error) {
  using R = typename M::real;
  const size_t bytes = general_arena_bytes<R>(text);
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);

  const auto t_parse = std::chrono::steady_clock::now();
  model::SceneBuilder<R> builder(arena);
  TextureFiles textures(base_dir, &load_minirt_texture, minirt::kMaxTextures, "texture files");
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minirt::Reader<M> reader(mem.source(), builder, minirt::TextureResolver{&TextureFiles::resolve, &textures},
                           reader_options);
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
  if (!set_up_and_render<M>(scene, arena, width, height, options, t_parse, out)) {
    error = name + ": the scene does not fit in memory (BVH)";
    return false;
  }
  return true;
}

}  // namespace

bool render_minirt(const std::string& text, const std::string& name, const std::string& base_dir, int width,
                   int height, const minirt::ReaderOptions& reader, const GeneralOptions& options,
                   GeneralResult& out, std::string& error) {
  bool ok = false;
  if (with_math_policy(options.variant, [&]<class M>() {
        ok = render_with<M>(text, name, base_dir, width, height, reader, options, out, error);
      }))
    return ok;
  error = name + ": this combination of --precision and --shims is not built";
  return false;
}

}  // namespace minrt::host
