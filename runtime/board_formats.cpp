#include "board_formats.hpp"

#include <minrt/serial_protocol.h>

#include "core/image/bmp_writer.hpp"
#include "core/image/png_writer.hpp"
#include "cs418_board.hpp"
#include "eastray_board.hpp"
#include "jaworski_board.hpp"
#include "minirt_board.hpp"

namespace minrt::fw {

namespace {

using formats::FormatId;

SceneResult cs418_rows(const BoardScene& s, RgbaRowSink rows) {
  return render_cs418_rows(s.text, rows, *s.arena, s.all_features, s.textures, *s.error);
}
SceneResult jaworski_rows(const BoardScene& s, RgbaRowSink rows) {
  return render_jaworski_rows(s.text, rows, *s.arena, *s.error);
}
SceneResult minirt_rows(const BoardScene& s, RgbaRowSink rows) {
  return render_minirt_rows(s.text, rows, *s.arena, s.width, s.height, s.all_features, s.textures, *s.error);
}
SceneResult eastray_rows(const BoardScene& s, RgbaRowSink rows) {
  if (s.bytes != nullptr)
    return render_eastray_rows(reinterpret_cast<const char*>(s.bytes), s.size, rows, *s.arena, s.textures, *s.error);
  return render_eastray_source_rows(s.text, rows, *s.arena, s.textures, *s.error);
}

constexpr BoardFormat kBoardFormats[] = {
    {FormatId::kSld, nullptr},
    {FormatId::kCs418, &cs418_rows},
    {FormatId::kJaworski, &jaworski_rows},
    {FormatId::kMinirt, &minirt_rows},
    {FormatId::kEastray, &eastray_rows},
};

static_assert(formats::follows_registry(kBoardFormats), "one row per registered format, in its order");

// The texture preamble at the start of an upload, read where it lies.
bool view_textures(const send::text::TextScene& upload, BoardScene& scene) {
  size_t at = 0;
  if (upload.size > 0 && send::textures::is_marker(upload.bytes[0])) {
    auto* table = scene.arena->alloc_zeroed<send::textures::Table>(1);
    if (table == nullptr) {
      scene.error->text("no room for the texture table");
      return false;
    }
    size_t used = 0;
    if (!send::textures::unpack(upload.bytes, upload.size, *scene.arena, *table, used, *scene.error)) return false;
    scene.textures = table;
    at = used;
  }
  scene.bytes = upload.bytes + at;
  scene.size = upload.size - at;
  return true;
}

}  // namespace

SceneResult render_board_rows(const formats::Format& format, const BoardScene& scene, RgbaRowSink rows) {
  const BoardFormat& f = kBoardFormats[static_cast<size_t>(format.id)];
  if (f.rows == nullptr) {
    scene.error->text(format.title).text(" scenes are not sent as text uploads");
    return SceneResult::kSceneError;
  }
  return f.rows(scene, rows);
}

SceneResult stream_board_image(const formats::Format& format, const BoardScene& scene, ByteSink out) {
  if (format.reply == formats::ImageKind::kBmp) {
    BmpWriter bmp(out);
    return render_board_rows(format, scene, rgba_row_sink_of(bmp));
  }
  PngStoredWriter png(out);
  return render_board_rows(format, scene, rgba_row_sink_of(png));
}

namespace {

// The upload's format and text: null, with the error set, when the tag is
// unknown or the preamble is damaged.
const formats::Format* open_upload(const send::text::TextScene& upload, BoardScene& scene, MemorySource& text) {
  const formats::Format* format = formats::format_with_tag(upload.format);
  if (format == nullptr) {
    scene.error->text("unknown scene format tag ").number(upload.format);
    return nullptr;
  }
  if (!view_textures(upload, scene)) return nullptr;
  text = MemorySource{scene.bytes, scene.size};
  scene.text = text.source();
  return format;
}

}  // namespace

SceneResult render_uploaded_rows(const send::text::TextScene& upload, BoardScene scene, RgbaRowSink rows) {
  MemorySource text{nullptr, 0};
  const formats::Format* format = open_upload(upload, scene, text);
  return format != nullptr ? render_board_rows(*format, scene, rows) : SceneResult::kSceneError;
}

SceneResult stream_uploaded_image(const send::text::TextScene& upload, BoardScene scene, ByteSink out) {
  MemorySource text{nullptr, 0};
  const formats::Format* format = open_upload(upload, scene, text);
  return format != nullptr ? stream_board_image(*format, scene, out) : SceneResult::kSceneError;
}

}  // namespace minrt::fw
