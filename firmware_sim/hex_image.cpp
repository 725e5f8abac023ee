#include "hex_image.hpp"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "posix/input_file.hpp"

namespace fwsim {
namespace {

struct Writer {
  const std::string& path;
  Bus& bus;
  uint32_t base;
  LoadedImage out{};
  bool any = false;
  uint64_t index = 0;  // next word

  void word(uint32_t value, unsigned line) {
    const uint64_t addr = base + 4 * index;
    uint8_t* p = addr + 4 <= (uint64_t{1} << 32) ? bus.host_at(static_cast<uint32_t>(addr), 4) : nullptr;
    if (!p) {
      char buf[96];
      std::snprintf(buf, sizeof buf, "word %llu at 0x%08llx lies outside RAM and ROM",
                    static_cast<unsigned long long>(index), static_cast<unsigned long long>(addr));
      fail(line, buf);
    }
    std::memcpy(p, &value, 4);
    if (!any || addr < out.begin) out.begin = static_cast<uint32_t>(addr);
    if (!any || addr + 4 > out.end) out.end = static_cast<uint32_t>(addr + 4);
    any = true;
    ++index;
  }
  [[noreturn]] void fail(unsigned line, const std::string& why) const {
    throw std::runtime_error(path + ":" + std::to_string(line) + ": " + why);
  }
};

uint64_t parse_digits(const std::string& tok, int radix, bool& ok) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(tok.c_str(), &end, radix);
  ok = !tok.empty() && !errno && *end == 0 && tok[0] != '-' && tok[0] != '+' && !std::isspace(static_cast<unsigned char>(tok[0]));
  return v;
}

void load_readmemh(const std::string& text, Writer& w) {
  unsigned line = 1;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (text.compare(i, 2, "//") == 0) {
      while (i < text.size() && text[i] != '\n') ++i;
    } else if (text.compare(i, 2, "/*") == 0) {
      const size_t end = text.find("*/", i + 2);
      if (end == std::string::npos) w.fail(line, "unterminated /* comment");
      for (size_t j = i; j < end; ++j) line += text[j] == '\n';
      i = end + 2;
    } else {
      size_t j = i;
      while (j < text.size() && !std::isspace(static_cast<unsigned char>(text[j])) && text.compare(j, 2, "//") != 0) ++j;
      std::string tok = text.substr(i, j - i);
      i = j;
      const bool at = tok[0] == '@';
      if (at) tok.erase(0, 1);
      std::string digits;
      for (char d : tok)
        if (d != '_') digits += d;  // Verilog allows _ separators
      bool ok = !digits.empty();
      for (char d : digits) ok = ok && std::isxdigit(static_cast<unsigned char>(d));
      const uint64_t v = ok ? parse_digits(digits, 16, ok) : 0;
      if (!ok || v > UINT32_MAX)
        w.fail(line, std::string(at ? "bad address" : "bad hex word") + " '" + (at ? "@" : "") + tok + "'");
      if (at) w.index = v;
      else w.word(static_cast<uint32_t>(v), line);
    }
  }
}

void load_coe(const std::string& text, Writer& w) {
  // key = value; pairs, ';' ends a statement, ',' separates vector words.
  int radix = 0;
  bool in_vector = false, done = false;
  std::istringstream in(text);
  std::string raw;
  for (unsigned line = 1; std::getline(in, raw); ++line) {
    std::string s;
    for (char ch : raw)
      if (!std::isspace(static_cast<unsigned char>(ch))) s += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (s.empty() || (!in_vector && s[0] == ';')) continue;  // blank or comment line
    if (done) w.fail(line, "text after the vector's ';'");
    if (!in_vector) {
      const size_t eq = s.find('=');
      if (eq == std::string::npos) w.fail(line, "expected 'key = value;'");
      const std::string key = s.substr(0, eq);
      std::string value = s.substr(eq + 1);
      if (key == "memory_initialization_radix") {
        if (!value.empty() && value.back() == ';') value.pop_back();
        if (value != "16" && value != "10" && value != "2") w.fail(line, "radix must be 2, 10 or 16, got '" + value + "'");
        radix = std::atoi(value.c_str());
        continue;
      }
      if (key != "memory_initialization_vector") w.fail(line, "unknown key '" + key + "'");
      if (!radix) w.fail(line, "memory_initialization_radix must come first");
      in_vector = true;
      s = value;
    }
    size_t pos = 0;
    while (pos < s.size() && !done) {
      size_t end = s.find_first_of(",;", pos);
      const std::string tok = s.substr(pos, end == std::string::npos ? std::string::npos : end - pos);
      if (!tok.empty()) {
        bool ok = false;
        const uint64_t v = parse_digits(tok, radix, ok);
        if (!ok || v > UINT32_MAX) w.fail(line, "bad word '" + tok + "'");
        w.word(static_cast<uint32_t>(v), line);
      }
      if (end == std::string::npos) break;
      if (s[end] == ';') done = true;
      pos = end + 1;
    }
  }
  if (!in_vector) w.fail(1, "no memory_initialization_vector");
}

}  // namespace

LoadedImage load_hex_image(const std::string& path, Bus& bus, uint32_t base) {
  // A word takes at most 34 bytes of text (32 binary digits, a separator
  // and a newline), so 16 bytes of text a byte of memory, plus room for a
  // header and comments, bounds an image that fits: checked before reading.
  const uint64_t room = uint64_t{bus.ram_size()} + (bus.code() != bus.ram() ? bus.code_size() : 0);
  const size_t bound = static_cast<size_t>(room * 16 + (uint64_t{1} << 20));
  std::string text, why;
  if (!minrt::host::read_whole_file(path, text, why, bound)) throw std::runtime_error(path + ": cannot read: " + why);
  Writer w{path, bus, base};
  const bool coe = path.size() > 4 && path.compare(path.size() - 4, 4, ".coe") == 0;
  if (coe) load_coe(text, w);
  else load_readmemh(text, w);
  if (!w.any) throw std::runtime_error(path + ":1: no words");
  return w.out;
}

}  // namespace fwsim
