// Image limits shared by every side: the renderers, the host tools and the
// firmware. Each format's own limits live with its reader
// (formats/sld/sld_limits.hpp).
#pragma once

namespace minrt::limits {

inline constexpr int kMaxImageWidth = 4096;
inline constexpr int kMaxImageHeight = 4096;
inline constexpr int kDefaultImageWidth = 512;
inline constexpr int kDefaultImageHeight = 512;

}  // namespace minrt::limits
