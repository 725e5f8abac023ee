// The EASTRAY preprocessor (manual lines 13-17, 27), run on the host before
// the reader sees the scene: `/* */` comments, `#include "file"` (the
// including file's folder, then the current folder), `#include <file>`
// (the folder in the EASTRAY environment variable), `#define NAME body`
// (token substitution from that line on). The board gets the expanded text.
//
// Bounded: includes nest at most 64 deep, macro bodies 32; and all the work
// (every byte emitted, every included file plus 1 KiB for opening it,
// every macro body copied plus 64 bytes for the call) is charged against a
// budget of 64 times the scene file's size, at least 1 MiB and at most
// 64 MiB. Past it, or past a depth, the scene is refused with a located
// error, so self-doubling includes or macros end in milliseconds.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace minrt::host {

struct EastrayLineOrigin {
  int file = 0;  // index into ExpandedEastray::files
  int line = 1;
};

struct ExpandedEastray {
  std::string text;                       // comments removed, macros expanded, includes inlined
  std::vector<std::string> files;         // as named in messages
  std::vector<EastrayLineOrigin> lines;   // origin of each line of `text`
  // Where the scene's own file ends, just after its last character: past a
  // final newline that is the line after it, column 1; without one, the
  // last line, one column past its end.
  int end_line = 1;
  int end_col = 1;

  // "FILE:LINE" of a line of `text` (1-based).
  std::string where(int line) const;
  // "FILE:LINE:COL" of a position in `text`; a position past its last line
  // (the end of the scene) is the scene file's end.
  std::string at(int line, int col) const;
};

// Where #include looks for files: the file system (eastray_files()) or,
// for the fuzzer and tests, files held in memory.
class EastrayFiles {
 public:
  virtual ~EastrayFiles() = default;
  virtual bool readable(const std::string& path) const = 0;
  // One name for each file, so a cycle is seen whatever path reaches it.
  virtual std::string canonical(const std::string& path) const = 0;
  // The whole file, at most `max_bytes`; false with the reason.
  virtual bool read(const std::string& path, std::string& out, std::string& why, std::size_t max_bytes) const = 0;
};
const EastrayFiles& eastray_files();

// Expands `text`, read from `path` (shown as `shown`). False with a located
// one-line message ("FILE:LINE:COL: error: ...") in `error`.
bool preprocess_eastray(const std::string& path, const std::string& shown, const std::string& text,
                        ExpandedEastray& out, std::string& error);
bool preprocess_eastray(const std::string& path, const std::string& shown, const std::string& text,
                        ExpandedEastray& out, std::string& error, const EastrayFiles& files);

}  // namespace minrt::host
