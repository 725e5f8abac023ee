#include "eastray_cli.hpp"
#include "image_window.hpp"

#include <atomic>
#include <cstdio>
#include <thread>
#include <memory>
#include <vector>

#include "core/base/arena.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "eastray_maps.hpp"
#include "eastray_preprocess.hpp"
#include "colour_depth.hpp"
#include "eastray_stereo.hpp"
#include "image_merge.hpp"
#include "file_input.hpp"
#include "formats/eastray/eastray_reader.hpp"
#include "posix/output_file.hpp"
#include "png_io.hpp"
#include "formats/eastray/eastray_model.hpp"
#include "render/general/render.hpp"
#include "thread_count.hpp"
#include "tiff_io.hpp"

namespace minrt::host {

namespace {

constexpr int kExitSceneError = 2;
constexpr int kExitIoError = 1;

bool ends_with_nocase(const std::string& s, const char* tail) {
  const std::string t(tail);
  if (s.size() < t.size()) return false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    char c = s[s.size() - t.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != t[i]) return false;
  }
  return true;
}

std::string replace_extension(const std::string& path, const char* ext) {
  const std::size_t dot = path.rfind('.');
  const std::size_t slash = path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ext;
  return path.substr(0, dot) + ext;
}

struct WarningContext {
  const ExpandedEastray* expanded;
  bool quiet;
};

void print_warning(void* ctx, const Diagnostic& d) {
  const auto* w = static_cast<const WarningContext*>(ctx);
  if (w->quiet) return;
  std::fprintf(stderr, "%s: %s\n", w->expanded->at(d.pos.line, d.pos.col).c_str(), d.message);
}

template <class M>
bool render(const std::string& path, const ExpandedEastray& x, bool quiet, EastrayImage& out, std::string& error,
            LiveWindow* window) {
  int& width = out.width;
  int& height = out.height;
  std::vector<uint8_t>& rgb = out.rgb;
  using R = typename M::real;
  using Scene = eastray::Scene<R>;
  const typename Scene::Capacities caps = Scene::Capacities::for_text(x.text.size());
  // The reader's scratch (part table, a mesh's vertex index) and the
  // hierarchies over the triangles and the objects come after the scene's
  // arrays.
  const std::size_t bytes = Scene::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() +
                            general::bvh_footprint<R>(static_cast<uint32_t>(caps.triangles)) +
                            general::object_bvh_bytes<R>(static_cast<uint32_t>(caps.nodes)) + 4096;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  Scene scene;
  if (!scene.allocate(arena, caps)) {
    error = "error: scene does not fit in memory";
    return false;
  }
  WarningContext wc{&x, quiet};
  auto reader = std::make_unique<eastray::Reader<M>>(x.text.data(), x.text.size(), scene, arena,
                                                     WarningSink{&print_warning, &wc});
  Diagnostic d;
  if (!reader->read(d)) {
    error = x.at(d.pos.line, d.pos.col) + ": error: " + d.message;
    return false;
  }
  out.output_statement = scene.output;
  width = scene.width;
  height = scene.height;
  out.x0 = scene.x0, out.y0 = scene.y0, out.x1 = scene.x1, out.y1 = scene.y1;
  out.output_bits = scene.output_bits;
  out.dither = scene.dither;
  // Drawn by the general tracer with EASTRAY's finish.
  model::EastrayShading<R> shading;
  model::Scene<R> model;
  eastray::to_model(scene, shading, model);
  EastrayMaps maps(path);
  int bad = 0;
  if (!maps.load(scene.map_files, scene.map_file_count, bad, error)) {
    error = x.at(scene.map_files[bad].line, scene.map_files[bad].col) + ": error: " + error;
    return false;
  }
  shading.map_images = maps.table();
  shading.map_image_count = maps.count();
  if (scene.input[0] != 0) {  // a missing or unreadable input is an error, where it is named
    if (!maps.load_input(scene.input, error)) {
      error = x.at(scene.input_line, scene.input_col) + ": error: input " + error;
      return false;
    }
    shading.input_image = maps.input();
  }
  general::Renderer<M> renderer;
  if (!renderer.setup(model, arena, 1)) {
    error = "error: scene does not fit in memory";
    return false;
  }
  // Rows are independent: every core takes the next one.
  const std::size_t stride = static_cast<std::size_t>(width) * 3;
  const int threads = minrt_thread_count(0, height);  // every core
  if (window != nullptr && !window->is_open()) window = nullptr;
  auto draw = [&](std::vector<uint8_t>& image) {
    image.assign(stride * static_cast<std::size_t>(height), 0);
    std::atomic<int> next{0};
    if (window != nullptr) window->begin(width, height);
    auto work = [&] {
      std::vector<uint8_t> row(static_cast<std::size_t>(width) * 4);
      for (int y; (y = next.fetch_add(1)) < height;) {
        renderer.render_row(y, row.data());
        uint8_t* line = image.data() + stride * static_cast<std::size_t>(y);
        for (int i = 0; i < width; ++i)
          for (int c = 0; c < 3; ++c) line[3 * i + c] = row[4 * static_cast<std::size_t>(i) + c];
        if (window != nullptr) window->row_rgb(y, line);
      }
    };
    std::vector<std::thread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
  };
  out.stereo = scene.stereo;
  if (!scene.stereo) {
    draw(rgb);
    return true;
  }
  // rmode 1: the right eye's image, then the left's (the view reads the
  // eye at every row).
  const Vec3<R> eye = shading.eye;
  shading.eye = general::eastray_stereo_eye<M>(shading, 1);
  draw(rgb);
  shading.eye = eye;
  shading.eye = general::eastray_stereo_eye<M>(shading, -1);
  draw(out.rgb_left);
  shading.eye = eye;
  return true;
}

}  // namespace

