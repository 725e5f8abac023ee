#include "eastray_preprocess.hpp"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <map>
#include <unistd.h>

#include "file_input.hpp"

namespace minrt::host {

namespace {

// The work budget (see eastray_preprocess.hpp): what the preprocessor may
// copy, in bytes, is kBudgetFactor times the scene file, at least
// kBudgetFloor and at most kMaxExpandedBytes. Includes and macros that
// name each other twice double at every level; the budget stops them after
// a few milliseconds and megabytes instead of hours and gigabytes.
constexpr int kMaxIncludeDepth = 64;
constexpr int kMaxMacroDepth = 32;  // a body naming a macro is expanded again, this deep at most
constexpr std::size_t kBudgetFactor = 64;
constexpr std::size_t kBudgetFloor = std::size_t{1} << 20;
constexpr std::size_t kMaxExpandedBytes = std::size_t{64} << 20;
constexpr std::size_t kExpansionCost = 64;  // bytes one macro expansion counts for beyond its body
constexpr std::size_t kIncludeCost = 1024;  // bytes one #include counts for beyond its file (open, read)

bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool ident_char(char c) { return ident_start(c) || (c >= '0' && c <= '9'); }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// Text editors of the FM TOWNS's MS-DOS ended files with Ctrl-Z (0x1a): it
// ends the file's text, as DOS's own text reading did.
std::size_t text_length(const std::string& text) {
  const std::size_t ctrl_z = text.find('\x1a');
  return ctrl_z == std::string::npos ? text.size() : ctrl_z;
}

class DiskFiles : public EastrayFiles {
 public:
  bool readable(const std::string& path) const override { return ::access(path.c_str(), R_OK) == 0; }
  std::string canonical(const std::string& path) const override {
    char buf[PATH_MAX];
    return ::realpath(path.c_str(), buf) != nullptr ? std::string(buf) : path;
  }
  bool read(const std::string& path, std::string& out, std::string& why, std::size_t max_bytes) const override {
    return read_whole_file(path, out, why, max_bytes);
  }
};

class Expander {
 public:
  Expander(ExpandedEastray& out, std::size_t scene_bytes, const EastrayFiles& files) : out_(out), files_(files) {
    budget_ = scene_bytes > kMaxExpandedBytes / kBudgetFactor ? kMaxExpandedBytes : scene_bytes * kBudgetFactor;
    if (budget_ < kBudgetFloor) budget_ = kBudgetFloor;
  }

  bool file(const std::string& path, const std::string& shown, const std::string& text, int depth) {
    const int index = static_cast<int>(out_.files.size());
    out_.files.push_back(shown);
    const std::string canon = files_.canonical(path);
    for (const std::string& open : stack_)
      if (open == canon) return false;  // caller reports the cycle
    stack_.push_back(canon);
    std::string clean;
    int bad_line = 0, bad_col = 0;
    if (!strip_comments(text.substr(0, text_length(text)), clean, bad_line, bad_col)) {
      error_ = shown + ":" + std::to_string(bad_line) + ":" + std::to_string(bad_col) +
               ": error: unterminated comment (no '*/' before the end of the file)";
      return false;
    }
    std::size_t start = 0;
    int line = 1;
    while (start <= clean.size()) {
      std::size_t end = clean.find('\n', start);
      const bool last = end == std::string::npos;
      if (last) end = clean.size();
      if (last && start == end) break;
      const std::string one = clean.substr(start, end - start);
      if (!this->line(one, path, shown, index, line, depth)) return false;
      start = end + 1;
      ++line;
      if (last) break;
    }
    stack_.pop_back();
    return true;
  }

  const std::string& error() const { return error_; }

