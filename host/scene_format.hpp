// Which reader a scene file goes to: --scene-format when given, else the
// file's extension, else its first word (SPEC.md 5.2: `png` starts a CS418
// file, a header field such as `imWidth` a Jaworski one (after `#`
// comments); SLD starts with numbers; a `.rt` name or a miniRT element
// identifier (A, C, L, sp, ...) means miniRT, whose reader then insists on
// the `.rt` name); `/*`, `#include`, `#define` or a statement name an
// EASTRAY one (.ray).
#pragma once

#include <string>

namespace minrt::host {

enum class SceneFormat { kAuto, kSld, kCs418, kJaworski, kMinirt, kEastray };

// "sld", "cs418", "jaworski", "minirt", "eastray" -> format; false for an unknown name.
bool parse_scene_format(const std::string& name, SceneFormat& out);

// Decides from the path and the first bytes of the file.
SceneFormat detect_scene_format(const std::string& path, const std::string& head);

}  // namespace minrt::host
