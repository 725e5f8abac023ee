#include "symbols.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace fwsim {

std::string demangle(const std::string& name) {
  if (name.rfind("_Z", 0) != 0) return name;  // C names pass through untouched
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
  return at(i).name + buf;
}

}  // namespace fwsim
