#include "scene_format.hpp"

namespace minrt::host {

bool parse_scene_format(const std::string& name, SceneFormat& out) {
  if (name == "sld") out = SceneFormat::kSld;
  else if (name == "cs418") out = SceneFormat::kCs418;
  else if (name == "jaworski") out = SceneFormat::kJaworski;
  else if (name == "minirt") out = SceneFormat::kMinirt;
  else return false;
  return true;
}

SceneFormat detect_scene_format(const std::string& path, const std::string& head) {
  auto ends_with = [&](const char* tail) {
    const std::string t(tail);
    return path.size() >= t.size() && path.compare(path.size() - t.size(), t.size(), t) == 0;
  };
  if (ends_with(".sld") || ends_with(".SLD")) return SceneFormat::kSld;
  if (ends_with(".rt")) return SceneFormat::kMinirt;
  std::size_t i = 0;
  for (;;) {  // blanks, and Jaworski's # comments (CS418 and SLD have none)
    while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) ++i;
    if (i < head.size() && head[i] == '#') {
      while (i < head.size() && head[i] != '\n') ++i;
      continue;
    }
    break;
  }
  // The first word: SLD starts with a number; a CS418 file with `png`, or
  // (when the png line is missing) with another of its keywords, which the
  // CS418 reader then reports properly.
  std::size_t end = i;
  while (end < head.size() && head[end] != ' ' && head[end] != '\t' && head[end] != '\r' && head[end] != '\n') ++end;
  const std::string word = head.substr(i, end - i);
  std::string lower;
  for (char c : word) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) break;  // Jaworski tokens may be glued
    lower.push_back(static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c));
  }
  for (const char* k : {"imwidth", "imheight", "canvwidth", "canvheight", "depth", "bgcolor", "raydepth", "lights",
                        "objects"})
    if (lower == k) return SceneFormat::kJaworski;
  static const char* const kCs418Words[] = {
      "png", "color", "sphere", "sun", "expose", "eye", "forward", "up", "fisheye", "panorama", "plane", "xyz",
      "tri", "texcoord", "texture", "bulb", "shininess", "bounces", "transparency", "ior", "roughness", "aa",
      "dof", "gi"};
  for (const char* k : kCs418Words)
    if (word == k) return SceneFormat::kCs418;
  for (const char* k : {"A", "C", "L", "sp", "pl", "cy", "co", "plc", "spt"})
    if (word == k) return SceneFormat::kMinirt;
  return SceneFormat::kSld;
}

}  // namespace minrt::host
