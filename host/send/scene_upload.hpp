// What host-send sends the board for each format in the registry
// (formats/registry.hpp), and what it expects back: one row per format in
// kUploads, in the registry's order (a format without its row does not
// compile). The protocols and the receivers are chosen from the registry's
// reply image alone.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "formats/registry.hpp"

namespace minrt::send {

struct UploadRequest {
  std::string path;             // the scene file as given
  std::string base_dir;         // its folder, with the slash, or ""
  std::uint64_t texture_bytes;  // board RAM the textures may take
  int width = 0, height = 0;    // --size (0: not given)
  bool sparse_textures = true;  // CS418: send only the texture tiles the render reads (not --full-textures)
  bool progress = false;        // a progress line for long work here (host-send's own render)
};

struct Upload {
  std::string bytes;            // what raw sends before its 0x04 (course and framed: the same behind a header)
  std::size_t text_at = 0;      // where the scene's text starts in `bytes` (after a texture preamble)
  bool sparse = false;          // the textures went sparse (MINRT_TEXTURES_SPARSE_MARKER)
  std::string note;             // for the summary: how many texels went
  int width = 0, height = 0;    // the reply's size (0: the board's --size; BMP: the scene's)
  std::string output;           // where the image goes without -o ("": the scene's stem with the reply's extension)
  std::string warning;          // printed before the transfer, when no -o names the output
  std::string refusal;          // why the default output cannot be written (a format we do not write)
  std::vector<std::string> scene_warnings;  // the scene's own, located lines, printed before the transfer (not under -q)
  bool stereo = false;          // the reply is EASTRAY's pair, right above left: written as _r and _l files
  // The file written at a path from the board's PNG (each of a stereo pair
  // alone); empty: the PNG recompressed.
  std::function<bool(const std::string& path, const std::string& png, std::string& file, std::string& warning,
                     std::string& error)>
      write_as;
};

struct UploadFormat {
  formats::FormatId id;
  // Checks `scene` here (so a bad one gets its located message before
  // anything is sent) and prepares the upload; false with the message.
  bool (*prepare)(const UploadRequest& request, std::string scene, Upload& out, std::string& error);
};

const UploadFormat& upload_format(formats::FormatId id);

}  // namespace minrt::send
