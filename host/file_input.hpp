// Reading a whole input file on the host with the system's reason on
// failure: a directory, an unreadable file or one over a size bound gets a
// message, never an exception or a silent empty read.
#pragma once

#include <cstddef>
#include <string>

namespace minrt::host {

// Reads `path` into `out`. False with `error` set to the reason ("Is a
// directory", "No such file or directory", "larger than N bytes", ...) when
// it cannot; `max_bytes` bounds what is read.
bool read_whole_file(const std::string& path, std::string& out, std::string& error,
                     std::size_t max_bytes = static_cast<std::size_t>(-1));

// minrt's scene files: reads `path` (unless it is "-", whose text the caller
// already has) into `text`; on failure prints "minrt: error: cannot read
// PATH: REASON" and returns false.
bool read_scene_file(const std::string& path, std::string& text, std::size_t max_bytes);

}  // namespace minrt::host
