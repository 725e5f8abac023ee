// posix/command_line.hpp: the table-driven parser every host tool uses.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "posix/command_line.hpp"

namespace {

using minrt::cli::Option;

const std::vector<Option> kTable = {
    {"size", 0, "WxH", "image size"},
    {"output", 'o', "FILE", "write the image to FILE"},
    {nullptr, 0, nullptr, "Debugging:"},
    {"define", 'D', "K=V", "a setting; may be given again"},
    {"stats", 0, nullptr, "print figures"},
    minrt::cli::kHelpOption,
};

// What the handler saw, one "name=value" (operands as "@value") a call.
struct Parsed {
  bool ok = false;
  std::string error;
  std::vector<std::string> seen, rest;
};

Parsed parse(std::vector<std::string> words, bool with_rest = false) {
  words.insert(words.begin(), "tool");
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  Parsed p;
  const auto handler = [&](const Option* o, const std::string& v) -> std::string {
    if (o != nullptr && std::string(o->name) == "size" && v == "bad") return "bad --size 'bad'";
    p.seen.push_back(o == nullptr ? "@" + v : std::string(o->name) + "=" + v);
    return "";
  };
  const int argc = static_cast<int>(argv.size());
  p.ok = with_rest ? minrt::cli::parse(argc, argv.data(), kTable, handler, p.error, p.rest)
                   : minrt::cli::parse(argc, argv.data(), kTable, handler, p.error);
  return p;
}

template <class Print>
std::string printed(Print print) {
  std::FILE* f = std::tmpfile();
  print(f);
  std::string text(static_cast<std::size_t>(std::ftell(f)), '\0');
  std::rewind(f);
  text.resize(std::fread(text.data(), 1, text.size(), f));
  std::fclose(f);
  return text;
}

}  // namespace

TEST_CASE("command line: every form of an option reaches the handler in order", "[command_line]") {
  const Parsed p = parse({"--size", "4x4", "-o", "a.png", "--define=x=1", "-D", "y=2", "scene", "--stats", "-"});
  REQUIRE(p.ok);
  CHECK(p.seen == std::vector<std::string>{"size=4x4", "output=a.png", "define=x=1", "define=y=2", "@scene", "stats=",
                                           "@-"});
}

TEST_CASE("command line: errors name the option", "[command_line]") {
  CHECK(parse({"--bogus"}).error == "unknown option '--bogus'");
  CHECK(parse({"-x"}).error == "unknown option '-x'");
  CHECK(parse({"--size"}).error == "--size needs a value");
  CHECK(parse({"--stats=1"}).error == "--stats takes no value");
  CHECK(parse({"--size", "bad"}).error == "bad --size 'bad'");
  // A heading is no option.
  CHECK(parse({"--Debugging:"}).error == "unknown option '--Debugging:'");
  CHECK_FALSE(parse({"--size"}).ok);
}

TEST_CASE("command line: after --, operands, or the words passed on", "[command_line]") {
  const Parsed plain = parse({"a", "--", "--stats", "b"});
  REQUIRE(plain.ok);
  CHECK(plain.seen == std::vector<std::string>{"@a", "@--stats", "@b"});
  CHECK(plain.rest.empty());
  const Parsed passed = parse({"--stats", "fw.elf", "--", "--stats", "x"}, true);
  REQUIRE(passed.ok);
  CHECK(passed.seen == std::vector<std::string>{"stats=", "@fw.elf"});
  CHECK(passed.rest == std::vector<std::string>{"--stats", "x"});
  // `--` given as an option's value ends nothing.
  const Parsed value = parse({"-o", "--", "y"}, true);
  REQUIRE(value.ok);
  CHECK(value.seen == std::vector<std::string>{"output=--", "@y"});
  CHECK(value.rest.empty());
}

TEST_CASE("command line: the help comes from the table, headings included", "[command_line]") {
  const std::string help = printed([](std::FILE* f) { minrt::cli::print_options(f, kTable); });
  CHECK(help ==
        "      --size WxH           image size\n"
        "  -o, --output FILE        write the image to FILE\n"
        "Debugging:\n"
        "  -D, --define K=V         a setting; may be given again\n"
        "      --stats              print figures\n"
        "  -h, --help               this text\n");
}

namespace {

const minrt::cli::Tool kTool{"tool", "Usage: tool [OPTIONS] A B\n", {{"stats", 0, nullptr, "print figures"}}, "Exit.\n", 2, 2,
                             "image"};

// parse_tool's status and go-on answer, and the operands it collected.
struct ToolRun {
  bool go_on;
  int status;
  std::vector<std::string> operands;
  int stats = 0;
};

ToolRun run_tool(std::vector<std::string> words) {
  words.insert(words.begin(), "tool");
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  ToolRun r{};
  r.go_on = minrt::cli::parse_tool(
      static_cast<int>(argv.size()), argv.data(), kTool, "1.2",
      [&](const Option*, const std::string&) -> std::string {
        ++r.stats;
        return "";
      },
      r.status, &r.operands);
  return r;
}

}  // namespace

TEST_CASE("command line: a tool's operands are counted, help and version end the run", "[command_line]") {
  const ToolRun ok = run_tool({"a.png", "--stats", "b.png"});
  CHECK(ok.go_on);
  CHECK(ok.status == 0);
  CHECK(ok.stats == 1);
  CHECK(ok.operands == std::vector<std::string>{"a.png", "b.png"});
  for (const auto& words : {std::vector<std::string>{"a.png"}, {"a", "b", "c"}, {"--bogus", "a", "b"}}) {
    const ToolRun bad = run_tool(words);
    CHECK_FALSE(bad.go_on);
    CHECK(bad.status == 2);
  }
  // --help and --version need no operands.
  for (const char* word : {"--help", "-h", "--version"}) {
    const ToolRun done = run_tool({word});
    CHECK_FALSE(done.go_on);
    CHECK(done.status == 0);
  }
  const std::string help = printed([](std::FILE* f) { minrt::cli::print_help(f, kTool); });
  CHECK(help ==
        "Usage: tool [OPTIONS] A B\n"
        "      --stats              print figures\n"
        "  -h, --help               this text\n"
        "      --version            version\n"
        "Exit.\n");
}
