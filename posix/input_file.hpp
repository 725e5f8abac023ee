// The one rule for every file a host tool reads (scenes, includes,
// textures, references, programs, firmware-sim's ELF, hex image, board,
// machine, cycle-model and FPU-model files): a regular file only, its size
// checked against the caller's bound before a byte is read, opened without
// blocking (a FIFO with no writer would block open() forever) and blocking
// again once it is known to be a regular file. A directory, FIFO, device,
// socket or oversized file is one reason ("Is a directory", "not a regular
// file (a FIFO)", "larger than N bytes"), never a hang or an unbounded read.
#pragma once

#include <cstddef>
#include <string>

namespace minrt::host {

// Opens `path` for reading and keeps it only when it is a regular file: -1
// with the reason otherwise. The descriptor is blocking when returned.
int open_regular_file(const std::string& path, std::string& error);

// Opens a stream the user names on purpose (firmware-sim's --uart-in): a
// FIFO, terminal or device is allowed, a directory is not. Opened with
// O_NONBLOCK so a FIFO without a writer cannot block the open, then
// blocking again. -1 with the reason on failure.
int open_input_stream(const std::string& path, std::string& error);

// Reads `path` (a regular file only) into `out`. False with `error` set to
// the reason when it cannot; `max_bytes` bounds what is read (every caller
// names its bound) and is checked against the file's size before reading.
bool read_whole_file(const std::string& path, std::string& out, std::string& error, std::size_t max_bytes);

// The same from an open descriptor (minrt's standard input), left open: a
// regular file is refused by its size, a pipe one read past the bound;
// `out` is empty after a failure.
bool read_whole_fd(int fd, std::string& out, std::string& error, std::size_t max_bytes);

}  // namespace minrt::host
