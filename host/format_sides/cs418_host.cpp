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

// The parse log and the final arrays take at most two records a line, the
// BVH a bounded amount per object.
template <class R>
std::size_t arena_bytes(std::size_t lines) {
  const std::size_t record = model::SceneBuilder<R>::record_bytes();
  return lines * (2 * record + 64) + general::bvh_footprint<R>(static_cast<uint32_t>(lines)) + (1u << 16);
}

template <class M>
std::unique_ptr<PreparedScene> prepare_with(const SceneInput& in, const DriverOptions& options,
                                            const WarningSink& warnings, std::string& error) {
  using R = typename M::real;
  const auto t_parse = std::chrono::steady_clock::now();
  std::size_t lines = content_lines(in.text) + 1;
  for (int growth = 0;; ++growth, lines *= 2) {
    auto scene = std::make_unique<GeneralScene<M>>();
    if (!scene->storage.allocate(arena_bytes<R>(lines), in.shown, error)) return nullptr;
    Arena arena(scene->storage.bytes.get(), scene->storage.size);
    model::SceneBuilder<R> builder(arena);
    scene->textures = std::make_unique<TextureFiles>(in.base_dir, &load_png_texture, cs418::kMaxTextures, "textures");
    TextureFiles& textures = *scene->textures;
    MemorySource mem{reinterpret_cast<const uint8_t*>(in.text.data()), in.text.size()};
    // Warnings once: on the first pass only (a larger arena reads the same text).
    cs418::Reader<M> reader(mem.source(), builder, cs418::TextureResolver{&TextureFiles::resolve, &textures},
                            growth == 0 ? warnings : WarningSink{});
    cs418::Header header;
    Diagnostic d;
    const cs418::ReadStatus st = reader.read(header, scene->model, d);
    const bool full = st == cs418::ReadStatus::kOutOfMemory || (st == cs418::ReadStatus::kOk && !builder.finish(scene->model));
    if (full && growth < kMaxArenaGrowths) continue;
    if (st != cs418::ReadStatus::kOk) {
      error = located_error(in.shown, d);
      return nullptr;
    }
    if (full) {
      error = in.shown + ": error: scene does not fit in memory";
      return nullptr;
    }
    scene->model.textures = textures.table();
    scene->model.texture_count = textures.count();
    scene->output_name = header.output_name;
    scene->opaque = false;  // the course's PNGs leave the background transparent
    if (!scene->set_up(arena, options, t_parse)) {
      if (growth < kMaxArenaGrowths) continue;
      error = in.shown + ": error: scene does not fit in memory (BVH)";
      return nullptr;
    }
    return scene;
  }
}

}  // namespace

bool cs418_png_line(const std::string& text, int& width, int& height, std::string& name) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string kw, w, h, extra;
    if (!(words >> kw)) continue;
    if (kw != "png" || !(words >> w >> h >> name) || (words >> extra)) return false;
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
