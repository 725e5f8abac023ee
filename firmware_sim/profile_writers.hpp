// Profile output formats: callgrind (callgrind_annotate, KCachegrind) and
// folded stacks (flamegraph.pl, speedscope, inferno).
#pragma once
#include <ostream>
#include <string>

#include "profiler.hpp"

namespace fwsim {

void write_callgrind(const Profiler& p, std::ostream& out, const std::string& command,
                     const std::string& elf_path);
// One line per call path: "f1;f2;f3 <cycles>" with the path's exclusive cycles.
void write_folded(const Profiler& p, std::ostream& out);

}  // namespace fwsim
