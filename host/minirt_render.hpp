// The host's driver for miniRT scenes on the general tracer: parse into an
// arena sized from the text, load the PPM textures the scene names, place
// the camera for the image size, render rows on several threads.
#pragma once

#include <string>

#include "formats/minirt/minirt_reader.hpp"
#include "general_render.hpp"

namespace minrt::host {

inline constexpr int kMinirtDefaultWidth = 800;
inline constexpr int kMinirtDefaultHeight = 600;

// Renders miniRT scene text at width x height. `name` is used in messages,
// `base_dir` (with its trailing slash, or empty) resolves texture names. On
// a scene error returns false with `error` set to the explicit line that
// follows "Error" ("scene.rt:3: sphere diameter \"3abc\" is not a number").
bool render_minirt(const std::string& text, const std::string& name, const std::string& base_dir, int width,
                   int height, const minirt::ReaderOptions& reader, const GeneralOptions& options,
                   GeneralResult& out, std::string& error);

}  // namespace minrt::host
