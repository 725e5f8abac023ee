// One small table-driven command-line parser for every host tool: each
// option is a row (long name, optional short letter, whether it takes a
// value, its help line), and the tool's help text is printed from the same
// rows, so an option and its documentation cannot drift apart.
//
// Accepted forms: `--name VALUE`, `--name=VALUE`, `-x VALUE`, `-x` for
// flags, `--` ends the options, `-` alone is an operand (standard input).
// An option may take its value optionally (host-send's `--sim [ELF]`).
// An option may be given again: the handler sees each one. A row without a
// name is a heading: the help prints its text, the parser skips it.
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

// The same for a tool that passes words on (`TOOL [OPTIONS] FILE -- ARGS...`):
// the words after `--` go to `rest`, not to the handler.
bool parse(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error,
           std::vector<std::string>& rest);

// The options' help lines, aligned: "  -o, --output FILE   write ...".
void print_options(std::FILE* f, const std::vector<Option>& options);

// The rows every tool ends its table with.
inline const Option kHelpOption{"help", 'h', nullptr, "this text"};
inline const Option kVersionOption{"version", 0, nullptr, "version"};

// Prints "TOOL: error: MESSAGE (see TOOL --help)", the one line of a usage
// error, on standard error; returns its exit status, 2.
int usage_error(const char* tool, const std::string& message);

// A tool's whole command line: its options, to which -h/--help and
// --version are added, and the help around them.
struct Tool {
  const char* name;             // "image-compare"
  std::string usage;            // "Usage: ..." and what the tool does, before the options
  std::vector<Option> options;  // the tool's own
  std::string footer;           // after the options (exit statuses); may be empty
  // The operands (the words that are not options) parse_tool collects: how
  // many the tool takes and their name in its errors ("image").
  std::size_t min_operands = 0, max_operands = 0;
  const char* operand = "argument";
};

// The help: usage, the options with help and version, footer.
void print_help(std::FILE* f, const Tool& tool);

// Parses argv for `tool`: the handler sees the tool's own options, and the
// operands unless `operands` is given, which then collects them, as many as
// the tool takes; `rest`, when given, takes the words after `--`. False
// when the program ends now with `status`: 0 once the help or
// "NAME VERSION" is printed on standard output, 2 once a usage error is.
bool parse_tool(int argc, char** argv, const Tool& tool, const char* version, const Handler& handler, int& status,
                std::vector<std::string>* operands = nullptr, std::vector<std::string>* rest = nullptr);

}  // namespace minrt::cli
