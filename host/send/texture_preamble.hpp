// host-send's side of the texture preamble (include/minrt/serial_protocol.h):
// finds the textures a CS418 scene (PNG), a miniRT scene (PPM) or an EASTRAY
// scene names, decodes them and lays them out ahead of the scene text,
// filtered and deflated (the compressed preamble), so the board needs only
// its small inflater (core/base/inflate.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "texel_record.hpp"

namespace minrt::send {

// Fills `out` with the preamble for the textures `scene` names (empty when it
// names none). Texture files resolve against `base_dir`. False with the
// reason: a missing or bad PNG, too many textures, a name too long, or more
// decoded texel bytes than `board_bytes` (then the message names the texture
// that crosses it, the decoded total and the limit).
// A texture that cannot be read is reported where the scene names it,
// "SCENE_NAME:LINE:COL: error: texture PATH: why", as minrt reports it.
// With `marks` (the texels the render reads, texel_record.hpp) a texture
// whose read tiles deflate smaller than the whole goes sparse
// (MINRT_TEXTURES_SPARSE_MARKER); without, or when none does, every texel
// goes, in the compressed preamble.
// `sent`, when given, gets the texels that go (sparse: those of the tiles
// sent) and `texels` all of them.
struct TexelCount {
  std::uint64_t texels = 0, sent = 0;
};
bool build_texture_preamble(const std::string& scene, const std::string& scene_name, const std::string& base_dir,
                            std::uint64_t board_bytes, std::string& out, std::string& error,
                            const TexelMarks* marks = nullptr, TexelCount* sent = nullptr);

// The same for a miniRT scene: the PPM files its `spt` lines name, found
// where minrt finds them (host/texture_files.hpp).
bool build_minirt_texture_preamble(const std::string& scene, const std::string& scene_name,
                                   const std::string& base_dir,
                                   std::uint64_t board_bytes, std::string& out, std::string& error);

// The same for an EASTRAY scene: its map_data images (`maps`: each file
// name as written and the "SCENE:LINE:COL: error: " of its entry), decoded
// as minrt decodes them (host/eastray_maps.hpp) and named as written.
bool build_eastray_texture_preamble(const std::vector<std::pair<std::string, std::string>>& maps,
                                    const std::string& base_dir, std::uint64_t board_bytes, std::string& out,
                                    std::string& error);

}  // namespace minrt::send
