// Flame graph as a standalone SVG (--flame-out): one box per call path,
// width = its inclusive cycles, callers below callees, the full name and
// cost in each box's tooltip. Opens in any web browser; no tools needed.
#pragma once
#include <ostream>
#include <string>

#include "profiler.hpp"

namespace fwsim {

// `title` heads the picture (e.g. the ELF's name and the cycle model).
void write_flame_graph_svg(const Profiler& p, std::ostream& out, const std::string& title);

}  // namespace fwsim