 private:
  // Comments become blanks (newlines kept), so lines and columns still hold.
  static bool strip_comments(const std::string& in, std::string& out, int& line, int& col) {
    out = in;
    int l = 1, c = 1;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i] == '/' && i + 1 < out.size() && out[i + 1] == '*') {
        const int sl = l, sc = c;
        std::size_t j = i + 2;
        while (j + 1 < out.size() && !(out[j] == '*' && out[j + 1] == '/')) ++j;
        if (j + 1 >= out.size()) {
          line = sl;
          col = sc;
          return false;
        }
        for (std::size_t k = i; k < j + 2; ++k) {
          if (out[k] == '\n') {
            ++l;
            c = 1;
          } else {
            out[k] = ' ';
            ++c;
          }
        }
        i = j + 1;
        continue;
      }
      if (out[i] == '\n') {
        ++l;
        c = 1;
      } else {
        ++c;
      }
    }
    drop_trailing_blanks(out);
    return true;
  }

  // Blanks at the end of a line mean nothing and may be megabytes of
  // padding: they are dropped (what comes before them keeps its columns).
  static void drop_trailing_blanks(std::string& text) {
    std::size_t w = 0, run = std::string::npos;  // where the current run of blanks starts in the output
    for (const char ch : text) {
      if (blank(ch)) {
        if (run == std::string::npos) run = w;
      } else {
        if (ch == '\n' && run != std::string::npos) w = run;
        run = std::string::npos;
      }
      text[w++] = ch;
    }
    if (run != std::string::npos) w = run;
    text.resize(w);
    text.shrink_to_fit();
  }

  bool fail(const std::string& shown, int line, std::size_t col, const std::string& msg) {
    error_ = shown + ":" + std::to_string(line) + ":" + std::to_string(col + 1) + ": error: " + msg;
    return false;
  }

  void emit(const std::string& text, int file, int line) {
    out_.text += text;
    out_.text += '\n';
    out_.lines.push_back(EastrayLineOrigin{file, line});
  }

  bool line(const std::string& one, const std::string& path, const std::string& shown, int file, int line,
            int depth) {
    std::size_t i = 0;
    while (i < one.size() && blank(one[i])) ++i;
    if (i >= one.size() || one[i] != '#') {
      std::string expanded;
      if (!expand(one, expanded, 0, shown, line)) return false;
      if (!spend(expanded.size() + 1, shown, line, 0)) return false;
      emit(expanded, file, line);
      return true;
    }
    const std::size_t hash = i++;
    while (i < one.size() && blank(one[i])) ++i;
    std::size_t w = i;
    while (w < one.size() && ident_char(one[w])) ++w;
    const std::string directive = one.substr(i, w - i);
    if (directive == "define") return define(one, w, shown, line, file);
    if (directive == "include") return include(one, w, path, shown, line, file, depth);
    return fail(shown, line, hash, "unknown directive '#" + directive + "' (expected #include or #define)");
  }

  bool define(const std::string& one, std::size_t i, const std::string& shown, int line, int file) {
    while (i < one.size() && blank(one[i])) ++i;
    if (i >= one.size() || !ident_start(one[i])) return fail(shown, line, i, "#define needs a name");
    std::size_t e = i;
    while (e < one.size() && ident_char(one[e])) ++e;
    std::string name = one.substr(i, e - i);
    if (e < one.size() && !blank(one[e]))
      return fail(shown, line, e, "#define name '" + name + "' must be followed by a blank");
    std::size_t b = e;
    while (b < one.size() && blank(one[b])) ++b;
    std::size_t be = one.size();
    while (be > b && blank(one[be - 1])) --be;
    macros_[name] = one.substr(b, be - b);
    emit("", file, line);
    return true;
  }

  bool include(const std::string& one, std::size_t i, const std::string& path, const std::string& shown, int line,
               int file, int depth) {
    while (i < one.size() && blank(one[i])) ++i;
    if (i >= one.size() || (one[i] != '"' && one[i] != '<'))
      return fail(shown, line, i, "#include needs \"file\" or <file>");
    const char close = one[i] == '"' ? '"' : '>';
    const std::size_t name_at = i;
    const std::size_t e = one.find(close, i + 1);
    if (e == std::string::npos) return fail(shown, line, i, std::string("#include name has no closing ") + close);
    std::string name = one.substr(i + 1, e - i - 1);
    for (char& c : name)
      if (c == '\\') c = '/';  // the manual's DOS paths
    if (name.empty()) return fail(shown, line, name_at, "#include names no file");
    std::string found;
    if (close == '"') {
      const std::string beside = name[0] == '/' ? name : folder_of(path) + name;
      if (files_.readable(beside)) found = beside;
      else if (files_.readable(name)) found = name;
      else return fail(shown, line, name_at, "cannot find include file '" + name + "' (looked beside " + shown +
                                                 " and in the current folder)");
    } else {
      const char* env = std::getenv("EASTRAY");
      if (env == nullptr || *env == 0)
        return fail(shown, line, name_at, "#include <" + name + "> needs the EASTRAY environment variable (the folder of system files)");
      std::string dir = env;
      for (char& c : dir)
        if (c == '\\') c = '/';
      if (dir.back() != '/') dir += '/';
      found = dir + name;
      if (!files_.readable(found)) return fail(shown, line, name_at, "cannot find include file '" + found + "' (from EASTRAY)");
    }
    if (depth + 1 > kMaxIncludeDepth)
      return fail(shown, line, name_at, "#include nested deeper than " + std::to_string(kMaxIncludeDepth));
    const std::string canon = files_.canonical(found);
    for (const std::string& open : stack_)
      if (open == canon) return fail(shown, line, name_at, "#include cycle: '" + name + "' is already being read");
    // Charged before the read, so a file over the rest of the budget is not read.
    if (!spend(kIncludeCost, shown, line, name_at)) return false;
    std::string text, why;
    const std::size_t room = budget_ - spent_;
    if (!files_.read(found, text, why, std::min(kMaxSceneBytes, room + 1))) {
      // Over what is left of the budget (read no further than that):
      // the budget's message, naming the file.
      if (room < kMaxSceneBytes && why.rfind("larger than", 0) == 0)
        return fail(shown, line, name_at,
                    "include file '" + found + "' is larger than the " + std::to_string(room) +
                        " bytes left of the scene's budget of " + std::to_string(budget_) + " bytes (" +
                        std::to_string(kBudgetFactor) + " times the scene file, at least " +
                        std::to_string(kBudgetFloor) + ")");
      return fail(shown, line, name_at, "cannot read include file '" + found + "': " + why);
    }
    if (!spend(text.size(), shown, line, name_at)) return false;
    emit("", file, line);  // the directive's own line stays, blank
    return this->file(found, found, text, depth + 1);
  }

  // Replaces macro names (whole identifiers) by their bodies, which are
  // scanned again; a macro is not expanded inside its own body.
  bool expand(const std::string& in, std::string& out, int depth, const std::string& shown, int line) {
    if (depth > kMaxMacroDepth) return fail(shown, line, 0, "macro expansion nested deeper than " + std::to_string(kMaxMacroDepth));
    std::size_t i = 0;
    while (i < in.size()) {
      if (ident_start(in[i]) && (i == 0 || !ident_char(in[i - 1]))) {
        std::size_t e = i;
        while (e < in.size() && ident_char(in[e])) ++e;
        const std::string name = in.substr(i, e - i);
        auto it = macros_.find(name);
        bool busy = false;
        for (const std::string& b : expanding_) busy = busy || b == name;
        if (it != macros_.end() && !busy) {
          expanding_.push_back(name);
          std::string body;
          const bool ok = expand(it->second, body, depth + 1, shown, line);
          expanding_.pop_back();
          if (!ok) return false;
          // Bodies naming a macro twice double at every level: count what
          // every level copies, and each expansion as kExpansionCost bytes
          // more (its call), so 2^30 copies of a 1-byte body stop at the
          // budget instead of running out of time or memory.
          if (!spend(body.size() + kExpansionCost, shown, line, i)) return false;
          out += body;
        } else {
          out += name;
        }
        i = e;
      } else if (in[i] >= '0' && in[i] <= '9') {  // a number's letters (1e5) are not names
        while (i < in.size() && (ident_char(in[i]) || in[i] == '.')) out += in[i++];
      } else {
        out += in[i++];
      }
    }
    return true;
  }

  // Charges `bytes` of work; false with a located error once over the budget.
  bool spend(std::size_t bytes, const std::string& shown, int line, std::size_t col) {
    spent_ += bytes;
    if (spent_ <= budget_) return true;
    return fail(shown, line, col,
                "the scene expands past " + std::to_string(budget_) +
                    " bytes (#include and #define copies count; the limit is " + std::to_string(kBudgetFactor) +
                    " times the scene file, at least " + std::to_string(kBudgetFloor) + ")");
  }

  ExpandedEastray& out_;
  const EastrayFiles& files_;
  std::map<std::string, std::string> macros_;
  std::vector<std::string> stack_;
  std::vector<std::string> expanding_;
  std::size_t budget_ = kBudgetFloor;
  std::size_t spent_ = 0;  // every byte emitted, included or copied by an expansion so far
  std::string error_;
};

}  // namespace

