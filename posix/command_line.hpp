// One small table-driven command-line parser for every host tool: each
// option is a row (long name, optional short letter, whether it takes a
// value, its help line), and the tool's help text is printed from the same
// rows, so an option and its documentation cannot drift apart.
//
// Accepted forms: `--name VALUE`, `--name=VALUE`, `-x VALUE`, `-x` for
// flags, `--` ends the options, `-` alone is an operand (standard input).
// An option may take its value optionally (host-send's `--sim [ELF]`).
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace minrt::cli {

struct Option {
  const char* name;        // without the dashes: "size"
  char letter = 0;         // 'o' for -o, 0 when none
  const char* value = nullptr;  // the value's name in the help ("WxH"); null for a flag
  const char* help = "";   // one or more lines, '\n' between them
  // Set when the value may be left out (the help shows [VALUE]): it is then
  // given as `--name=VALUE`, or is the next argument when this says so; else "".
  bool (*is_value)(const char* next) = nullptr;
};

// Called for each option in order with its row and value ("" for a flag),
// and for each operand with a null row. Returns "" to go on, or the error
// message.
using Handler = std::function<std::string(const Option* option, const std::string& value)>;

// Parses argv[1..argc) against `options`. False with `error` set ("unknown
// option '--x'", "--size needs a value", or the handler's message).
bool parse(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error);

// The options' help lines, aligned: "  -o, --output FILE   write ...".
void print_options(std::FILE* f, const std::vector<Option>& options);

}  // namespace minrt::cli
