#include "symbols.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fwsim {

namespace {

// A mangled name is short, but its readable form is not bounded by its
// length: every back-reference (S_, S0_, T_, fp_ ...) prints a whole earlier
// component again, so a name built from references to references doubles
// with every few characters (300 characters: gigabytes, for many seconds).
// An upper bound on the output: at most 1.5 times more per reference (the
// most a chain of references can multiply by per reference is e^(1/e), at
// three references to each earlier component), the name's length times for
// each pack expansion (Dp, sp). Names whose bound passes 2^20 characters stay
// mangled; the firmware's longest names stay below 2^18.
constexpr double kLog2MaxReadable = 20;
constexpr size_t kMaxMangled = 4096;

bool readable_form_is_small(const std::string& name) {
  if (name.size() > kMaxMangled) return false;
  const double log2_len = std::log2(static_cast<double>(name.size()));
  double log2_bound = log2_len;
  for (size_t i = 0; i + 1 < name.size(); ++i) {
    const char c = name[i];
    if ((c == 'D' || c == 's') && name[i + 1] == 'p') {
      log2_bound += log2_len;
      continue;
    }
    size_t j = i + 1;
    if (c == 'S' || c == 'T') {
      while (j < name.size() && (std::isdigit(static_cast<unsigned char>(name[j])) || std::isupper(static_cast<unsigned char>(name[j])))) ++j;
    } else if (c == 'f' && name[i + 1] == 'p') {
      j = i + 2;
      while (j < name.size() && std::isdigit(static_cast<unsigned char>(name[j]))) ++j;
      if (j < name.size() && (name[j] == 'T' || name[j] == '_')) j += name[j] == 'T';
    } else {
      continue;
    }
    if (j < name.size() && name[j] == '_') log2_bound += 0.585;  // log2(1.5)
  }
  return log2_bound <= kLog2MaxReadable;
}

}  // namespace

std::string demangle(const std::string& name) {
  if (name.rfind("_Z", 0) != 0) return name;  // C names pass through untouched
  if (!readable_form_is_small(name)) return name;
  int status = 0;
  char* readable = abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status);
  if (status != 0 || !readable) return name;
  std::string out(readable);
  std::free(readable);
  return out;
}

void SymbolTable::finalize() {
  std::stable_sort(syms_.begin(), syms_.end(), [](const Symbol& a, const Symbol& b) {
    if (a.addr != b.addr) return a.addr < b.addr;
    return a.size > b.size;  // keep the sized (typed) symbol of an alias group
  });
  syms_.erase(std::unique(syms_.begin(), syms_.end(),
                          [](const Symbol& a, const Symbol& b) { return a.addr == b.addr; }),
              syms_.end());
  for (size_t i = 0; i < syms_.size(); ++i) {
    if (syms_[i].size == 0 && i + 1 < syms_.size()) syms_[i].size = syms_[i + 1].addr - syms_[i].addr;
  }
}

int SymbolTable::find(uint32_t addr) const {
  auto it = std::upper_bound(syms_.begin(), syms_.end(), addr,
                             [](uint32_t a, const Symbol& s) { return a < s.addr; });
  if (it == syms_.begin()) return -1;
  --it;
  // Unsized last symbol: accept anything after it.
  if (it->size != 0 && addr - it->addr >= it->size) return -1;
  return static_cast<int>(it - syms_.begin());
}

std::string SymbolTable::describe(uint32_t addr) const {
  char buf[32];
  int i = find(addr);
  if (i < 0) {
    std::snprintf(buf, sizeof buf, "0x%08x", addr);
    return buf;
  }
  std::snprintf(buf, sizeof buf, "+0x%x", addr - at(i).addr);
  return demangle(at(i).name) + buf;
}

}  // namespace fwsim
