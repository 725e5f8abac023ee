// A fixture for tools/layout/check_format_lists.py: a second list of
// formats outside the registry, which the checker must report.
#include "formats/registry.hpp"

int reply_bytes(minrt::formats::FormatId id, const char* path) {
  if (id == minrt::formats::FormatId::kJaworski) return 4;  // reported: compares FormatIds
  const char* ext = ".RT";                                  // reported: a format's extension
  (void)path;
  (void)ext;
  return 3;
}
