// EASTRAY on the host: the .ray text preprocessed (#include, #define), read,
// turned into the general model with EASTRAY's finish, and rendered by the
// general tracer. Messages name the file and line the text came from.
#include "eastray_host.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "colour_depth.hpp"
#include "eastray_maps.hpp"
#include "eastray_preprocess.hpp"
#include "eastray_stereo.hpp"
#include "image_merge.hpp"
#include "png_io.hpp"
#include "tiff_io.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "general_scene.hpp"
#include "image_file_output.hpp"
#include "math_policy_dispatch.hpp"

namespace minrt::host {

namespace {

struct WarningContext {
  const ExpandedEastray* expanded;
};

void print_warning(void* ctx, const Diagnostic& d) {
  const auto* w = static_cast<const WarningContext*>(ctx);
  std::fprintf(stderr, "%s: %s\n", w->expanded->at(d.pos.line, d.pos.col).c_str(), d.message);
}

// host-send's: the lines kept, printed with its own output.
struct WarningLines {
  const ExpandedEastray* expanded;
  std::vector<std::string>* lines;
};

void keep_warning(void* ctx, const Diagnostic& d) {
  const auto* w = static_cast<const WarningLines*>(ctx);
  w->lines->push_back(w->expanded->at(d.pos.line, d.pos.col) + ": " + d.message);
}

// Reads the expanded text into `scene`, in an arena (in `storage`) sized for
// capacities from the text's content plus `extra(caps)` bytes, doubling the
// capacities while the reader finds a table full. `arena` is the arena the
// scene lies in. False with the message line.
template <class M, class Extra>
bool read_growing(const ExpandedEastray& x, const std::string& shown, const WarningSink& warnings, Extra extra,
                  ArenaStorage& storage, std::unique_ptr<Arena>& arena, eastray::Scene<typename M::real>& scene,
                  std::string& error) {
  using Scene = eastray::Scene<typename M::real>;
  typename Scene::Capacities caps = Scene::Capacities::for_text(content_bytes(x.text));
  for (int growth = 0;; ++growth) {
    if (!storage.allocate(Scene::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() + extra(caps) + 4096, shown,
                          error))
      return false;
    arena = std::make_unique<Arena>(storage.bytes.get(), storage.size);
    scene = Scene{};
    if (!scene.allocate(*arena, caps)) {
      error = shown + ": error: scene does not fit in memory";
      return false;
    }
    // Warnings once: a larger arena reads the same text again.
    auto reader = std::make_unique<eastray::Reader<M>>(x.text.data(), x.text.size(), scene, *arena,
                                                       growth == 0 ? warnings : WarningSink{});
    Diagnostic d;
    if (reader->read(d)) return true;
    if (!d.out_of_memory || growth == kMaxArenaGrowths) {
      error = x.at(d.pos.line, d.pos.col) + ": error: " + d.message;
      return false;
    }
    caps = caps.doubled();
  }
}

// The general scene with what EASTRAY's model points into, and what its
// output needs: the stereo pair (rmode 1), 32K colours (output_mode 16),
// the display window kept in an existing file (manual line 180).
template <class M>
struct EastrayScene final : GeneralScene<M> {
  using R = typename M::real;
  ExpandedEastray expanded;
  eastray::Scene<R> source;
  model::EastrayShading<R> shading;
  std::unique_ptr<EastrayMaps> maps;  // the map_data and input images the shading points into
  std::vector<uint8_t> mip_bytes;     // the halved images of maps read with mip 1
  std::vector<model::Texture> mips;   // kMipLevels per map_data entry
  Vec3<R> eye{};                      // the scene's own eye, between the stereo pair's

  // The right eye's image first, then the left's (the view reads the eye at every row).
  void select_view(int view) override {
    if (this->views > 1) shading.eye = general::eastray_stereo_eye<M>(with_eye(eye), view == 0 ? 1 : -1);
  }
  std::string view_output_name(const std::string& out_path, int view) const override {
    return this->views > 1 ? eastray_stereo_name(out_path, view == 0 ? 'r' : 'l') : out_path;
  }
  std::string finish_image(const std::string& out_path, ImageFile kind, RgbaImage& image) const override {
    const bool tiff = kind == ImageFile::kTiff;
    if (!tiff && kind != ImageFile::kPng) return "";
    std::vector<uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
    if (tiff && source.output_bits == 16) reduce_to_32k_colours(rgb, image.width, image.height, source.dither);
    std::string why;
    const MergeOutcome merge = merge_outside_window(out_path, tiff, image.width, image.height,
                                                    PixelWindow{source.x0, source.y0, source.x1, source.y1}, rgb, why);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
      for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = rgb[3 * i + c];
    return merge == MergeOutcome::kReplaced ? why + ": replaced, black outside the display window (line 180)" : "";
  }

