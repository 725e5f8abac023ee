#include "scene_upload.hpp"

#include <minrt/limits.hpp>
#include <minrt/serial_protocol.h>

#include "format_sides/cs418_host.hpp"
#include "format_sides/eastray_host.hpp"
#include "format_sides/jaworski_host.hpp"
#include "format_sides/minirt_host.hpp"
#include "render_driver.hpp"
#include "texel_record.hpp"
#include "texture_preamble.hpp"

namespace minrt::send {

namespace {

using formats::FormatId;

// SLD travels as it is; the board answers with the PPM at its --size.
bool prepare_sld(const UploadRequest&, std::string scene, Upload& out, std::string&) {
  out.bytes = std::move(scene);
  return true;
}

// CS418: the textures it names, decoded here (the board has no PNG
// decoder), go first; the reply's size and default name are the png line's.
bool prepare_cs418(const UploadRequest& r, std::string scene, Upload& out, std::string& error) {
  std::string name;
  if (!host::cs418_png_line(scene, out.width, out.height, name)) {
    // The reply's size comes from that line, so the board cannot be asked.
    // minrt's reader, given the line alone, says what is wrong and where.
    const std::string first = scene.substr(0, scene.find('\n'));
    host::RenderedScene unused;
    const host::SceneInput in{r.path, r.path, "", first + "\n"};
    if (host::render_in_memory(formats::format_of(FormatId::kCs418), in, host::DriverOptions{}, unused, error))
      error = r.path + ":1:1: error: the first line must be 'png WIDTH HEIGHT FILE.png' (1.." +
              std::to_string(limits::kMaxImageWidth) + " each)";
    return false;
  }
  out.output = name;
  // Only the tiles the render reads, found by rendering the scene here
  // as the board will (texel_record.hpp), unless --full-textures.
  TexelMarks marks;
  const bool recorded = r.sparse_textures && scene.find("texture") != std::string::npos &&
                        record_cs418_texels(scene, r.base_dir, marks, r.progress);
  std::string preamble;
  TexelCount count;
  if (!build_texture_preamble(scene, r.path, r.base_dir, r.texture_bytes, preamble, error, recorded ? &marks : nullptr,
                              &count))
    return false;
  out.text_at = preamble.size();
  out.sparse = !preamble.empty() && static_cast<unsigned char>(preamble[0]) == MINRT_TEXTURES_SPARSE_MARKER;
  if (out.sparse)
    out.note = "textures: " + std::to_string(count.sent) + " of " + std::to_string(count.texels) +
               " texels sent, the tiles the render reads (--full-textures sends every one)";
  out.bytes = preamble + scene;
  return true;
}

// Jaworski: the text as it is; the BMP's size is the scene's.
bool prepare_jaworski(const UploadRequest& r, std::string scene, Upload& out, std::string&) {
  out.output = host::jaworski_output_name(r.path);
  out.bytes = std::move(scene);
  return true;
}

// miniRT: the subject's file name, the PPM textures decoded here, the PNG at --size.
bool prepare_minirt(const UploadRequest& r, std::string scene, Upload& out, std::string& error) {
  if (!host::has_rt_extension(r.path)) {
    error = r.path + ": a miniRT scene file's name must end in .rt";
    return false;
  }
  const formats::Format& f = formats::format_of(FormatId::kMinirt);
  out.width = r.width > 0 ? r.width : f.default_width;
  out.height = r.height > 0 ? r.height : f.default_height;
  std::string preamble;
  if (!build_minirt_texture_preamble(scene, r.path, r.base_dir, r.texture_bytes, preamble, error)) return false;
  out.text_at = preamble.size();
  out.bytes = preamble + scene;
  return true;
}

// EASTRAY: preprocessed and checked here, sent expanded behind its
// map_data images (decoded here, as a CS418 scene's textures); the board
// sends PNG (a stereo pair as one, right above left), written here as minrt
// writes its image.
bool prepare_eastray(const UploadRequest& r, std::string scene, Upload& out, std::string& error) {
  std::string statement, text;
  std::vector<std::pair<std::string, std::string>> maps;
  host::EastrayBoardOutput how;
  if (!host::eastray_board_text(r.path, scene, text, out.width, out.height, statement, error, &maps, &how))
    return false;
  out.scene_warnings = std::move(how.warnings);
  out.stereo = how.stereo;
  if (out.stereo) out.height *= 2;  // rmode 1: the right image above the left
  // TIFF or PNG by the name, output_mode, the window kept in an existing file.
  out.write_as = [how](const std::string& path, const std::string& png, std::string& file, std::string& warning,
                       std::string& error) { return host::eastray_board_file(png, how, path, file, warning, error); };
  std::string preamble;
  if (!build_eastray_texture_preamble(maps, r.base_dir, r.texture_bytes, preamble, error)) return false;
  out.text_at = preamble.size();
  out.bytes = preamble + text;
  bool tiff = false;
  std::string unsupported;
  out.output = host::eastray_output_name("", statement, r.path, tiff, unsupported);
  if (!unsupported.empty()) out.refusal = unsupported;  // only when no -o names the output
  return true;
}

constexpr UploadFormat kUploads[] = {
    {FormatId::kSld, &prepare_sld},
    {FormatId::kCs418, &prepare_cs418},
    {FormatId::kJaworski, &prepare_jaworski},
    {FormatId::kMinirt, &prepare_minirt},
    {FormatId::kEastray, &prepare_eastray},
};

static_assert(formats::follows_registry(kUploads), "one row per registered format, in its order");

}  // namespace

const UploadFormat& upload_format(formats::FormatId id) { return kUploads[static_cast<std::size_t>(id)]; }

}  // namespace minrt::send
