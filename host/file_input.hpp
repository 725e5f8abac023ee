// The host tools' scene-size bound and minrt's scene reading; the rule for
// opening and reading every input file is posix/input_file.hpp's.
#pragma once

#include <cstddef>
#include <string>

#include "posix/input_file.hpp"  // open_regular_file, read_whole_file, read_whole_fd

namespace minrt::host {

// The largest scene file a host tool reads (minrt in every text format, the
// files an EASTRAY scene includes, host-send's upload): 256 MiB, some 280
// times the largest scene in ../shared (ray-many.txt, 0.9 MB). The wire
// formats carry a scene's length in 32 bits (protocol/text_scene_upload.hpp)
// and the board has 4 MiB of RAM by default, so a scene this large already
// cannot reach the board; on the host the bound stops a wrong path to a huge
// file at once with "larger than N bytes" rather than filling the memory.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 28;

// minrt's scene files: reads `path` (unless it is "-", whose text the caller
// already has) into `text`; on failure prints "minrt: error: cannot read
// PATH: REASON" and returns false.
bool read_scene_file(const std::string& path, std::string& text, std::size_t max_bytes);

}  // namespace minrt::host