std::string eastray_output_name(const std::string& option, const std::string& statement,
                                const std::string& scene_path, bool& tiff, std::string& unsupported) {
  std::string name = !option.empty() ? option : !statement.empty() ? statement
                                              : scene_path == "-" ? std::string("-")
                                                                  : replace_extension(scene_path, ".png");
  for (char& c : name)
    if (c == '\\') c = '/';
  tiff = ends_with_nocase(name, ".tif") || ends_with_nocase(name, ".tiff");
  for (const char* old : {".fal", ".ipr", ".hpi"})
    if (ends_with_nocase(name, old))
      unsupported = "cannot write " + name + ": " + std::string(old + 1) +
                    " images (FM TOWNS raw RGB and headers) are not written; name a .tif or .tiff (TIFF) or any other "
                    "name (PNG)";
  return name;
}

bool render_eastray(const std::string& path, const std::string& shown, const std::string& text, Variant v,
                    bool quiet, EastrayImage& out, std::string& error, LiveWindow* window) {
  ExpandedEastray x;
  if (!preprocess_eastray(path, shown, text, x, error)) return false;
  if (v.precision == Precision::kDouble) return render<LibmDouble>(path, x, quiet, out, error, window);
  if (v.shims == ShimSet::kLibm) return render<LibmFloat>(path, x, quiet, out, error, window);
  if (v.shims == ShimSet::kPortableFast) return render<PortableFloatFast>(path, x, quiet, out, error, window);
  if (v.shims == ShimSet::kPortableMin) return render<PortableFloatMin>(path, x, quiet, out, error, window);
  return render<PortableFloat>(path, x, quiet, out, error, window);
}

bool eastray_board_text(const std::string& path, const std::string& text, std::string& board_text, int& width,
                        int& height, std::string& output_statement, std::string& error,
                        std::vector<std::pair<std::string, std::string>>* maps) {
  ExpandedEastray x;
  if (!preprocess_eastray(path, path, text, x, error)) return false;
  using M = PortableFloat;
  using R = M::real;
  using Scene = eastray::Scene<R>;
  const typename Scene::Capacities caps = Scene::Capacities::for_text(x.text.size());
  const std::size_t bytes = Scene::bytes_for(caps) + eastray::Reader<M>::scratch_bytes() +
                            4 * Arena::footprint<int32_t>(static_cast<std::size_t>(caps.vertices)) + 4096;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  Scene scene;
  if (!scene.allocate(arena, caps)) {
    error = "error: scene does not fit in memory";
    return false;
  }
  auto reader = std::make_unique<eastray::Reader<M>>(x.text.data(), x.text.size(), scene, arena);
  Diagnostic d;
  if (!reader->read(d)) {
    error = x.at(d.pos.line, d.pos.col) + ": error: " + d.message;
    return false;
  }
  width = scene.width;
  height = scene.height;
  output_statement = scene.output;
  if (maps != nullptr) {
    maps->clear();
    for (int32_t i = 0; i < scene.map_file_count; ++i)
      maps->emplace_back(scene.map_files[i].file, x.at(scene.map_files[i].line, scene.map_files[i].col) + ": error: ");
    if (scene.input[0] != 0) maps->emplace_back(scene.input, x.at(scene.input_line, scene.input_col) + ": error: input ");
  }
  board_text = "/* EASTRAY */ " + x.text;  // on the first line: line numbers stay
  return true;
}

