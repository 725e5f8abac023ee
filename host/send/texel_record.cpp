#include "texel_record.hpp"

#include <cstdlib>

#include "core/base/arena.hpp"
#include "core/base/byte_io.hpp"
#include "core/base/diagnostic.hpp"
#include "core/math/math_portable.hpp"
#include "formats/cs418/cs418_limits.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/model/scene_builder.hpp"
#include "posix/progress_line.hpp"
#include "render/general/render.hpp"
#include "texture_files.hpp"

namespace minrt::send {

namespace {

using M = PortableFloat;  // the host float model: the board's image
using R = M::real;

// The texture files, with the name each index was resolved from.
struct NamedFiles {
  host::TextureFiles files;
  std::vector<std::string> names;
  static int32_t resolve(void* ctx, const char* name, Diagnostic& error) {
    auto* self = static_cast<NamedFiles*>(ctx);
    const int32_t id = host::TextureFiles::resolve(&self->files, name, error);
    if (id >= 0 && static_cast<std::size_t>(id) >= self->names.size()) self->names.resize(static_cast<std::size_t>(id) + 1);
    if (id >= 0) self->names[static_cast<std::size_t>(id)] = name;
    return id;
  }
};

enum class Pass { kDone, kFailed, kFull };

// Silent for renders shorter than this, as minrt is.
constexpr double kProgressAfterSeconds = 1.0;

Pass record_in(std::vector<std::uint8_t>& memory, const std::string& scene, const std::string& base_dir,
               TexelMarks& marks, bool show_progress) {
  Arena arena(memory.data(), memory.size());
  model::SceneBuilder<R> builder(arena);
  NamedFiles named{host::TextureFiles(base_dir, &host::load_png_texture, cs418::kMaxTextures, "textures"), {}};
  MemorySource text{reinterpret_cast<const std::uint8_t*>(scene.data()), scene.size()};
  cs418::Reader<M> reader(text.source(), builder, cs418::TextureResolver{&NamedFiles::resolve, &named}, WarningSink{});
  cs418::Header header;
  model::Scene<R> model;
  Diagnostic error;
  const cs418::ReadStatus st = reader.read(header, model, error);
  if (st == cs418::ReadStatus::kSceneError) return Pass::kFailed;
  if (st == cs418::ReadStatus::kOutOfMemory) return Pass::kFull;
  model.textures = named.files.table();
  model.texture_count = named.files.count();
  // The board's set-up (runtime/general_board.hpp): seed 1, its own path.
  general::Renderer<M> renderer;
  if (!builder.finish(model) || !renderer.setup(model, arena, 1)) return Pass::kFull;
  if (!renderer.can_watch_texels()) return Pass::kFailed;
  std::vector<std::vector<std::uint8_t>> read(model.texture_count);
  std::vector<general::TexelWatch::Entry> entries(model.texture_count);
  for (std::uint32_t i = 0; i < model.texture_count; ++i) {
    const model::Texture& t = model.textures[i];
    read[i].assign(static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height), 0);
    entries[i] = general::TexelWatch::Entry{t.rgb, t.width, read[i].data(), {}};
  }
  general::TexelWatch watch;
  watch.entries = entries.data();
  watch.count = static_cast<int32_t>(entries.size());
  // One row at a time, in this thread: the watch is not shared.
  general::g_texel_watch = &watch;
  std::vector<std::uint8_t> row(4 * static_cast<std::size_t>(model.width));
  host::WorkProgress progress(show_progress, "host-send: finding the texels the render reads", "rows",
                              static_cast<std::uint64_t>(model.height), kProgressAfterSeconds);
  for (int y = 0; y < model.height; ++y) {
    renderer.render_row_watched(y, row.data());
    progress.add();
  }
  progress.finish();
  general::g_texel_watch = nullptr;
  // Test only: every read becomes a read of a texel not sent, so the tests
  // can see the board catch it and host-send send the textures whole.
  const bool drop = std::getenv("MINRT_HOST_SEND_TEST_UNSENT_TEXELS") != nullptr;
  for (std::size_t i = 0; i < read.size(); ++i) {
    if (drop) read[i].assign(read[i].size(), 0);
    marks[named.names[i]] = std::move(read[i]);
  }
  return Pass::kDone;
}

}  // namespace

bool record_cs418_texels(const std::string& scene, const std::string& base_dir, TexelMarks& marks, bool progress) {
  // The arena grows until the scene fits, as minrt's does.
  for (std::size_t bytes = std::size_t{16} << 20; bytes <= std::size_t{1} << 30; bytes *= 4) {
    std::vector<std::uint8_t> memory(bytes);
    marks.clear();
    const Pass p = record_in(memory, scene, base_dir, marks, progress);
    if (p != Pass::kFull) return p == Pass::kDone;
  }
  return false;
}

}  // namespace minrt::send
