// 42 miniRT on the host: a .rt scene with the PPM textures it names, placed
// for the image size (--size, else the registry's 800x600), on the general
// tracer. Messages follow the subject: the driver prints "Error" and then
// this side's "FILE:LINE: message".
#include "minirt_host.hpp"

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "general_scene.hpp"
#include "math_policy_dispatch.hpp"

namespace minrt::host {

namespace {

template <class M>
std::unique_ptr<PreparedScene> prepare_with(const SceneInput& in, const DriverOptions& options, std::string& error) {
  using R = typename M::real;
  const formats::Format& f = formats::format_of(formats::FormatId::kMinirt);
  const int width = options.width > 0 ? options.width : f.default_width;
  const int height = options.height > 0 ? options.height : f.default_height;
  const auto t_parse = std::chrono::steady_clock::now();
  return prepare_growing<M>(content_lines(in.text) + 1, in.shown, error,
                            [&](GeneralScene<M>& scene, Arena& arena, bool, std::string& message) {
    model::SceneBuilder<R> builder(arena);
    scene.textures =
        std::make_unique<TextureFiles>(in.base_dir, &load_minirt_texture, minirt::kMaxTextures, "texture files");
    MemorySource mem{reinterpret_cast<const uint8_t*>(in.text.data()), in.text.size()};
    minirt::ReaderOptions reader_options;
    reader_options.mandatory = options.mandatory;
    if (options.cylinder_base) reader_options.cylinder_point = minirt::CylinderPoint::kBase;
    minirt::Reader<M> reader(mem.source(), builder, minirt::TextureResolver{&TextureFiles::resolve, scene.textures.get()},
                             reader_options);
    minirt::View<R> view;
    Diagnostic d;
    const minirt::ReadStatus st = reader.read(scene.model, view, d);
    if (st == minirt::ReadStatus::kSceneError) {
      message = d.has_pos ? in.shown + ":" + std::to_string(d.pos.line) + ": " + d.message : in.shown + ": " + d.message;
      return Pass::kFailed;
    }
    if (st == minirt::ReadStatus::kOutOfMemory || !builder.finish(scene.model)) {
      message = in.shown + ": the scene does not fit in memory";
      return Pass::kFull;
    }
    scene.model.width = width;
    scene.model.height = height;
    scene.model.camera = minirt::place_camera<M>(view, width, height);
    scene.model.textures = scene.textures->table();
    scene.model.texture_count = scene.textures->count();
    scene.opaque = false;
    if (!scene.set_up(arena, options, t_parse)) {
      message = in.shown + ": the scene does not fit in memory (BVH)";
      return Pass::kFull;
    }
    return Pass::kDone;
  });
}

}  // namespace

bool has_rt_extension(const std::string& path) {
  // The registry's extension exactly as the subject writes it: recognition
  // ignores case, this check does not, so "x.RT" is a miniRT scene with a
  // wrong name.
  const std::string ext = formats::format_of(formats::FormatId::kMinirt).extensions[0];
  const std::size_t slash = path.rfind('/');
  const std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  return base.size() > ext.size() && base.compare(base.size() - ext.size(), ext.size(), ext) == 0;
}

std::unique_ptr<PreparedScene> prepare_minirt(const SceneInput& in, const DriverOptions& options, const WarningSink&,
                                              std::string& error) {
  if (in.path == "-") {
    error = "minrt: a miniRT scene is read from a file whose name ends in .rt, not from standard input";
    return nullptr;
  }
  if (!has_rt_extension(in.path)) {
    error = in.path + ": a miniRT scene file's name must end in .rt";
    return nullptr;
  }
  std::unique_ptr<PreparedScene> scene;
  with_math_policy(options.variant, [&]<class M>() { scene = prepare_with<M>(in, options, error); });
  return scene;
}

}  // namespace minrt::host
