// The EASTRAY preprocessor on arbitrary text with includes from an
// in-memory file system: the input's NUL bytes split it into top.ray, f1.h,
// f2.h, ... It accepts, or refuses with a located message; it never
// crashes, and whatever it emits stays within its work budget (64 times
// the scene file, at least 1 MiB), however the files include each other
// and however the macros double.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <string>

#include "eastray_preprocess.hpp"

namespace {

class MemoryFiles : public minrt::host::EastrayFiles {
 public:
  std::map<std::string, std::string> files;
  bool readable(const std::string& path) const override { return files.count(strip(path)) != 0; }
  std::string canonical(const std::string& path) const override { return strip(path); }
  bool read(const std::string& path, std::string& out, std::string& why, std::size_t max_bytes) const override {
    const auto it = files.find(strip(path));
    if (it == files.end()) {
      why = "No such file or directory";
      return false;
    }
    if (it->second.size() > max_bytes) {
      why = "larger than " + std::to_string(max_bytes) + " bytes";
      return false;
    }
    out = it->second;
    return true;
  }

 private:
  // Every file sits in one folder: "./f1.h", "mem/f1.h" and "f1.h" are one.
  static std::string strip(const std::string& path) {
    const std::size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  MemoryFiles fs;
  std::string top;
  int index = 0;
  std::string part;
  auto flush = [&] {
    if (index == 0) top = part;
    else fs.files["f" + std::to_string(index) + ".h"] = part;
    ++index;
    part.clear();
  };
  for (size_t i = 0; i < size; ++i) {
    if (data[i] == 0 && index < 8) flush();
    else part.push_back(static_cast<char>(data[i]));
  }
  flush();
  fs.files["top.ray"] = top;
  minrt::host::ExpandedEastray out;
  std::string error;
  if (!minrt::host::preprocess_eastray("mem/top.ray", "top.ray", top, out, error, fs)) {
    if (error.find(": error: ") == std::string::npos) std::abort();  // a refusal says what and where
    return 0;
  }
  const std::size_t budget = top.size() * 64 > (std::size_t{1} << 20) ? top.size() * 64 : std::size_t{1} << 20;
  if (out.text.size() > budget) std::abort();
  std::size_t lines = 0;
  for (char c : out.text) lines += c == '\n';
  if (lines != out.lines.size()) std::abort();  // every emitted line has its origin
  for (const auto& o : out.lines)
    if (o.file < 0 || static_cast<std::size_t>(o.file) >= out.files.size()) std::abort();
  return 0;
}
