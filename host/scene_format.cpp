#include "scene_format.hpp"

namespace minrt::host {

bool parse_scene_format(const std::string& name, SceneFormat& out) {
  if (name == "sld") out = SceneFormat::kSld;
  else if (name == "cs418") out = SceneFormat::kCs418;
  else return false;
  return true;
}

SceneFormat detect_scene_format(const std::string& path, const std::string& head) {
  auto ends_with = [&](const char* tail) {
    const std::string t(tail);
    return path.size() >= t.size() && path.compare(path.size() - t.size(), t.size(), t) == 0;
  };
  if (ends_with(".sld") || ends_with(".SLD")) return SceneFormat::kSld;
  std::size_t i = 0;
  while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) ++i;
  if (head.compare(i, 3, "png") == 0 && (i + 3 == head.size() || head[i + 3] == ' ' || head[i + 3] == '\t'))
    return SceneFormat::kCs418;
  return SceneFormat::kSld;
}

}  // namespace minrt::host
