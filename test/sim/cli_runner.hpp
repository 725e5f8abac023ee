// Runs the firmware-sim binary from the CLI tests: a command line in, exit
// status and both output streams back; temporary files per test process.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace cli {

struct Result {
  int status;
  std::string out, err;
};

inline std::string temp_path(const std::string& name) {
  return std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/fwsim_cli_" +
         std::to_string(::getpid()) + "_" + name;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void spit(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// Runs firmware-sim with `args` (shell syntax) and `input` on stdin.
inline Result sim(const std::string& args, const std::string& input = "") {
  const std::string in = temp_path("in"), out = temp_path("out"), err = temp_path("err");
  spit(in, input);
  const std::string cmd = std::string(FWSIM_BINARY) + " " + args + " <" + in + " >" + out + " 2>" + err;
  const int rc = std::system(cmd.c_str());
  Result r{WIFEXITED(rc) ? WEXITSTATUS(rc) : -1, slurp(out), slurp(err)};
  std::remove(in.c_str());
  std::remove(out.c_str());
  std::remove(err.c_str());
  return r;
}

inline const std::string kElf = FWSIM_TEST_ELF;

// The number after "key: " in --stats output, or all ones when absent.
inline uint64_t stat_value(const std::string& err, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(err, m, std::regex("(^|\n)" + key + ": ([0-9]+)\n"))) return ~uint64_t{0};
  return std::stoull(m[2]);
}

}  // namespace cli