 private:
  model::EastraySettings<R> with_eye(const Vec3<R>& e) const {
    model::EastraySettings<R> s = shading;
    s.eye = e;
    return s;
  }
};

// The halved images of the maps read with mip 1 (line 398), which modes
// 10-14 pick by the pixel's footprint; the board builds the same.
template <class M>
void build_mips(const eastray::Scene<typename M::real>& src, EastrayScene<M>& scene) {
  const model::Texture* maps = scene.maps->table();
  std::size_t bytes = 0;
  for (int32_t i = 0; i < src.map_file_count; ++i)
    if (src.map_files[i].mip) bytes += general::eastray_mip_bytes(maps[i].width, maps[i].height);
  if (bytes == 0) return;
  scene.mip_bytes.assign(bytes, 0);
  scene.mips.assign(static_cast<std::size_t>(src.map_file_count) * model::kMipLevels, model::Texture{});
  uint8_t* at = scene.mip_bytes.data();
  for (int32_t i = 0; i < src.map_file_count; ++i) {
    if (!src.map_files[i].mip) continue;
    general::eastray_build_mips(maps[i], at, scene.mips.data() + static_cast<std::size_t>(i) * model::kMipLevels);
    at += general::eastray_mip_bytes(maps[i].width, maps[i].height);
  }
  scene.shading.map_mips = scene.mips.data();
}

template <class M>
std::unique_ptr<PreparedScene> prepare_with(const SceneInput& in, const DriverOptions& options, std::string& error) {
  using R = typename M::real;
  const auto t_parse = std::chrono::steady_clock::now();
  auto scene = std::make_unique<EastrayScene<M>>();
  if (!preprocess_eastray(in.path, in.shown, in.text, scene->expanded, error)) return nullptr;
  WarningContext wc{&scene->expanded};
  // The hierarchies over the triangles and the objects come after the arrays.
  auto hierarchies = [](const typename eastray::Scene<R>::Capacities& c) {
    return general::bvh_footprint<R>(static_cast<uint32_t>(c.triangles)) +
           general::object_bvh_bytes<R>(static_cast<uint32_t>(c.nodes));
  };
  std::unique_ptr<Arena> arena;
  if (!read_growing<M>(scene->expanded, in.shown, options.quiet ? WarningSink{} : WarningSink{&print_warning, &wc},
                       hierarchies, scene->storage, arena, scene->source, error))
    return nullptr;
  bool tiff = false;
  std::string unsupported;
  scene->output_name = eastray_output_name("", scene->source.output, in.path, tiff, unsupported);
  if (!unsupported.empty() && options.output_path.empty() && options.save) {
    error = in.shown + ": error: " + unsupported;
    return nullptr;
  }
  eastray::to_model(scene->source, scene->shading, scene->model);
  // The images the scene's map_data and input name, found from its folder.
  const eastray::Scene<R>& src = scene->source;
  scene->maps = std::make_unique<EastrayMaps>(in.path);
  int bad = 0;
  if (!scene->maps->load(src.map_files, src.map_file_count, bad, error)) {
    error = scene->expanded.at(src.map_files[bad].line, src.map_files[bad].col) + ": error: " + error;
    return nullptr;
  }
  scene->shading.map_images = scene->maps->table();
  scene->shading.map_image_count = scene->maps->count();
  build_mips(src, *scene);
  if (src.input[0] != 0) {  // a missing or unreadable input is an error, where it is named
    if (!scene->maps->load_input(src.input, error)) {
      error = scene->expanded.at(src.input_line, src.input_col) + ": error: input " + error;
      return nullptr;
    }
    scene->shading.input_image = scene->maps->input();
  }
  scene->eye = scene->shading.eye;
  scene->views = src.stereo ? 2 : 1;
  if (!scene->set_up(*arena, options, t_parse)) {
    error = in.shown + ": error: scene does not fit in memory";
    return nullptr;
  }
  return scene;
}

}  // namespace

std::string eastray_output_name(const std::string& option, const std::string& statement,
                                const std::string& scene_path, bool& tiff, std::string& unsupported) {
  std::string name = !option.empty() ? option : !statement.empty() ? statement
                                              : scene_path == "-" ? std::string("-")
                                                                  : with_extension(scene_path, ".png");
  for (char& c : name)
    if (c == '\\') c = '/';
  tiff = formats::has_extension(name.c_str(), ".tif") || formats::has_extension(name.c_str(), ".tiff");
  for (const char* old : {".fal", ".ipr", ".hpi"})
    if (formats::has_extension(name.c_str(), old))
      unsupported = "cannot write " + name + ": " + std::string(old + 1) +
                    " images (FM TOWNS raw RGB and headers) are not written; name a .tif or .tiff (TIFF) or any other "
                    "name (PNG)";
  return name;
}

bool eastray_board_text(const std::string& path, const std::string& text, std::string& board_text, int& width,
                        int& height, std::string& output_statement, std::string& error,
                        std::vector<std::pair<std::string, std::string>>* maps, EastrayBoardOutput* output) {
  ExpandedEastray x;
  if (!preprocess_eastray(path, path, text, x, error)) return false;
  using M = PortableFloat;  // the board's reader and arithmetic
  using Caps = eastray::Scene<M::real>::Capacities;
  auto vertex_index = [](const Caps& c) { return 4 * Arena::footprint<int32_t>(static_cast<std::size_t>(c.vertices)); };
  ArenaStorage storage;
  std::unique_ptr<Arena> arena;
  eastray::Scene<M::real> scene;
  std::vector<std::string> warnings;
  WarningLines lines{&x, &warnings};
  if (!read_growing<M>(x, path, WarningSink{&keep_warning, &lines}, vertex_index, storage, arena, scene, error))
    return false;
  width = scene.width;
  height = scene.height;
  output_statement = scene.output;
  if (output != nullptr)
    *output = EastrayBoardOutput{scene.stereo, scene.x0,          scene.y0,     scene.x1,
                                 scene.y1,     scene.output_bits, scene.dither, std::move(warnings)};
  if (maps != nullptr) {
    maps->clear();
    for (int32_t i = 0; i < scene.map_file_count; ++i)
      maps->emplace_back(scene.map_files[i].file, x.at(scene.map_files[i].line, scene.map_files[i].col) + ": error: ");
    if (scene.input[0] != 0) maps->emplace_back(scene.input, x.at(scene.input_line, scene.input_col) + ": error: input ");
  }
  board_text = "/* EASTRAY */ " + x.text;  // on the first line: line numbers stay
  return true;
}

bool eastray_board_file(const std::string& png, const EastrayBoardOutput& how, const std::string& path,
                        std::string& file, std::string& warning, std::string& error) {
  RgbaImage image;
  if (!decode_png(png, image, error)) return false;
  bool tiff = false;
  std::string unsupported;
  eastray_output_name(path, "", path, tiff, unsupported);
  std::vector<uint8_t> rgb(static_cast<std::size_t>(image.width) * image.height * 3);
  for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
    for (int c = 0; c < 3; ++c) rgb[3 * i + c] = image.rgba[4 * i + c];
  if (tiff && how.bits == 16) reduce_to_32k_colours(rgb, image.width, image.height, how.dither);
  std::string why;
  if (merge_outside_window(path, tiff, image.width, image.height, PixelWindow{how.x0, how.y0, how.x1, how.y1}, rgb, why) ==
      MergeOutcome::kReplaced)
    warning = why + ": replaced, black outside the display window (line 180)";
  std::FILE* out = std::tmpfile();  // libtiff writes through a seekable file
  if (out == nullptr) {
    error = std::strerror(errno);
    return false;
  }
  bool ok;
  if (tiff) {
    ok = write_tiff_rgb(out, image.width, image.height, rgb, error);
  } else {
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i)
      for (int c = 0; c < 3; ++c) image.rgba[4 * i + c] = rgb[3 * i + c];
    ok = write_png(out, image, error);
  }
  if (ok) {
    std::fflush(out);
    std::rewind(out);
    file.clear();
    char buffer[65536];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, out)) > 0;) file.append(buffer, n);
    if (std::ferror(out)) {
      error = std::strerror(errno);
      ok = false;
    }
  }
  std::fclose(out);
  return ok;
}

std::unique_ptr<PreparedScene> prepare_eastray(const SceneInput& in, const DriverOptions& options, const WarningSink&,
                                               std::string& error) {
  std::unique_ptr<PreparedScene> scene;
  with_math_policy(options.variant, [&]<class M>() { scene = prepare_with<M>(in, options, error); });
  return scene;
}

}  // namespace minrt::host
