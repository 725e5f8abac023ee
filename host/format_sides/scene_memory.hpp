// The one arena a scene takes on the host, sized from what the text holds
// rather than from its byte count (blanks and comments cost nothing), and
// grown when a reader finds its tables full: a format's prepare() runs its
// read in a loop, doubling the capacity while the reader's Diagnostic says
// out_of_memory. An allocation the system refuses is a one-line error.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <string>

namespace minrt::host {

// At most this many doublings after the first try: from the content-based
// first guess, 2^12 times the tables covers any text kMaxSceneBytes holds.
inline constexpr int kMaxArenaGrowths = 12;

// Bytes that are not blank (space, tab, CR, LF): what a scene's items take.
inline std::size_t content_bytes(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c != ' ' && c != '\t' && c != '\r' && c != '\n';
  return n;
}

// The same outside comments that run from `marker` to the end of the line
// (Jaworski's #): a scene of one sphere and a 10 MB comment is one sphere.
inline std::size_t content_bytes_outside_comments(const std::string& text, char marker) {
  std::size_t n = 0;
  bool in_comment = false;
  for (char c : text) {
    if (c == '\n') in_comment = false;
    else if (c == marker) in_comment = true;
    n += !in_comment && c != ' ' && c != '\t' && c != '\r' && c != '\n';
  }
  return n;
}

// Lines with something other than blanks on them.
inline std::size_t content_lines(const std::string& text) {
  std::size_t n = 0;
  bool any = false;
  for (char c : text) {
    if (c == '\n') {
      n += any;
      any = false;
    } else if (c != ' ' && c != '\t' && c != '\r') {
      any = true;
    }
  }
  return n + any;
}

struct ArenaStorage {
  std::unique_ptr<unsigned char[]> bytes;
  std::size_t size = 0;

  // False, with `error` set, when the system has not that much memory.
  bool allocate(std::size_t n, const std::string& name, std::string& error) {
    bytes.reset(new (std::nothrow) unsigned char[n]);
    size = bytes ? n : 0;
    if (!bytes) error = name + ": error: the scene needs " + std::to_string(n >> 20) + " MiB, which the system refused";
    return bytes != nullptr;
  }
};

}  // namespace minrt::host
