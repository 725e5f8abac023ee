// One render of each path through the core for the freestanding link check: the byte I/O
// is a pair of function pointers, so the only external symbols left are
// those of the math policy and the compiler's memory routines.
#include "core/math/math_libm.hpp"
#include "core/math/math_portable.hpp"
#include "core/image/bmp_writer.hpp"
#include "core/image/png_writer.hpp"
#include "formats/jaworski/jaworski_reader.hpp"
#include "render/jaworski/tracer.hpp"
#include "formats/cs418/cs418_reader.hpp"
#include "formats/minirt/minirt_camera.hpp"
#include "formats/minirt/minirt_reader.hpp"
#include "render/general/render.hpp"
#include "render/sld/render.hpp"

namespace {
alignas(16) unsigned char g_arena[1 << 20];
minrt::RenderState<POLICY> g_state;
int read_byte(void*) { return -1; }
void write_bytes(void*, const uint8_t*, size_t) {}

// A scene of the general model through the general tracer, PNG rows out,
// as the board sends them.
int render_png(const minrt::model::Scene<POLICY::real>& scene, minrt::Arena& arena) {
  minrt::general::Renderer<POLICY> renderer;
  if (!renderer.setup(scene, arena, 1)) return 3;
  uint8_t* row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width));
  if (row == nullptr) return 4;
  minrt::PngStoredWriter png(minrt::ByteSink{&write_bytes, nullptr});
  renderer.render(minrt::rgba_row_sink_of(png), row);
  return 0;
}
}  // namespace

// The general path as the board runs it: CS418 text in, PNG rows out.
int general_entry() {
  minrt::Arena arena(g_arena, sizeof g_arena);
  minrt::model::SceneBuilder<POLICY::real> builder(arena);
  minrt::cs418::Reader<POLICY> reader(minrt::ByteSource{&read_byte, nullptr}, builder, {}, {});
  minrt::cs418::Header header;
  minrt::model::Scene<POLICY::real> scene;
  minrt::Diagnostic error;
  if (reader.read(header, scene, error) != minrt::cs418::ReadStatus::kOk) return 1;
  if (!builder.finish(scene)) return 2;
  return render_png(scene, arena);
}

// miniRT's path as the board runs it: .rt text in, PNG rows out.
int minirt_entry() {
  minrt::Arena arena(g_arena, sizeof g_arena);
  minrt::model::SceneBuilder<POLICY::real> builder(arena);
  minrt::minirt::Reader<POLICY> reader(minrt::ByteSource{&read_byte, nullptr}, builder, {});
  minrt::model::Scene<POLICY::real> scene;
  minrt::minirt::View<POLICY::real> view;
  minrt::Diagnostic error;
  if (reader.read(scene, view, error) != minrt::minirt::ReadStatus::kOk) return 1;
  if (!builder.finish(scene)) return 2;
  scene.width = 16;
  scene.height = 12;
  scene.camera = minrt::minirt::place_camera<POLICY>(view, scene.width, scene.height);
  return render_png(scene, arena);
}

// Jaworski's path: keyword scene in, BMP rows out.
int jaworski_entry() {
  minrt::Arena arena(g_arena, sizeof g_arena);
  minrt::jaworski::Scene<POLICY::real> scene;
  if (!scene.allocate(arena, 256)) return 1;
  minrt::jaworski::Reader<POLICY> reader(minrt::ByteSource{&read_byte, nullptr}, scene);
  minrt::Diagnostic error;
  if (!reader.read(error)) return 2;
  uint8_t* row = arena.alloc_zeroed<uint8_t>(4 * static_cast<size_t>(scene.width));
  if (row == nullptr) return 3;
  minrt::BmpWriter bmp(minrt::ByteSink{&write_bytes, nullptr});
  const minrt::jaworski::Tracer<POLICY> tracer(scene, arena);
  if (!tracer.ready()) return 4;
  tracer.render(minrt::rgba_row_sink_of(bmp), row);
  return 0;
}

extern "C" int minrt_entry() {
  if (general_entry() != 0 || minirt_entry() != 0 || jaworski_entry() != 0) return 1;
  minrt::Arena arena(g_arena, sizeof g_arena);
  minrt::Diagnostic error;
  return static_cast<int>(minrt::render_sld<POLICY>(minrt::ByteSource{&read_byte, nullptr},
                                                    minrt::ByteSink{&write_bytes, nullptr}, {},
                                                    g_state, arena, error));
}
