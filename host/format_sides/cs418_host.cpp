// CS418 on the host: the course's .txt scenes, read with the textures they
// name (PNG files beside the scene), on the general tracer; the image goes
// to the name on the png line unless -o says otherwise.
#include "cs418_host.hpp"

#include <sstream>

#include <minrt/limits.hpp>

#include "core/base/text_numbers.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "general_scene.hpp"
#include "math_policy_dispatch.hpp"
#include "texture_files.hpp"

namespace minrt::host {

namespace {

template <class M>
std::unique_ptr<PreparedScene> prepare_with(const SceneInput& in, const DriverOptions& options,
                                            const WarningSink& warnings, std::string& error) {
  using R = typename M::real;
  const auto t_parse = std::chrono::steady_clock::now();
  return prepare_growing<M>(content_lines(in.text) + 1, in.shown, error,
                            [&](GeneralScene<M>& scene, Arena& arena, bool first, std::string& message) {
    model::SceneBuilder<R> builder(arena);
    scene.textures = std::make_unique<TextureFiles>(in.base_dir, &load_png_texture, cs418::kMaxTextures, "textures");
    MemorySource mem{reinterpret_cast<const uint8_t*>(in.text.data()), in.text.size()};
    // Warnings once: a larger arena reads the same text again.
    cs418::Reader<M> reader(mem.source(), builder, cs418::TextureResolver{&TextureFiles::resolve, scene.textures.get()},
                            first ? warnings : WarningSink{});
    cs418::Header header;
    Diagnostic d;
    const cs418::ReadStatus st = reader.read(header, scene.model, d);
    if (st == cs418::ReadStatus::kSceneError) {
      message = located_error(in.shown, d);
      return Pass::kFailed;
    }
    if (st == cs418::ReadStatus::kOutOfMemory || !builder.finish(scene.model)) {
      message = in.shown + ": error: scene does not fit in memory";
      return Pass::kFull;
    }
    scene.model.textures = scene.textures->table();
    scene.model.texture_count = scene.textures->count();
    scene.output_name = header.output_name;
    scene.opaque = false;  // the course's PNGs leave the background transparent
    if (!scene.set_up(arena, options, t_parse)) {
      message = in.shown + ": error: scene does not fit in memory (BVH)";
      return Pass::kFull;
    }
    return Pass::kDone;
  });
}

}  // namespace

bool cs418_png_line(const std::string& text, int& width, int& height, std::string& name) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kw, w, h;
    if (!(words >> kw) || kw[0] == '#') continue;  // blank or comment: the reader skips both
    // Fields after the name are ignored, as the reader ignores them.
    if (kw != "png" || !(words >> w >> h >> name)) return false;
    uint32_t wv = 0, hv = 0;
    const char* pw = w.c_str();
    const char* ph = h.c_str();
    if (!parse_decimal(pw, 0, limits::kMaxImageWidth, wv) || !parse_decimal(ph, 0, limits::kMaxImageHeight, hv) ||
        wv == 0 || hv == 0)
      return false;
    width = static_cast<int>(wv);
    height = static_cast<int>(hv);
    return true;
  }
  return false;
}

std::unique_ptr<PreparedScene> prepare_cs418(const SceneInput& in, const DriverOptions& options,
                                             const WarningSink& warnings, std::string& error) {
  std::unique_ptr<PreparedScene> scene;
  with_math_policy(options.variant, [&]<class M>() { scene = prepare_with<M>(in, options, warnings, error); });
  return scene;
}

}  // namespace minrt::host
