// Which texels of its textures a CS418 scene's render reads, found by
// rendering it here as the board does (float, portable shims: the host
// float model, whose image equals the board's) with the texel watch on
// (render/general/surface_maps.hpp). host-send then sends only the tiles
// that hold them (texture_preamble.hpp).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace minrt::send {

// Texture name (as the scene writes it) -> one byte a texel, 1 where read.
using TexelMarks = std::map<std::string, std::vector<std::uint8_t>>;

// False when the scene does not render here (a scene error, which the board
// reports itself, or no memory): then nothing is known and every texel goes.
// `progress`: a progress line on stderr if the render takes long (it runs
// on one thread before the link opens).
bool record_cs418_texels(const std::string& scene, const std::string& base_dir, TexelMarks& marks,
                         bool progress = false);

}  // namespace minrt::send
