#include "posix/command_line.hpp"

#include <cstring>

namespace minrt::cli {

namespace {

const Option* by_name(const std::vector<Option>& options, const std::string& name) {
  for (const Option& o : options)
    if (name == o.name) return &o;
  return nullptr;
}

const Option* by_letter(const std::vector<Option>& options, char letter) {
  for (const Option& o : options)
    if (o.letter != 0 && o.letter == letter) return &o;
  return nullptr;
}

std::string spelled(const Option& o) { return std::string("--") + o.name; }

}  // namespace

bool parse(int argc, char** argv, const std::vector<Option>& options, const Handler& handler, std::string& error) {
  bool operands_only = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const Option* option = nullptr;
    std::string value;
    bool inline_value = false;
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

void print_options(std::FILE* f, const std::vector<Option>& options) {
  constexpr std::size_t kColumn = 27;
  for (const Option& o : options) {
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
