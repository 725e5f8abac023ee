// The EASTRAY preprocessor (manual lines 13-17, 27), run on the host before
// the reader sees the scene: `/* */` comments, `#include "file"` (the
// including file's folder, then the current folder), `#include <file>`
// (the folder in the EASTRAY environment variable), `#define NAME body`
// (token substitution from that line on). The board gets the expanded text.
#pragma once

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

  // "FILE:LINE" of a line of `text` (1-based).
  std::string where(int line) const;
};

// Expands `text`, read from `path` (shown as `shown`). False with a located
// one-line message ("FILE:LINE:COL: error: ...") in `error`.
bool preprocess_eastray(const std::string& path, const std::string& shown, const std::string& text,
                        ExpandedEastray& out, std::string& error);

}  // namespace minrt::host
