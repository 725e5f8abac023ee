// Bounds of the miniRT reader, defined once: the host, the board and the
// tests size their buffers from these.
#pragma once

namespace minrt::minirt {

inline constexpr int kMaxLineBytes = 4096;  // longer lines are refused, not cut
inline constexpr int kMaxFields = 8;        // `spt` has the most: 5 (+1 optional)
inline constexpr int kMaxPathBytes = 255;   // a texture file name
inline constexpr int kMaxTextures = 16;     // distinct texture files in one scene

}  // namespace minrt::minirt
