// The format registry (formats/registry.hpp): one recognition rule, the
// same for minrt, host-send and the board (which sees the text through a
// PeekSource), tolerant of a UTF-8 byte-order mark and of letter case.
#include <catch2/catch.hpp>

#include <string>

#include "core/base/peek_source.hpp"
#include "formats/registry.hpp"

namespace {

using minrt::formats::FormatId;

minrt::formats::TextStart start_of(const std::string& text) {
  return minrt::formats::text_start(reinterpret_cast<const uint8_t*>(text.data()), text.size());
}

FormatId host_rule(const char* path, const std::string& text) {
  return minrt::formats::detect_format(path, start_of(text)).id;
}

// The board's view: the bytes a PeekSource keeps, and what it replays.
FormatId board_rule(const std::string& text, std::string* replayed = nullptr) {
  minrt::MemorySource mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()};
  minrt::PeekSource peek(mem.source());
  minrt::formats::TextStart start;
  while (!(start = minrt::formats::text_start(peek.kept(), static_cast<size_t>(peek.kept_count()))).complete &&
         peek.extend()) {
  }
  const FormatId id = minrt::formats::format_of_text(start).id;
  if (replayed != nullptr) {
    minrt::ByteSource src = peek.source();
    for (int c; (c = src.get()) >= 0;) replayed->push_back(static_cast<char>(c));
  }
  return id;
}

const std::string kBom = "\xEF\xBB\xBF";

}  // namespace

TEST_CASE("registry: the extension decides when one format has it, in any case", "[registry]") {
  CHECK(host_rule("a.sld", "png 1 1 a.png") == FormatId::kSld);
  CHECK(host_rule("A.SLD", "") == FormatId::kSld);
  CHECK(host_rule("dir/x.rt", "") == FormatId::kMinirt);
  CHECK(host_rule("x.RT", "") == FormatId::kMinirt);
  CHECK(host_rule("x.Ray", "") == FormatId::kEastray);
  CHECK(host_rule("dir.rt/", "0 0 0") == FormatId::kSld);  // a folder's name is no extension
}

TEST_CASE("registry: a .txt file is CS418 or Jaworski by its first word, CS418 when neither", "[registry]") {
  CHECK(host_rule("s.txt", "png 4 4 s.png\nsphere 0 0 -1 0.5\n") == FormatId::kCs418);
  CHECK(host_rule("s.txt", "imWidth: 4\n") == FormatId::kJaworski);
  CHECK(host_rule("s.txt", "# a comment\nimWidth: 4\n") == FormatId::kJaworski);
  CHECK(host_rule("s.txt", "") == FormatId::kCs418);
  CHECK(host_rule("s.txt", "\x01\x02 garbage") == FormatId::kCs418);
  CHECK(host_rule("s.TXT", "PNG 4 4 s.png") == FormatId::kCs418);
  CHECK(host_rule("s.txt", "0 0 0 0 30\n") == FormatId::kCs418);  // numbers claim nothing
  // A miniRT scene misnamed .txt is miniRT's, whose reader asks for .rt.
  CHECK(host_rule("s.txt", "A 0.2 255,255,255\n") == FormatId::kMinirt);
}

TEST_CASE("registry: a byte-order mark and letter case do not change the format", "[registry]") {
  const char* texts[] = {"png 4 4 s.png\n", "imWidth: 4\n", "A 0.2 255,255,255\n", "/* EASTRAY */ display 1 1 ;",
                         "0.0 0.0 0.0\n", "color [ 1 1 1 ]", "color 1 0 0\n", "#include \"x.h\"\n", "IMWIDTH: 4"};
  for (const char* t : texts) {
    INFO(t);
    CHECK(host_rule(nullptr, kBom + t) == host_rule(nullptr, t));
    CHECK(board_rule(kBom + t) == board_rule(t));
  }
  CHECK(host_rule(nullptr, "Png 4 4 s.png") == FormatId::kCs418);
  CHECK(host_rule(nullptr, "SP 0,0,0 1 255,0,0") == FormatId::kMinirt);
}

TEST_CASE("registry: without an extension the first word decides, as on the board", "[registry]") {
  struct Case {
    const char* text;
    FormatId id;
  } cases[] = {
      {"png 4 4 s.png\n", FormatId::kCs418},       {"imWidth: 4\n", FormatId::kJaworski},
      {"# comment\n", FormatId::kJaworski},        {"# a CS418 scene\n#\npng 4 4 s.png\n", FormatId::kCs418},
      {"# Jaworski\nimWidth 4\n", FormatId::kJaworski}, {"#define R 1\n", FormatId::kEastray},        {"A 0.2 255,255,255\n", FormatId::kMinirt},
      {"sp 0,0,0 1 255,0,0\n", FormatId::kMinirt}, {"/* EASTRAY */ display", FormatId::kEastray},
      {"#include \"a.ray\"\n", FormatId::kEastray}, {"color [ 1 1 1 ]", FormatId::kEastray},
      {"color\n\n  [1 1 1]", FormatId::kEastray},  {"color 1 0 0\n", FormatId::kCs418},
      {"0 0 0 0\n", FormatId::kSld},               {"-1.5 2\n", FormatId::kSld},
      {"", FormatId::kSld},                        {"   \n\t", FormatId::kSld},
  };
  for (const Case& c : cases) {
    INFO(c.text);
    CHECK(host_rule(nullptr, c.text) == c.id);
    CHECK(board_rule(c.text) == c.id);
  }
}

TEST_CASE("registry: the board replays the text without its byte-order mark", "[registry]") {
  std::string replayed;
  CHECK(board_rule(kBom + "png 2 2 x.png\nsun 1 1 1\n", &replayed) == FormatId::kCs418);
  CHECK(replayed == "png 2 2 x.png\nsun 1 1 1\n");
  replayed.clear();
  CHECK(board_rule("  0 0 0\n", &replayed) == FormatId::kSld);
  CHECK(replayed == "  0 0 0\n");
}

TEST_CASE("registry: names and wire tags find their format, others none", "[registry]") {
  for (const minrt::formats::Format& f : minrt::formats::kFormats) {
    CHECK(minrt::formats::format_named(f.name) == &f);
    CHECK(minrt::formats::format_with_tag(f.wire_tag) == &f);
  }
  CHECK(minrt::formats::format_named("pov") == nullptr);
  CHECK(minrt::formats::format_with_tag(999) == nullptr);
}
