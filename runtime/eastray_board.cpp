#include "eastray_board.hpp"

#include "board_math.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "render/general/render.hpp"

namespace minrt::fw {

namespace {

// Items of each kind a scene may have on the board: about 1 MB of arena in
// float, the rest for the text, the BVH and the rows.
constexpr eastray::Scene<Math::real>::Capacities kCapacity{256, 256, 2048, 4096, 4096, 4096, 16, 256, 256};

}  // namespace

SceneResult render_eastray_rows(const char* text, size_t size, RgbaRowSink rows, Arena& arena,
                                const send::textures::Table* textures, Diagnostic& error) {
  using R = Math::real;
  eastray::Scene<R> scene;
  if (!scene.allocate(arena, kCapacity)) {
    error.text("no room for the scene tables");
    return SceneResult::kOutOfMemory;
  }
  eastray::Reader<Math> reader(text, size, scene, arena);
  if (!reader.read(error)) return SceneResult::kSceneError;
  // Drawn by the general tracer with EASTRAY's finish; the rows' buffer
  // first, so the hierarchies (without room: the same image, slower) do not
  // leave it none.
  uint8_t* row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width));
  if (row == nullptr) {
    error.text("image row does not fit in the board's memory");
    return SceneResult::kOutOfMemory;
  }
  model::EastrayShading<R> shading;
  model::Scene<R> model;
  eastray::to_model(scene, shading, model);
  // The map_data images, found by their names as written among those
  // host-send decoded and sent ahead (host/eastray_maps.cpp reads them).
  if (scene.map_file_count > 0) {
    model::Texture* maps = arena.alloc_zeroed<model::Texture>(static_cast<size_t>(scene.map_file_count));
    if (maps == nullptr) {
      error.text("no room for the map table");
      return SceneResult::kOutOfMemory;
    }
    for (int32_t i = 0; i < scene.map_file_count; ++i) {
      const model::EastrayMapFile& f = scene.map_files[i];
      const int32_t t = textures != nullptr ? textures->find(f.file) : -1;
      if (t < 0) {
        error.pos.line = f.line;
        error.pos.col = f.col;
        error.has_pos = true;
        error.text("map_data image ").text(f.file).text(" was not sent ahead of the scene (host-send sends the ones it names)");
        return SceneResult::kSceneError;
      }
      maps[i].width = textures->items[t].width;
      maps[i].height = textures->items[t].height;
      maps[i].rgb = textures->items[t].rgb;
    }
    shading.map_images = maps;
    shading.map_image_count = scene.map_file_count;
    // The halved images of the maps read with mip 1 (line 398), as the
    // host builds them (render/general/eastray_mapping.hpp).
    bool any_mip = false;
    for (int32_t i = 0; i < scene.map_file_count; ++i) any_mip = any_mip || scene.map_files[i].mip;
    if (any_mip) {
      model::Texture* mips =
          arena.alloc_zeroed<model::Texture>(static_cast<size_t>(scene.map_file_count) * model::kMipLevels);
      for (int32_t i = 0; mips != nullptr && i < scene.map_file_count; ++i) {
        const size_t size = general::eastray_mip_bytes(maps[i].width, maps[i].height);
        if (!scene.map_files[i].mip || size == 0) continue;
        uint8_t* bytes = arena.alloc_uninit<uint8_t>(size);
        if (bytes == nullptr) mips = nullptr;
        else general::eastray_build_mips(maps[i], bytes, mips + static_cast<size_t>(i) * model::kMipLevels);
      }
      if (mips == nullptr) {
        error.text("no room for the mip-mapped images");
        return SceneResult::kOutOfMemory;
      }
      shading.map_mips = mips;
    }
  }
  if (scene.input[0] != 0) {  // back_mode's background, sent like the maps
    const int32_t t = textures != nullptr ? textures->find(scene.input) : -1;
    model::Texture* input = t < 0 ? nullptr : arena.alloc_zeroed<model::Texture>(1);
    if (input == nullptr) {
      error.pos.line = scene.input_line;
      error.pos.col = scene.input_col;
      error.has_pos = true;
      error.text("input image ").text(scene.input).text(" was not sent ahead of the scene");
      return SceneResult::kSceneError;
    }
    input->width = textures->items[t].width;
    input->height = textures->items[t].height;
    input->rgb = textures->items[t].rgb;
    shading.input_image = input;
  }
  general::Renderer<Math> renderer;
  if (!renderer.setup(model, arena, 1)) {
    error.text("scene does not fit in the board's memory (").number(static_cast<int64_t>(arena.capacity())).text(
        " bytes)");
    return SceneResult::kOutOfMemory;
  }
  if (!scene.stereo) {
    renderer.render(rows, row);
    return SceneResult::kOk;
  }
  // rmode 1 (lines 57, 117): the right eye's image, then the left eye's,
  // as one image of twice the height; host-send cuts it into the _r and _l
  // files (host/eastray_stereo.hpp). The view reads the eye at every row.
  const model::EastraySettings<R> centre = shading;
  rows.begin(scene.width, 2 * scene.height);
  for (int view = 0; view < 2; ++view) {
    shading.eye = general::eastray_stereo_eye<Math>(centre, view == 0 ? 1 : -1);
    for (int y = 0; y < scene.height; ++y) {
      renderer.render_row(y, row);
      rows.row(view * scene.height + y, row);
    }
  }
  rows.end();
  return SceneResult::kOk;
}

SceneResult render_eastray_source_rows(ByteSource in, RgbaRowSink rows, Arena& arena,
                                       const send::textures::Table* textures, Diagnostic& error) {
  // The text, whole, at the arena's top: parts are read again at every
  // call. Room is left below it for the scene, the reader's part table and
  // the rows.
  const size_t room = arena.capacity() - arena.used();
  const size_t reserve = eastray::Scene<Math::real>::bytes_for(kCapacity) + eastray::Reader<Math>::scratch_bytes() +
                         64 * 1024;
  if (room <= reserve) {
    error.text("no room for the scene text");
    return SceneResult::kOutOfMemory;
  }
  const size_t limit = room - reserve;
  const size_t top = arena.top_mark();
  char* text = arena.alloc_top<char>(limit);
  size_t size = 0;
  for (int c; (c = in.get()) >= 0;) {
    if (size == limit) {
      error.text("scene larger than the board's memory allows (").number(static_cast<int64_t>(limit)).text(" bytes)");
      return SceneResult::kOutOfMemory;
    }
    text[size++] = static_cast<char>(c);
  }
  // Keep only what arrived, moved up against the top: the room below is the
  // hierarchies' (with the whole buffer kept, a scene of some 1500 objects
  // left them too little, and every ray tested every object).
  arena.release_top(top);
  char* kept = arena.alloc_top<char>(size);
  for (size_t i = size; i-- > 0;) kept[i] = text[i];  // kept >= text: from the end
  text = kept;
  return render_eastray_rows(text, size, rows, arena, textures, error);
}

}  // namespace minrt::fw