std::string ExpandedEastray::where(int line) const {
  if (line >= 1 && line <= static_cast<int>(lines.size())) {
    const EastrayLineOrigin& o = lines[static_cast<std::size_t>(line - 1)];
    return files[static_cast<std::size_t>(o.file)] + ":" + std::to_string(o.line);
  }
  const std::string scene = files.empty() ? std::string("<scene>") : files[0];
  return scene + ":" + std::to_string(end_line);
}

std::string ExpandedEastray::at(int line, int col) const {
  if (line >= 1 && line <= static_cast<int>(lines.size())) return where(line) + ":" + std::to_string(col);
  return where(line) + ":" + std::to_string(end_col);
}

const EastrayFiles& eastray_files() {
  static const DiskFiles files;
  return files;
}

bool preprocess_eastray(const std::string& path, const std::string& shown, const std::string& text,
                        ExpandedEastray& out, std::string& error) {
  return preprocess_eastray(path, shown, text, out, error, eastray_files());
}

bool preprocess_eastray(const std::string& path, const std::string& shown, const std::string& text,
                        ExpandedEastray& out, std::string& error, const EastrayFiles& files) {
  out = ExpandedEastray{};
  Expander x(out, text.size(), files);
  if (!x.file(path == "-" ? std::string() : path, shown, text, 0)) {
    error = x.error();
    return false;
  }
  // The expanded text ends every line with a newline; the scene file may
  // not (nor, after a Ctrl-Z, at it), and its end is where it really stops.
  const std::size_t length = text_length(text);
  out.end_line = 1;
  out.end_col = 1;
  for (std::size_t i = 0; i < length; ++i) {
    if (text[i] == '\n') {
      ++out.end_line;
      out.end_col = 1;
    } else {
      ++out.end_col;
    }
  }
  return true;
}

}  // namespace minrt::host
