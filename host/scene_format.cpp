#include "scene_format.hpp"

namespace minrt::host {

bool parse_scene_format(const std::string& name, SceneFormat& out) {
  if (name == "sld") out = SceneFormat::kSld;
  else if (name == "cs418") out = SceneFormat::kCs418;
  else if (name == "jaworski") out = SceneFormat::kJaworski;
  else if (name == "minirt") out = SceneFormat::kMinirt;
  else if (name == "eastray") out = SceneFormat::kEastray;
  else return false;
  return true;
}

namespace {

// EASTRAY: a comment or a preprocessor line first, or a statement name
// (`color` only with its '[': CS418 has a `color` keyword too).
bool looks_like_eastray(const std::string& head) {
  std::size_t i = 0;
  while (i < head.size() && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) ++i;
  const std::string rest = head.substr(i, 16);
  if (rest.rfind("/*", 0) == 0 || rest.rfind("#include", 0) == 0 || rest.rfind("#define", 0) == 0) return true;
  std::size_t end = i;
  while (end < head.size() && head[end] != ' ' && head[end] != '\t' && head[end] != '\r' && head[end] != '\n') ++end;
  const std::string word = head.substr(i, end - i);
  for (const char* k : {"display", "condition", "anti", "camera", "mist", "sky", "env", "shadow", "voxel", "output",
                        "rmode", "e_light", "p_light", "s_light", "map_data", "obj", "input", "back_mode", "output_mode"})
    if (word == k) return true;
  if (word == "color") {
    std::size_t j = end;
    while (j < head.size() && (head[j] == ' ' || head[j] == '\t' || head[j] == '\r' || head[j] == '\n')) ++j;
    return j < head.size() && head[j] == '[';
  }
  return false;
}

}  // namespace

SceneFormat detect_scene_format(const std::string& path, const std::string& head) {
  auto ends_with = [&](const char* tail) {
    const std::string t(tail);
    return path.size() >= t.size() && path.compare(path.size() - t.size(), t.size(), t) == 0;
  };
  if (ends_with(".sld") || ends_with(".SLD")) return SceneFormat::kSld;
  if (ends_with(".rt")) return SceneFormat::kMinirt;
  if (ends_with(".ray") || ends_with(".RAY")) return SceneFormat::kEastray;
  if (looks_like_eastray(head)) return SceneFormat::kEastray;
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
