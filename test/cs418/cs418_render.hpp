// A CS418 scene's text rendered in memory by minrt's driver (the format's
// prepare and the row pool), for the tests of this folder.
#pragma once

#include <string>

#include "render_driver.hpp"

namespace minrt::test {

inline bool render_cs418(const std::string& text, const std::string& name, const std::string& dir,
                         const host::DriverOptions& o, host::RenderedScene& r, std::string& error) {
  const host::SceneInput in{name, name, dir, text};
  return host::render_in_memory(formats::format_of(formats::FormatId::kCs418), in, o, r, error);
}

}  // namespace minrt::test