// Writes one image to `out_path`: 32K colours for a 16-bit TIFF, the
// existing file's pixels outside the display window. False after the message.
bool write_eastray_file(const std::string& out_path, bool tiff, const EastrayImage& img,
                        const std::vector<uint8_t>& rgb, const EastrayCli& cli) {
  const int width = img.width, height = img.height;
  std::string why;
  if (!check_output_target(out_path, cli.write_through, why)) {
    std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
    return false;
  }
  std::vector<uint8_t> merged = rgb;
  if (tiff && img.output_bits == 16) reduce_to_32k_colours(merged, width, height, img.dither);
  // An existing file of the same format and size keeps its pixels outside
  // the display window (line 180); any other is replaced, black outside it.
  const MergeOutcome merge = merge_outside_window(out_path, tiff, width, height,
                                                  PixelWindow{img.x0, img.y0, img.x1, img.y1}, merged, why);
  if (merge == MergeOutcome::kReplaced && !cli.quiet)
    std::fprintf(stderr, "minrt: warning: %s: replaced, black outside the display window (line 180)\n", why.c_str());
  why.clear();
  AtomicOutput output(cli.durability);
  bool written = output.open(out_path, cli.write_through, why);
  if (written) {
    if (tiff) {
      written = write_tiff_rgb(output.file(), width, height, merged, why);
    } else {
      RgbaImage image;
      image.width = width;
      image.height = height;
      image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
      for (std::size_t i = 0, n = static_cast<std::size_t>(width) * height; i < n; ++i) {
        image.rgba[i * 4] = merged[i * 3];
        image.rgba[i * 4 + 1] = merged[i * 3 + 1];
        image.rgba[i * 4 + 2] = merged[i * 3 + 2];
        image.rgba[i * 4 + 3] = 255;
      }
      written = write_png(output.file(), image, why);
    }
  }
  if (!written || !output.commit(why)) {
    output.discard();
    std::fprintf(stderr, "minrt: error: cannot write %s: %s\n", out_path.c_str(), why.empty() ? "write error" : why.c_str());
    return false;
  }
  return true;
}

int run_eastray_cli(EastrayCli& cli) {
  const bool from_stdin = cli.scene_path == "-";
  const std::string shown = from_stdin ? "<stdin>" : cli.scene_path;
  if (!read_scene_file(cli.scene_path, cli.scene_text, kMaxSceneBytes)) return kExitSceneError;
  EastrayImage img;
  std::string error, why;
  LiveWindow window;
  if (cli.show && !window.open("minrt: " + shown, why))
    std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  if (!render_eastray(cli.scene_path, shown, cli.scene_text, cli.variant, cli.quiet, img, error, &window)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitSceneError;
  }
  // Once the file is written (or not asked for), the window stays until closed.
  auto wait_for_window = [&] {
    if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
    return 0;
  };
  const std::string& statement = img.output_statement;
  if (!cli.save) return wait_for_window();
  bool tiff = false;
  std::string unsupported;
  why.clear();
  const std::string out_path =
      eastray_output_name(cli.output_path != nullptr ? cli.output_path : "", statement, cli.scene_path, tiff, unsupported);
  if (!unsupported.empty()) {
    std::fprintf(stderr, "minrt: error: %s\n", unsupported.c_str());
    return kExitSceneError;
  }
  if (!img.stereo) {
    if (!write_eastray_file(out_path, tiff, img, img.rgb, cli)) return kExitIoError;
  } else if (!write_eastray_file(eastray_stereo_name(out_path, 'r'), tiff, img, img.rgb, cli) ||
             !write_eastray_file(eastray_stereo_name(out_path, 'l'), tiff, img, img.rgb_left, cli)) {
    return kExitIoError;
  }
  return wait_for_window();
}

}  // namespace minrt::host
