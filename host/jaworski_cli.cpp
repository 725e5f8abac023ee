#include "jaworski_cli.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <thread>
#include <memory>
#include <vector>

#include "core/base/arena.hpp"
#include "core/image/bmp_writer.hpp"
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "math_policy_dispatch.hpp"
#include "file_input.hpp"
#include "image_window.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "posix/output_file.hpp"
#include "render/jaworski/tracer.hpp"
#include "thread_count.hpp"

namespace minrt::host {

namespace {

constexpr int kExitSceneError = 2;
constexpr int kExitIoError = 1;

// The BMP file laid out in memory: rows are rendered straight into their
// place behind the header, so no copy or growing buffer follows the render.
struct BmpImage {
  std::unique_ptr<uint8_t[]> bytes;  // not zeroed: every byte is written
  size_t size = 0;
};

// Parses and renders into `bmp`, handing each row to `window` (when open)
// as it is finished; false with the message line in `error`.
template <class M>
bool render(const std::string& text, const std::string& name, int threads, BmpImage& bmp, LiveWindow& window,
            std::string& error) {
  using R = typename M::real;
  const int32_t capacity = jaworski::Scene<R>::capacity_for(text.size());
  const size_t bytes = static_cast<size_t>(capacity) * (sizeof(jaworski::Object<R>) + sizeof(jaworski::Light<R>) +
                                                        sizeof(jaworski::SurfaceNode<R>) + sizeof(jaworski::Part<R>)) +
                       jaworski::Tracer<M>::arena_bytes(capacity, capacity) + 4096;
  std::unique_ptr<unsigned char[]> storage(new unsigned char[bytes]);
  Arena arena(storage.get(), bytes);
  jaworski::Scene<R> scene;
  if (!scene.allocate(arena, capacity)) {
    error = name + ": error: scene does not fit in memory";
    return false;
  }
  MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  jaworski::Reader<M> reader(mem.source(), scene);
  Diagnostic d;
  if (!reader.read(d)) {
    error = name + ":" + std::to_string(d.pos.line) + ":" + std::to_string(d.pos.col) + ": error: " + d.message;
    return false;
  }
  // Rows are independent: render them on every core, each into its place
  // in the file (the BMP stores the bottom row first, as the tracer counts
  // them), turned from RGBA into the file's BGRA once the window has it.
  const jaworski::Tracer<M> tracer(scene, arena);
  if (!tracer.ready()) {
    error = name + ": error: scene does not fit in memory";
    return false;
  }
  const size_t stride = static_cast<size_t>(scene.width) * 4;
  bmp.size = BmpWriter::file_bytes(scene.width, scene.height);
  bmp.bytes.reset(new uint8_t[bmp.size]);
  BmpWriter::header(bmp.bytes.get(), scene.width, scene.height);
  uint8_t* const rows = bmp.bytes.get() + BmpWriter::kHeaderBytes;
  threads = minrt_thread_count(threads, scene.height);
  std::atomic<int> next{0};
  const bool live = window.is_open();
  if (live) window.begin(scene.width, scene.height);
  auto work = [&] {
    for (int y; (y = next.fetch_add(1)) < scene.height;) {
      uint8_t* const row = rows + stride * y;
      tracer.render_row(y, row);
      if (live) window.row_rgba(scene.height - 1 - y, row);  // the window counts from the top
      BmpWriter::to_bgra(row, row, scene.width);
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  return true;
}

}  // namespace

std::string jaworski_output_name(const std::string& scene_path) {
  const std::size_t dot = scene_path.rfind('.');
  const std::size_t slash = scene_path.rfind('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return scene_path + ".bmp";
  return scene_path.substr(0, dot + 1) + "bmp";
}

int run_jaworski_cli(JaworskiCli& cli) {
  const bool from_stdin = cli.scene_path == "-";
  const std::string shown = from_stdin ? "<stdin>" : cli.scene_path;
  if (!read_scene_file(cli.scene_path, cli.scene_text, kMaxSceneBytes)) return kExitSceneError;
  std::string out_path;
  if (cli.save) {
    out_path = cli.output_path != nullptr ? cli.output_path : from_stdin ? "-" : jaworski_output_name(cli.scene_path);
    std::string why;
    if (!check_output_target(out_path, cli.write_through, why)) {
      std::fprintf(stderr, "minrt: error: %s\n", why.c_str());
      return kExitIoError;
    }
  }
  BmpImage bmp;
  std::string error, why;
  LiveWindow window;
  if (cli.show && !window.open("minrt: " + shown, why))
    std::fprintf(stderr, "minrt: warning: not showing the image: %s\n", why.c_str());
  bool ok = false;
  if (!with_math_policy(cli.variant, [&]<class M>() {
        ok = render<M>(cli.scene_text, shown, cli.threads, bmp, window, error);
      }))
    error = "minrt: error: this combination of --precision and --shims is not built";
  if (!ok) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return kExitSceneError;
  }
  if (cli.save) {
    AtomicOutput output(cli.durability);
    if (!output.open(out_path, cli.write_through, why) ||
        std::fwrite(bmp.bytes.get(), 1, bmp.size, output.file()) != bmp.size || !output.commit(why)) {
      output.discard();
      std::fprintf(stderr, "minrt: error: cannot write %s: %s\n", out_path.c_str(), why.empty() ? "write error" : why.c_str());
      return kExitIoError;
    }
  }
  if (window.is_open() && !window.finish_and_wait(why)) std::fprintf(stderr, "minrt: warning: %s\n", why.c_str());
  return 0;
}

}  // namespace minrt::host
