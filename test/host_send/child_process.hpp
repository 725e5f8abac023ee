// Starting a program under test as a child process with its output in files.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace hs_test {

// Starts argv[0] with the arguments in a child: standard input from
// /dev/null, standard output and error to the files named (created), in
// `dir` when one is given, SIGINT at its default action (a test runner may
// ignore it for its children; a user's Ctrl-C reaches a program that has not).
pid_t start_program(const std::vector<std::string>& argv, const std::string& out_path, const std::string& err_path,
                    const std::string& dir = {});

}  // namespace hs_test
