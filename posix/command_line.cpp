#include "posix/command_line.hpp"

#include <cstring>

namespace minrt::cli {

namespace {

const Option* by_name(const std::vector<Option>& options, const std::string& name) {
  for (const Option& o : options)
    if (o.name != nullptr && name == o.name) return &o;
  return nullptr;
}

const Option* by_letter(const std::vector<Option>& options, char letter) {
  for (const Option& o : options)
    if (o.letter != 0 && o.letter == letter) return &o;
  return nullptr;
}

std::string spelled(const Option& o) { return std::string("--") + o.name; }

// `rest`, when given, takes the words after `--`.
bool parse_args(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error,
                std::vector<std::string>* rest) {
  bool operands_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const Option* option = nullptr;
    std::string value;
    bool inline_value = false;
    if (operands_only && rest != nullptr) {
      rest->push_back(arg);
      continue;
    }
    if (operands_only || arg.size() < 2 || arg[0] != '-') {
      error = handler(nullptr, arg);
      if (!error.empty()) return false;
      continue;
    }
    if (arg == "--") {
      operands_only = true;
      continue;
    }
    if (arg[1] == '-') {
      const std::size_t eq = arg.find('=');
      option = by_name(options, arg.substr(2, eq == std::string::npos ? std::string::npos : eq - 2));
      if (option != nullptr && eq != std::string::npos) {
        value = arg.substr(eq + 1);
        inline_value = true;
      }
    } else if (arg.size() == 2) {
      option = by_letter(options, arg[1]);
    }
    if (option == nullptr) {
      error = "unknown option '" + arg + "'";
      return false;
    }
    if (option->value == nullptr && inline_value) {
      error = spelled(*option) + " takes no value";
      return false;
    }
    if (option->value != nullptr && !inline_value && option->is_value != nullptr) {
      if (i + 1 < argc && option->is_value(argv[i + 1])) value = argv[++i];
    } else if (option->value != nullptr && !inline_value) {
      if (i + 1 >= argc) {
        error = spelled(*option) + " needs a value";
        return false;
      }
      value = argv[++i];
    }
    error = handler(option, value);
    if (!error.empty()) return false;
  }
  return true;
}

}  // namespace

bool parse(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error) {
  return parse_args(argc, argv, options, handler, error, nullptr);
}

bool parse(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error,
           std::vector<std::string>& rest) {
  return parse_args(argc, argv, options, handler, error, &rest);
}

int usage_error(const char* tool, const std::string& message) {
  std::fprintf(stderr, "%s: error: %s (see %s --help)\n", tool, message.c_str(), tool);
  return 2;
}

namespace {

std::vector<Option> with_help_and_version(const Tool& tool) {
  std::vector<Option> all = tool.options;
  all.push_back(kHelpOption);
  all.push_back(kVersionOption);
  return all;
}

}  // namespace

void print_help(std::FILE* f, const Tool& tool) {
  std::fputs(tool.usage.c_str(), f);
  print_options(f, with_help_and_version(tool));
  std::fputs(tool.footer.c_str(), f);
}

bool parse_tool(int argc, char** argv, const Tool& tool, const char* version, const Handler& handler, int& status,
                std::vector<std::string>* operands, std::vector<std::string>* rest) {
  bool help = false, show_version = false;
  const std::string operand = tool.operand;
  const auto own = [&](const Option* o, const std::string& v) -> std::string {
    if (o == nullptr && operands != nullptr) {
      if (operands->size() < tool.max_operands) operands->push_back(v);
      else if (tool.max_operands == 0) return "unexpected " + operand + " '" + v + "'";
      else if (tool.max_operands == 1) return "more than one " + operand + " given";
      else return "more than " + std::to_string(tool.max_operands) + " " + operand + "s given";
    } else if (o != nullptr && std::strcmp(o->name, kHelpOption.name) == 0) {
      help = true;
    } else if (o != nullptr && std::strcmp(o->name, kVersionOption.name) == 0) {
      show_version = true;
    } else {
      return handler(o, v);
    }
    return "";
  };
  std::string error;
  if (!parse_args(argc, argv, with_help_and_version(tool), own, error, rest)) {
    status = usage_error(tool.name, error);
    return false;
  }
  if (!help && !show_version && operands != nullptr && operands->size() < tool.min_operands) {
    status = usage_error(tool.name, tool.min_operands == 1 ? "no " + operand + " given"
                                                           : std::to_string(tool.min_operands) + " " + operand +
                                                                 "s are needed");
    return false;
  }
  status = 0;
  if (help) print_help(stdout, tool);
  else if (show_version) std::printf("%s %s\n", tool.name, version);
  return !help && !show_version;
}

void print_options(std::FILE* f, const std::vector<Option>& options) {
  constexpr std::size_t kColumn = 27;
  for (const Option& o : options) {
    if (o.name == nullptr) {
      std::fprintf(f, "%s\n", o.help);
      continue;
    }
    std::string left = "  ";
    left += o.letter != 0 ? std::string("-") + o.letter + ", " : "    ";
    left += spelled(o);
    if (o.value != nullptr) left += o.is_value != nullptr ? std::string(" [") + o.value + "]" : std::string(" ") + o.value;
    const char* help = o.help;
    bool first = true;
    while (first || *help != 0) {
      const char* end = std::strchr(help, '\n');
      const std::size_t n = end != nullptr ? static_cast<std::size_t>(end - help) : std::strlen(help);
      std::string line = first ? left : std::string();
      if (line.size() >= kColumn && first) {
        std::fprintf(f, "%s\n", line.c_str());
        line.clear();
      }
      line.resize(kColumn, ' ');
      std::fprintf(f, "%s%.*s\n", line.c_str(), static_cast<int>(n), help);
      help += n;
      if (*help == '\n') ++help;
      first = false;
    }
  }
}

}  // namespace minrt::cli
