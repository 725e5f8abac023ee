// Reading a whole input file on the host with the system's reason on
// failure: a directory, an unreadable file or one over a size bound gets a
// message, never an exception or a silent empty read.
#pragma once

#include <cstddef>
#include <string>

namespace minrt::host {

// The largest scene file a host tool reads (minrt in every text format, the
// files an EASTRAY scene includes, host-send's upload): 256 MiB, some 280
// times the largest scene in ../shared (ray-many.txt, 0.9 MB). The wire
// formats carry a scene's length in 32 bits (protocol/text_scene_upload.hpp)
// and the board has 4 MiB of RAM by default, so a scene this large already
// cannot reach the board; on the host the bound stops a wrong path to a huge
// file at once with "larger than N bytes" rather than filling the memory.
inline constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 28;

// Opens `path` for reading without blocking (a FIFO with no writer would
// block open() forever) and keeps it only when it is a regular file: -1
// with the reason ("not a regular file (a FIFO)", the system's error)
// otherwise. The descriptor is blocking again when returned.
int open_regular_file(const std::string& path, std::string& error);

// Reads `path` into `out` (a regular file only: open_regular_file). False with `error` set to the reason ("Is a
// directory", "No such file or directory", "larger than N bytes", ...) when
// it cannot; `max_bytes` bounds what is read (every caller names its bound).
bool read_whole_file(const std::string& path, std::string& out, std::string& error, std::size_t max_bytes);

// The same from an open descriptor (minrt's standard input), left open;
// `out` is empty after a failure.
bool read_whole_fd(int fd, std::string& out, std::string& error, std::size_t max_bytes);

// minrt's scene files: reads `path` (unless it is "-", whose text the caller
// already has) into `text`; on failure prints "minrt: error: cannot read
// PATH: REASON" and returns false.
bool read_scene_file(const std::string& path, std::string& text, std::size_t max_bytes);

}  // namespace minrt::host
