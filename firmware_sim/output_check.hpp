// Checks, before a long run, that an output file can be created where the
// user asked, so a bad path fails at once instead of after the run.
#pragma once
#include <string>

namespace fwsim {

// Empty when `path` can be written (an existing writable file, or a new file
// in an existing writable folder); otherwise "PATH: reason" with strerror's
// reason. Creates nothing.
std::string output_path_problem(const std::string& path);

}  // namespace fwsim
