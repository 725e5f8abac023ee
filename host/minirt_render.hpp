// The host's driver for miniRT scenes on the general tracer: parse into an
// arena sized from the text, load the PPM textures the scene names, place
// the camera for the image size, render rows on several threads.
#pragma once

#include <string>

#include "general_render.hpp"

namespace minrt::host {

inline constexpr int kMinirtDefaultWidth = 800;
inline constexpr int kMinirtDefaultHeight = 600;

// Renders miniRT scene text at width x height. `name` is used in messages,
// `base_dir` (with its trailing slash, or empty) resolves texture names. On
// a scene error returns false with `error` set to the explicit line that
// follows "Error" ("scene.rt:3: sphere diameter \"3abc\" is not a number").
bool render_minirt(const std::string& text, const std::string& name, const std::string& base_dir, int width,
                   int height, const GeneralOptions& options, GeneralResult& out, std::string& error);

// Where a texture name of a scene is looked for, in order: an absolute name
// as it is; else relative to the scene's folder; else its last component in
// the scene's folder (the shared scenes name `scenes/textures/earth.ppm`
// and ship the file beside them).
std::vector<std::string> minirt_texture_candidates(const std::string& base_dir, const std::string& name);

}  // namespace minrt::host
