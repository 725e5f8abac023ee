#include "output_check.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace fwsim {

std::string output_path_problem(const std::string& path) {
  auto reason = [&](int err) { return path + ": " + std::strerror(err); };
  if (path.empty()) return "empty output file name";
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) return reason(EISDIR);
    if (::access(path.c_str(), W_OK) != 0) return reason(errno);
    return "";
  }
  if (errno != ENOENT) return reason(errno);
  // A new file: its folder must exist and be writable.
  const size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  if (::stat(dir.c_str(), &st) != 0) return reason(errno);
  if (!S_ISDIR(st.st_mode)) return reason(ENOTDIR);
  if (::access(dir.c_str(), W_OK | X_OK) != 0) return reason(errno);
  return "";
}

}  // namespace fwsim
