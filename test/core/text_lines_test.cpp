// The line reading and word splitting the CS418 and miniRT readers share
// (core/base/text_lines.hpp).
#include <catch2/catch.hpp>

#include <string>

#include "core/base/byte_io.hpp"
#include "core/base/text_lines.hpp"

namespace {

using minrt::text::LineRead;

struct Lines {
  explicit Lines(const std::string& s)
      : text(s), mem{reinterpret_cast<const uint8_t*>(text.data()), text.size()}, in(mem.source()) {}
  LineRead next(int capacity = 8) {
    length = -1;
    return minrt::text::read_line(in, buf, capacity, length, at_end);
  }
  std::string line() const { return std::string(buf, static_cast<std::size_t>(length)); }

  std::string text;
  minrt::MemorySource mem;
  minrt::ByteSource in;
  char buf[16] = {};
  int length = 0;
  bool at_end = false;
};

}  // namespace

TEST_CASE("text lines: newline dropped, CR kept for the splitter, a last line without newline, then the end",
          "[core][text]") {
  Lines l("ab\r\n\nlast");
  REQUIRE(l.next() == LineRead::kLine);
  CHECK(l.line() == "ab\r");
  CHECK_FALSE(l.at_end);
  REQUIRE(l.next() == LineRead::kLine);
  CHECK(l.line().empty());
  REQUIRE(l.next() == LineRead::kLine);
  CHECK(l.line() == "last");
  CHECK(l.at_end);
  CHECK(l.next() == LineRead::kEnd);

  Lines ended("x\n");
  CHECK(ended.next() == LineRead::kLine);
  CHECK(ended.next() == LineRead::kEnd);
  CHECK(ended.at_end);
}

TEST_CASE("text lines: a NUL byte is reported where it stands", "[core][text]") {
  Lines l(std::string("ok\nab\0cd\n", 9));
  REQUIRE(l.next() == LineRead::kLine);
  REQUIRE(l.next() == LineRead::kNulByte);
  CHECK(l.length == 2);  // column 3
}

TEST_CASE("text lines: a line of exactly the capacity fits, one byte more is too long", "[core][text]") {
  Lines fits("12345678\n123456789\n");
  REQUIRE(fits.next() == LineRead::kLine);
  CHECK(fits.line() == "12345678");
  REQUIRE(fits.next() == LineRead::kTooLong);
  CHECK(fits.length == 8);
}

TEST_CASE("text words: blanks split, the first max_words are kept, the rest counted", "[core][text]") {
  using minrt::text::Word;
  const std::string line = " \tsp  1,2,3\f10\v255\r";
  Word words[2] = {};
  int unstored = -1;
  CHECK(minrt::text::split_words(line.data(), static_cast<int>(line.size()), words, 2, unstored) == 4);
  CHECK(words[0].start == 2);
  CHECK(words[0].length == 2);
  CHECK(minrt::text::word_is(line.data(), words[0], "sp"));
  CHECK_FALSE(minrt::text::word_is(line.data(), words[0], "s"));
  CHECK_FALSE(minrt::text::word_is(line.data(), words[0], "spt"));
  CHECK(words[1].start == 6);
  CHECK(unstored == 12);  // "10"

  Word three[3] = {};
  unstored = -1;
  CHECK(minrt::text::split_words(line.data(), static_cast<int>(line.size()), three, 3, unstored) == 4);
  CHECK(unstored == 15);  // "255"
  CHECK(minrt::text::split_words("  \r", 3, three, 3, unstored) == 0);
}
